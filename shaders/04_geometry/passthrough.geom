#version 430 core
// Lab 4, mode passthrough: the lecture's first geometry shader. It receives
// one whole triangle (its three vertices in gl_in[] and in the arrays below)
// and emits it again unchanged: one triangle in, one triangle out.

layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

in vec3 v_position[];  // world space, from mesh.vert
in vec3 v_normal[];

uniform vec3 u_color;  // the sphere's Lambert colour

out vec3 g_normal;  // interpolated for lambert.frag
out vec3 g_color;

void main() {
    for (int i = 0; i < 3; ++i) {
        gl_Position = gl_in[i].gl_Position;
        g_normal = v_normal[i];
        g_color = u_color;
        EmitVertex();
    }
    EndPrimitive();
}
