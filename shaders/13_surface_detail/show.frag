#version 430 core
// Lab 13, scene raycast: the ray-cast image, GL's image or their
// difference, magnified (nearest).
#include "shared.glsl"

in vec2 v_uv;
uniform sampler2D u_cpu;
uniform sampler2D u_gl;
uniform int u_view;  // VIEW_*
out vec4 frag_color;

void main() {
    vec3 cpu = texture(u_cpu, v_uv).rgb;
    vec3 gl = texture(u_gl, v_uv).rgb;
    vec3 c = u_view == VIEW_CPU ? cpu : u_view == VIEW_GL ? gl : abs(cpu - gl);
    frag_color = vec4(c, 1.0);
}
