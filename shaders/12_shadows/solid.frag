#version 430 core
// Lab 12, scene planar: one colour with its alpha (the ground, the casters,
// and the flattened shadow, black with alpha u_color.a, blended).

uniform vec4 u_color;

layout(location = 0) out vec4 frag_color;

void main() { frag_color = u_color; }
