// Test shader for the uniform setters: every uniform but u_unused affects
// the output, so only u_unused is optimised out.
#version 430 core
uniform vec3 u_color;
uniform float u_weights[4];
uniform vec3 u_lights[3];
uniform bool u_flag;
uniform int u_count;
uniform uint u_mask;
uniform mat3 u_tint;
uniform sampler2D u_texture;
uniform float u_unused;
out vec4 o_color;

void main() {
    float w = u_weights[0] + u_weights[1] + u_weights[2] + u_weights[3];
    vec3 light = u_lights[0] + u_lights[1] + u_lights[2];
    vec3 c = u_tint * (u_color + light * w);
    c += texture(u_texture, vec2(0.5)).rgb * float(u_count) + float(u_mask);
    o_color = u_flag ? vec4(c, 1.0) : vec4(c.bgr, 1.0);
}
