// Test shader: red, green = uv; blue = (cell.x * 16 + cell.y) / 255.
#version 430 core
in vec2 v_uv;
flat in ivec2 v_cell;
out vec4 o_color;

void main() {
    o_color = vec4(v_uv, float(v_cell.x * 16 + v_cell.y) / 255.0, 1.0);
}
