#version 430 core
// Lab 2: places one part of the arm. a_position is the part's point as
// designed at the origin; u_mvp = projection * (the part's matrix: S, H or a
// finger's), so gl_Position = P * M * p with column vectors.

// A_POSITION: the attribute location, shared with robot_arm.cpp.
#include "shared.glsl"

layout(location = A_POSITION) in vec2 a_position;

uniform mat4 u_mvp;

void main() {
    gl_Position = u_mvp * vec4(a_position, 0.0, 1.0);
}
