#version 430 core
// Lab 10, scene instances: the instance's colour.

in vec3 v_color;

layout(location = 0) out vec4 frag_color;

void main() { frag_color = vec4(v_color, 1.0); }
