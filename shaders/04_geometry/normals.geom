#version 430 core
// Lab 4, mode normals, second draw: a geometry shader whose output is not the
// primitive it receives. For each triangle it emits its three vertex normals
// as line strips of two vertices each: one triangle in, three lines out.

layout(triangles) in;
layout(line_strip, max_vertices = 6) out;

in vec3 v_position[];  // world space, from mesh.vert
in vec3 v_normal[];    // world space, unit length

uniform mat4 u_view_projection;  // P * V: world -> clip space
uniform float u_length;          // of each line, in world units

void main() {
    // BEGIN SOLUTION
    // STUDENT: // TODO: for each corner i, a line from the vertex (gl_in[i].gl_Position)
    // STUDENT: // to v_position[i] + u_length * v_normal[i] (taken to clip space):
    // STUDENT: // two EmitVertex() calls, then EndPrimitive() to start the next line.
    for (int i = 0; i < 3; ++i) {
        gl_Position = gl_in[i].gl_Position;
        EmitVertex();
        gl_Position = u_view_projection * vec4(v_position[i] + u_length * v_normal[i], 1.0);
        EmitVertex();
        EndPrimitive();
    }
    // END SOLUTION
}
