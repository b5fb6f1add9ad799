// Test shader: reads v_value as vec4 (mismatch.vert writes a vec3).
#version 430 core
in vec4 v_value;
out vec4 o_color;

void main() {
    o_color = v_value;
}
