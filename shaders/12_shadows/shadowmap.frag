#version 430 core
// Lab 12, scene shadowmap: the ground lit where the light sees it, and at
// half its colour where the shadow map holds something nearer to the light.

in vec4 v_light;  // the fragment in the light's clip space (an orthographic light: w = 1)

uniform vec4 u_color;
uniform sampler2DShadow u_shadow_map;  // compares a reference depth with the stored one
uniform float u_bias;                  // subtracted from the fragment's light depth

layout(location = 0) out vec4 frag_color;

void main() {
    float lit = 1.0;
    // BEGIN SOLUTION
    // STUDENT: // TODO: p, the fragment's position in the light's window (v_light is its clip
    // STUDENT: // position), then lit: the shadow map's comparison at p.xy of p.z less the bias
    vec3 p = v_light.xyz / v_light.w * 0.5 + 0.5;
    lit = texture(u_shadow_map, vec3(p.xy, p.z - u_bias));
    // END SOLUTION
    frag_color = vec4(u_color.rgb * (0.5 + 0.5 * lit), 1.0);
}
