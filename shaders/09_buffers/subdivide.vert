#version 430 core
// Lab 9, scene subdivide: a vertex handed on unchanged to subdivide.geom.

// A_POSITION: the attribute location, shared with the lab.
#include "shared.glsl"

layout(location = A_POSITION) in vec3 a_position;

out vec3 v_position;

void main() {
    v_position = a_position;
    gl_Position = vec4(a_position, 1.0);
}
