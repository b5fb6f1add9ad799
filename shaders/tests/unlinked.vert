// Test shader: declares displace() but no vertex shader of the program
// defines it, so the program must fail to link (every driver reports an
// unresolved function; a vec3/vec4 mismatch between stages is not enough:
// NVIDIA's 580 driver links that).
#version 430 core
layout(location = 0) in vec3 a_position;

vec3 displace(vec3 p);

void main() { gl_Position = vec4(displace(a_position), 1.0); }
