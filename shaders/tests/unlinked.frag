// Test shader: a plain fragment stage for unlinked.vert.
#version 430 core
out vec4 o_color;

void main() { o_color = vec4(1.0); }
