#version 430 core
// Lab 6, scene shading: one fragment of the sphere, shaded as u_shading says.

in vec3 v_position;
in vec3 v_normal;
in vec3 v_gouraud;

// SHADING_GOURAUD, SHADING_PHONG, SHADING_TOON: the values of u_shading,
// shared with interpolation.cpp.
#include "shared.glsl"

uniform int u_shading;  // a SHADING_* value
uniform vec3 u_light, u_eye;
uniform vec3 u_ka, u_kd, u_ks, u_la, u_le;
uniform float u_shine;

layout(location = 0) out vec4 frag_color;

// The same model as blinn_phong() in shading.vert (shared.glsl holds only
// names, no code): Gouraud and Phong shading differ only in where it is
// evaluated.
vec3 blinn_phong(vec3 N, vec3 P) {
    // BEGIN SOLUTION
    // STUDENT: return abs(N);  // TODO: the model of shading.vert, here per pixel
    vec3 L = normalize(u_light - P);
    vec3 V = normalize(u_eye - P);
    vec3 H = normalize(L + V);
    float diffuse = max(dot(N, L), 0.0);
    float specular = dot(N, L) > 0.0 ? pow(max(dot(N, H), 0.0), u_shine) : 0.0;
    return u_ka * u_la + (u_kd * diffuse + u_ks * specular) * u_le;
    // END SOLUTION
}

// The lecture's NPR shader: an outline where the surface turns away from
// the eye (|N.V| < 0.2) in black, else kd in two tones, full where
// N.L > 0.5, half elsewhere.
vec3 toon(vec3 N, vec3 P) {
    // BEGIN SOLUTION
    // STUDENT: return u_kd;  // TODO: black, kd or 0.5 kd
    vec3 L = normalize(u_light - P);
    vec3 V = normalize(u_eye - P);
    if (abs(dot(N, V)) < 0.2) return vec3(0.0);
    return u_kd * (dot(N, L) > 0.5 ? 1.0 : 0.5);
    // END SOLUTION
}

void main() {
    // The interpolated normal is shorter than 1 between the vertices.
    vec3 N = normalize(v_normal);
    vec3 color = u_shading == SHADING_GOURAUD ? v_gouraud
               : u_shading == SHADING_PHONG   ? blinn_phong(N, v_position)
                                              : toon(N, v_position);
    frag_color = vec4(color, 1.0);
}
