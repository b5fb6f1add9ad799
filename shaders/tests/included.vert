// Test shader: color.vert with its locations from an #include.
#version 430 core
#include "shared.glsl"
layout(location = A_POSITION) in vec3 a_position;
layout(location = A_COLOR) in vec3 a_color;
out vec3 v_color;

void main() {
    v_color = a_color;
    gl_Position = vec4(a_position, 1.0);
}
