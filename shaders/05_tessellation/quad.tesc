#version 430 core
// Lab 5: the control shader of the quad patches (scenes flag and
// param_sphere). The patch's four control points are the corners of the unit
// square in (u, v); the evaluation shaders compute every point from
// gl_TessCoord alone, so nothing per vertex is passed on, only the levels
// (set_levels() in levels.tesc).

layout(vertices = 4) out;

void set_levels();

void main() {
    if (gl_InvocationID == 0) set_levels();
}
