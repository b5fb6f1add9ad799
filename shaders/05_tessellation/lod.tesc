#version 430 core
// Lab 5, scene lod: the control shader of the ground's 16 quad patches. Each
// patch's levels come from its distance to the eye: near patches are cut
// finely, far ones coarsely. Two patches that share an edge must give it the
// same outer level, or the tessellator cuts the edge differently on each
// side and a crack opens between them (labs/05_tessellation/README.md, The
// scene lod).
//
// The corners, as (u, v) of the quad domain: p0 (0, 0), p1 (1, 0), p2 (1, 1),
// p3 (0, 1). The quad's outer levels belong to its edges in the order of GL
// 4.3, section 11.2.2.2: gl_TessLevelOuter[0] the edge u = 0 (p0 p3), [1]
// v = 0 (p0 p1), [2] u = 1 (p1 p2), [3] v = 1 (p3 p2).

layout(vertices = 4) out;

in vec3 v_position[];   // the patch's corners on the ground, world space
out vec3 c_position[];  // the same corners, for lod.tese

uniform vec3 u_eye;          // the camera's position, world space
uniform float u_detail;      // `detail`, k: level k / d at distance d
uniform bool u_from_centre;  // lod=centre: every level from the patch's centre

// The level of a point p of the ground: k over its distance d from the eye,
// rounded to the nearest integer and clamped to [1, 64].
float level_at(vec3 p) {
    // BEGIN SOLUTION
    // STUDENT: // TODO: clamp(round(k / d), 1, 64), d the distance from the eye u_eye to p.
    // STUDENT: return 1.0;
    return clamp(round(u_detail / distance(p, u_eye)), 1.0, 64.0);
    // END SOLUTION
}

// lod=edges: each outer level from the midpoint of its own edge, which the
// patch on the other side of that edge computes from the same two corners;
// both inner levels from the patch's centre.
void set_edge_levels(vec3 p0, vec3 p1, vec3 p2, vec3 p3) {
    // BEGIN SOLUTION
    // STUDENT: // TODO: gl_TessLevelOuter[0..3] from the midpoints of the edges u = 0 (p0 p3),
    // STUDENT: // v = 0 (p0 p1), u = 1 (p1 p2) and v = 1 (p3 p2); the inner levels from the
    // STUDENT: // centre, the mean of the four corners.
    // STUDENT: gl_TessLevelInner[0] = gl_TessLevelInner[1] = 1.0;
    // STUDENT: gl_TessLevelOuter[0] = gl_TessLevelOuter[1] = 1.0;
    // STUDENT: gl_TessLevelOuter[2] = gl_TessLevelOuter[3] = 1.0;
    gl_TessLevelOuter[0] = level_at(0.5 * (p0 + p3));
    gl_TessLevelOuter[1] = level_at(0.5 * (p0 + p1));
    gl_TessLevelOuter[2] = level_at(0.5 * (p1 + p2));
    gl_TessLevelOuter[3] = level_at(0.5 * (p3 + p2));
    float inner = level_at(0.25 * (p0 + p1 + p2 + p3));
    gl_TessLevelInner[0] = inner;
    gl_TessLevelInner[1] = inner;
    // END SOLUTION
}

// lod=centre: one level for the whole patch, from its centre. A neighbour
// nearer or farther may choose another one for the edge they share.
void set_centre_levels(vec3 p0, vec3 p1, vec3 p2, vec3 p3) {
    float level = level_at(0.25 * (p0 + p1 + p2 + p3));
    gl_TessLevelInner[0] = gl_TessLevelInner[1] = level;
    for (int edge = 0; edge < 4; ++edge) gl_TessLevelOuter[edge] = level;
}

void main() {
    c_position[gl_InvocationID] = v_position[gl_InvocationID];
    if (gl_InvocationID != 0) return;
    if (u_from_centre)
        set_centre_levels(v_position[0], v_position[1], v_position[2], v_position[3]);
    else
        set_edge_levels(v_position[0], v_position[1], v_position[2], v_position[3]);
}
