#version 430 core
// Lab 9, scene subdivide: the captured triangles, drawn with their
// world-space positions handed on for flat shading.

// A_POSITION: the attribute location, shared with the lab.
#include "shared.glsl"

layout(location = A_POSITION) in vec3 a_position;

uniform mat4 u_mvp;  // world -> clip coordinates

out vec3 v_world;

void main() {
    v_world = a_position;
    gl_Position = u_mvp * vec4(a_position, 1.0);
}
