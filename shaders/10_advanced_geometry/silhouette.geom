#version 430 core
// Lab 10, scene silhouette: a triangle with its neighbours in
// (GL_TRIANGLES_ADJACENCY), the edges of the outline out. gl_in[0], [2] and
// [4] are the triangle; gl_in[1], [3] and [5] are the far corners of the
// triangles across its edges 0-2, 2-4 and 4-0. An edge is on the silhouette
// where a triangle that faces the eye meets one that faces away.

layout(triangles_adjacency) in;
layout(line_strip, max_vertices = 6) out;

// Whether the triangle (a, b, c) faces the eye: counter-clockwise in
// normalized device coordinates, as glFrontFace(GL_CCW) decides.
bool front_facing(vec4 a, vec4 b, vec4 c) {
    vec2 p = a.xy / a.w, q = b.xy / b.w, r = c.xy / c.w;
    vec2 e = q - p, f = r - p;
    return e.x * f.y - e.y * f.x > 0.0;
}

// One line of its own from a to b.
void edge(vec4 a, vec4 b) {
    gl_Position = a;
    EmitVertex();
    gl_Position = b;
    EmitVertex();
    EndPrimitive();
}

void main() {
    // The neighbour across the edge from a to b runs the other way round it,
    // (b, a, far), which is (a, far, b) turned: its facing is that of
    // (a, far, b). Each outline edge is drawn once, by its front triangle.
    // BEGIN SOLUTION
    // STUDENT: // TODO: if this triangle faces the eye, each edge whose neighbour does not
    if (!front_facing(gl_in[0].gl_Position, gl_in[2].gl_Position, gl_in[4].gl_Position)) return;
    for (int e = 0; e < 3; ++e) {
        vec4 a = gl_in[2 * e].gl_Position, b = gl_in[(2 * e + 2) % 6].gl_Position;
        if (!front_facing(a, gl_in[2 * e + 1].gl_Position, b)) edge(a, b);
    }
    // END SOLUTION
}
