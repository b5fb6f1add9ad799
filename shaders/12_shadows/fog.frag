#version 430 core
// Lab 12, scene fog: the surface colour mixed with the fog colour by the fog
// factor f of the distance d = -v_eye.z (the eye-space depth): f = 1 shows the
// surface, f = 0 only fog.

// FOG_NONE, FOG_LINEAR, FOG_EXP, FOG_EXP2: the values of u_fog_mode.
#include "shared.glsl"

in vec3 v_eye;

uniform vec4 u_color;       // the surface
uniform vec3 u_fog_color;
uniform int u_fog_mode;
uniform float u_fog_start;  // linear: f = 1 at this distance ...
uniform float u_fog_end;    // ... and 0 at this one
uniform float u_fog_density;

layout(location = 0) out vec4 frag_color;

void main() {
    float d = -v_eye.z;
    float f = 1.0;
    // BEGIN SOLUTION
    // STUDENT: // TODO: f for u_fog_mode (the sheet's table): linear (end - d) / (end - start),
    // STUDENT: // exp exp(-density d), exp2 exp(-(density d)^2), clamped to [0, 1]
    if (u_fog_mode == FOG_LINEAR) f = (u_fog_end - d) / (u_fog_end - u_fog_start);
    if (u_fog_mode == FOG_EXP) f = exp(-u_fog_density * d);
    if (u_fog_mode == FOG_EXP2) f = exp(-(u_fog_density * d) * (u_fog_density * d));
    f = clamp(f, 0.0, 1.0);
    // END SOLUTION
    frag_color = vec4(mix(u_fog_color, u_color.rgb, f), 1.0);
}
