#version 430 core
// Lab 9, scenes feedback and compute: each particle drawn as a square point.

// A_POSITION: the attribute location, shared with the lab.
#include "shared.glsl"

layout(location = A_POSITION) in vec3 a_position;

uniform mat4 u_projection;  // world -> clip coordinates
uniform float u_point_size; // pixels

void main() {
    gl_PointSize = u_point_size;
    gl_Position = u_projection * vec4(a_position, 1.0);
}
