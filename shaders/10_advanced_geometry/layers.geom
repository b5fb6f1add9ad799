#version 430 core
// Lab 10, scene layers: one triangle in, six out, one into each face of the
// cube map. The framebuffer's attachments are whole cube maps (layered), and
// gl_Layer says which face, 0 to 5 in the order +x, -x, +y, -y, +z, -z, a
// primitive is drawn into. Each face sees the world through its own view.

layout(triangles) in;
layout(triangle_strip, max_vertices = 18) out;

uniform mat4 u_projection;  // perspective(90, 1, 0.1, 10): a face's quarter of the world
uniform mat4 u_views[6];    // cube_face_view(face) for each face

in vec3 v_world[];

out vec3 g_world;

void main() {
    // An output is undefined after EmitVertex(): gl_Layer, g_world and
    // gl_Position are written again before every vertex.
    // BEGIN SOLUTION
    // STUDENT: int face = 0;  // TODO: all six faces: gl_Layer = face, the face's view, three vertices
    // STUDENT: for (int i = 0; i < 3; ++i) {
    // STUDENT:     g_world = v_world[i];
    // STUDENT:     gl_Position = u_projection * u_views[face] * vec4(v_world[i], 1.0);
    // STUDENT:     EmitVertex();
    // STUDENT: }
    for (int face = 0; face < 6; ++face) {
        for (int i = 0; i < 3; ++i) {
            gl_Layer = face;
            g_world = v_world[i];
            gl_Position = u_projection * u_views[face] * vec4(v_world[i], 1.0);
            EmitVertex();
        }
        EndPrimitive();
    }
    // END SOLUTION
}
