#version 430 core
// Lab 4, mode explode: each triangle moves along its own face normal, so
// triangles that shared an edge drift apart and the gaps between them open.
// One triangle in, one out.

layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

in vec3 v_position[];  // world space, from mesh.vert
in vec3 v_normal[];

uniform mat4 u_view_projection;  // P * V: world -> clip space
uniform vec3 u_color;            // the sphere's Lambert colour
uniform float u_amount;          // how far each triangle moves

out vec3 g_normal;  // interpolated for lambert.frag
out vec3 g_color;

void main() {
    // BEGIN SOLUTION
    // STUDENT: vec3 shift = vec3(0.0);  // TODO: u_amount times this face's unit normal
    // The faces run counter-clockwise seen from outside, so the cross product
    // of two edges, in this order, points out of the sphere.
    vec3 face_normal =
        normalize(cross(v_position[1] - v_position[0], v_position[2] - v_position[0]));
    vec3 shift = u_amount * face_normal;
    // END SOLUTION
    for (int i = 0; i < 3; ++i) {
        gl_Position = u_view_projection * vec4(v_position[i] + shift, 1.0);
        // The vertex normals stay: the moved triangle is shaded as before.
        g_normal = v_normal[i];
        g_color = u_color;
        EmitVertex();
    }
    EndPrimitive();
}
