// Test shader: samples u_texture at the interpolated uv.
#version 430 core
uniform sampler2D u_texture;
in vec2 v_uv;
out vec4 o_color;

void main() {
    o_color = texture(u_texture, v_uv);
}
