#version 430 core
// Lab 1: every vertex of a square goes through the model matrix M (u_model),
// then the projection P (u_projection): gl_Position = P * M * p, column
// vectors, so M acts first. The 2D position becomes a point (x, y, 0, 1):
// w = 1 is what lets the last column of a translation reach it.

// A_POSITION: the attribute location, shared with transforms.cpp.
#include "shared.glsl"

layout(location = A_POSITION) in vec2 a_position;

uniform mat4 u_projection;
uniform mat4 u_model;

void main() {
    gl_Position = u_projection * u_model * vec4(a_position, 0.0, 1.0);
}
