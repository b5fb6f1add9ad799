#version 430 core
// Lab 12, the shadow map's depth pass: no colour at all. The framebuffer has
// only a depth attachment; the depth test writes each fragment's window depth.

void main() {}
