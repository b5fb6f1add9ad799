#version 430 core
// Lab 5: the tessellation levels of every patch, from the parameters `inner`
// and `outer`. triangle.tesc and quad.tesc both call set_levels(): one stage
// may be linked from several shader objects, like a C program from several
// files, and this file is linked into both control shaders.
//
// A triangle patch reads gl_TessLevelInner[0] and gl_TessLevelOuter[0..2]; a
// quad patch reads both inner levels and all four outer ones. The
// tessellator ignores the levels its domain does not use, so writing all
// six serves both.

uniform float u_inner;  // `inner`, in [1, 64]
uniform float u_outer;  // `outer`, in [1, 64]

void set_levels() {
    // BEGIN SOLUTION
    // STUDENT: // TODO: gl_TessLevelInner[0..1] from u_inner, gl_TessLevelOuter[0..3] from u_outer.
    // STUDENT: // Level 1 everywhere means no subdivision: the patch comes out whole.
    // STUDENT: gl_TessLevelInner[0] = gl_TessLevelInner[1] = 1.0;
    // STUDENT: gl_TessLevelOuter[0] = gl_TessLevelOuter[1] = 1.0;
    // STUDENT: gl_TessLevelOuter[2] = gl_TessLevelOuter[3] = 1.0;
    gl_TessLevelInner[0] = u_inner;
    gl_TessLevelInner[1] = u_inner;
    for (int edge = 0; edge < 4; ++edge) gl_TessLevelOuter[edge] = u_outer;
    // END SOLUTION
}
