#version 430 core
// Lab 13, scene raycast: the ray caster's shading without its shadows,
// albedo (0.2 + the sum of 0.5 max(n . l, 0) over the lights), or the
// triangle's number (gl_PrimitiveID + 1, in 1/255) for the comparison.
#include "shared.glsl"

flat in vec3 v_normal;
flat in vec3 v_color;

uniform vec3 u_light0;
uniform vec3 u_light1;
uniform int u_light_count;
uniform int u_output;  // OUTPUT_*

out vec4 frag_color;

void main() {
    if (u_output == OUTPUT_ID) {
        frag_color = vec4(float(gl_PrimitiveID + 1) / 255.0, 0.0, 0.0, 1.0);
        return;
    }
    float light = 0.2 + 0.5 * max(dot(v_normal, u_light0), 0.0);
    if (u_light_count > 1) light += 0.5 * max(dot(v_normal, u_light1), 0.0);
    frag_color = vec4(clamp(v_color * light, 0.0, 1.0), 1.0);
}
