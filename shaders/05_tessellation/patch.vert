#version 430 core
// Lab 5: the vertex shader of every scene. With tessellation on, it runs once
// per control point of a patch and only hands the point on; the evaluation
// shader places the vertices that the tessellator generates.

// A_POSITION: the attribute location, shared with tessellation.cpp.
#include "shared.glsl"

layout(location = A_POSITION) in vec3 a_position;  // a control point, object space

out vec3 v_position;

void main() {
    v_position = a_position;
}
