// Test shader: three attributes of different formats, each sent on to the
// fragment shader unchanged (an ivec2 must stay an exact integer).
#version 430 core
layout(location = 0) in vec3 a_position;
layout(location = 1) in vec2 a_uv;
layout(location = 2) in ivec2 a_cell;
out vec2 v_uv;
flat out ivec2 v_cell;

void main() {
    v_uv = a_uv;
    v_cell = a_cell;
    gl_Position = vec4(a_position, 1.0);
}
