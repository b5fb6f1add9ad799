#version 430 core
// Lab 7, scenes blend, sorting, stencil and scissor: one colour and alpha for
// the whole draw. What happens to it next is the frame buffer operations'
// business: the blend equation, the depth and stencil tests, the scissor.

uniform vec4 u_color;  // (r, g, b, alpha): premultiplied for mode=premultiplied

layout(location = 0) out vec4 frag_color;

void main() { frag_color = u_color; }
