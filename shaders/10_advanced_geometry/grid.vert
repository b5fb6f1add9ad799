#version 430 core
// Lab 10, scene instances: one quad, drawn once per instance. Instance i of
// columns x rows sits in cell (i % columns, i / columns), row 0 at the
// bottom; its colour is an attribute that advances once per instance.

// A_POSITION, A_COLOR: the attribute locations, shared with the lab.
#include "shared.glsl"

layout(location = A_POSITION) in vec2 a_corner;  // (+-1, +-1)
layout(location = A_COLOR) in vec3 a_color;      // this instance's colour

uniform int u_columns;
uniform int u_rows;

out vec3 v_color;

void main() {
    // The frame's [-1, 1]^2 in columns x rows cells of this size.
    vec2 cell = vec2(2.0 / float(u_columns), 2.0 / float(u_rows));
    // BEGIN SOLUTION
    // STUDENT: vec2 centre = vec2(0.0);  // TODO: the centre of instance gl_InstanceID's cell
    int column = gl_InstanceID % u_columns, row = gl_InstanceID / u_columns;
    vec2 centre = vec2(-1.0) + (vec2(column, row) + 0.5) * cell;
    // END SOLUTION
    v_color = a_color;
    // The quad covers the middle 80% of its cell.
    gl_Position = vec4(centre + 0.4 * cell * a_corner, 0.0, 1.0);
}
