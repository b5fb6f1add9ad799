#version 430 core
// Lab 5: passes each tessellated triangle through unchanged and adds, as lab
// 4's wireframe.geom does, each corner's distance in pixels to the opposite
// edge, so that shade.frag can paint the edges white in the same draw. One
// triangle in, one out: the frame's primitives_generated, which counts what
// the geometry shader emits, is the number of triangles the tessellator made.

layout(triangles) in;
layout(triangle_strip, max_vertices = 3) out;

in vec3 e_normal[];  // from the evaluation shader

uniform vec2 u_viewport;  // width and height in pixels

out vec3 g_normal;
noperspective out vec3 g_edge_distance;  // linear on screen, not in the world

void main() {
    // Window positions: perspective division, then the viewport transform.
    vec2 w[3];
    for (int i = 0; i < 3; ++i)
        w[i] = (gl_in[i].gl_Position.xy / gl_in[i].gl_Position.w + 1.0) * 0.5 * u_viewport;
    // Twice the area over an edge's length is the height over that edge. A
    // triangle of zero area (the poles of param_sphere) gets no edge band.
    vec2 e0 = w[2] - w[1], e1 = w[0] - w[2], e2 = w[1] - w[0];
    float area2 = abs(e1.x * e2.y - e1.y * e2.x);
    vec3 lengths = max(vec3(length(e0), length(e1), length(e2)), vec3(1e-6));
    vec3 height = area2 / lengths;
    for (int i = 0; i < 3; ++i) {
        gl_Position = gl_in[i].gl_Position;
        g_normal = e_normal[i];
        g_edge_distance = vec3(0.0);
        g_edge_distance[i] = height[i];
        EmitVertex();
    }
    EndPrimitive();
}
