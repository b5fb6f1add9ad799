// Test shader: each triangle into all six faces of a layered cube
// framebuffer, one invocation a face, at NDC depth u_depth, in a colour that
// names the face (or white).
#version 430 core
layout(triangles, invocations = 6) in;
layout(triangle_strip, max_vertices = 3) out;

uniform float u_depth;
uniform bool u_white;

out vec3 v_color;

void main() {
    int face = gl_InvocationID;
    vec3 color = u_white ? vec3(1.0) : vec3(face & 1, (face >> 1) & 1, face >= 4 ? 1.0 : 0.5);
    for (int i = 0; i < 3; ++i) {
        gl_Layer = face;
        gl_Position = vec4(gl_in[i].gl_Position.xy, u_depth, 1.0);
        v_color = color;
        EmitVertex();
    }
    EndPrimitive();
}
