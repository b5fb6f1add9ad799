// Test shader: pixel column x shows u_palette[x % 4], so a 4x1 framebuffer
// shows the whole array, one element per pixel.
#version 430 core
uniform vec3 u_palette[4];
out vec4 o_color;

void main() {
    o_color = vec4(u_palette[int(gl_FragCoord.x) % 4], 1.0);
}
