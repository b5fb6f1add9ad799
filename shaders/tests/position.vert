// Test shader: position only (for the uniform, query and depth tests).
#version 430 core
layout(location = 0) in vec3 a_position;

void main() {
    gl_Position = vec4(a_position, 1.0);
}
