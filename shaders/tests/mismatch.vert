// Test shader: writes v_value as vec3; mismatch.frag reads it as vec4, so
// the two must fail to link.
#version 430 core
layout(location = 0) in vec3 a_position;
out vec3 v_value;

void main() {
    v_value = a_position;
    gl_Position = vec4(a_position, 1.0);
}
