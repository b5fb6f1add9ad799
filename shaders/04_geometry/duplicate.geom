#version 430 core
// Lab 4, mode duplicate: the lecture's second example. Each triangle is
// emitted twice: as it is, then a copy moved by the offset and tinted. One
// triangle in, two out, so the frame generates 2T primitives.

layout(triangles) in;
layout(triangle_strip, max_vertices = 6) out;

in vec3 v_position[];  // world space, from mesh.vert
in vec3 v_normal[];

uniform mat4 u_view_projection;  // P * V: world -> clip space
uniform vec3 u_color;            // the original's Lambert colour
uniform vec3 u_tint;             // the copy's Lambert colour
// The parameter `offset` in object space, turned by the model's rotation into
// world space: the copy moved by `offset` in object space lies here.
uniform vec3 u_offset;

out vec3 g_normal;  // interpolated for lambert.frag
out vec3 g_color;

void main() {
    // The original, as passthrough emits it.
    for (int i = 0; i < 3; ++i) {
        gl_Position = gl_in[i].gl_Position;
        g_normal = v_normal[i];
        g_color = u_color;
        EmitVertex();
    }
    EndPrimitive();

    // BEGIN SOLUTION
    // STUDENT: // TODO: emit the copy, a second triangle: each corner at v_position[i] +
    // STUDENT: // u_offset taken to clip space with u_view_projection, its normal
    // STUDENT: // v_normal[i] (moving does not turn it), colour u_tint; then EndPrimitive().
    for (int i = 0; i < 3; ++i) {
        gl_Position = u_view_projection * vec4(v_position[i] + u_offset, 1.0);
        g_normal = v_normal[i];
        g_color = u_tint;
        EmitVertex();
    }
    EndPrimitive();
    // END SOLUTION
}
