#version 430 core
// Lab 10, scene clip: the sphere coloured by its normal, 0.5 + 0.5 n.

in vec3 v_normal;

layout(location = 0) out vec4 frag_color;

void main() { frag_color = vec4(0.5 + 0.5 * normalize(v_normal), 1.0); }
