#version 430 core
// Lab 4, mode wireframe: the mesh and its edges in one pass. The geometry
// shader is the one stage that sees all three corners of a triangle, so it
// can give each corner its distance, in pixels, to the opposite edge. Each
// fragment then gets its distances to the three edges by interpolation.

layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

in vec3 v_position[];  // world space, from mesh.vert
in vec3 v_normal[];

uniform vec3 u_color;     // the sphere's Lambert colour
uniform vec2 u_viewport;  // width and height in pixels

out vec3 g_normal;  // interpolated for wireframe.frag
out vec3 g_color;
// Distances in window space, where they are linear: interpolated without the
// perspective correction (noperspective), or they would bend.
noperspective out vec3 g_edge_distance;

void main() {
    // BEGIN SOLUTION
    // STUDENT: vec3 height = vec3(0.0);  // TODO: corner i's distance in pixels to the opposite edge
    // Window position of each corner: perspective division, then the
    // viewport transform (x_w = (x_ndc + 1) / 2 * width, likewise y).
    vec2 w[3];
    for (int i = 0; i < 3; ++i)
        w[i] = (gl_in[i].gl_Position.xy / gl_in[i].gl_Position.w + 1.0) * 0.5 * u_viewport;
    // Twice the triangle's area, divided by the length of an edge, is the
    // height over that edge.
    vec2 e0 = w[2] - w[1], e1 = w[0] - w[2], e2 = w[1] - w[0];
    float area2 = abs(e1.x * e2.y - e1.y * e2.x);
    vec3 height = vec3(area2 / length(e0), area2 / length(e1), area2 / length(e2));
    // END SOLUTION
    for (int i = 0; i < 3; ++i) {
        gl_Position = gl_in[i].gl_Position;
        g_normal = v_normal[i];
        g_color = u_color;
        // Corner i lies on the two edges next to it (distance 0) and at
        // height[i] from the edge opposite.
        g_edge_distance = vec3(0.0);
        g_edge_distance[i] = height[i];
        EmitVertex();
    }
    EndPrimitive();
}
