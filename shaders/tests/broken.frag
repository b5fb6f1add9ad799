// Test shader that must NOT compile: `undeclared_colour` on line 9 does not
// exist. test_wrapper.cpp checks that the error names this file, the
// fragment stage, line 9 and quotes that line.
#version 430 core
in vec3 v_color;
out vec4 o_color;

void main() {
    o_color = vec4(undeclared_colour, 1.0);
}
