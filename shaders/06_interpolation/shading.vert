#version 430 core
// Lab 6, scene shading: the sphere, lit by the lecture's model. Gouraud
// shading evaluates the model here, once per vertex, and lets the rasterizer
// interpolate the colour; Phong and toon shading hand the position and the
// normal on, and shading.frag evaluates per pixel.

// A_POSITION and A_NORMAL: the attribute locations, shared with
// interpolation.cpp.
#include "shared.glsl"

layout(location = A_POSITION) in vec3 a_position;
layout(location = A_NORMAL) in vec3 a_normal;

// The sphere sits at the origin unscaled (model = identity), so object
// coordinates are world coordinates and the lighting is done in the world.
uniform mat4 u_view_projection;
uniform vec3 u_light;  // point light position
uniform vec3 u_eye;    // camera position
uniform vec3 u_ka, u_kd, u_ks, u_la, u_le;
uniform float u_shine;

out vec3 v_position;  // world position
out vec3 v_normal;    // world normal, unit length at the vertices only
out vec3 v_gouraud;   // the model evaluated at this vertex

// The lecture's model at point P with unit normal N:
//   ka La + (kd cos(theta) + ks cos(delta)^shine) Le,
// cos(theta) = N.L, cos(delta) = N.H with the half vector H = normalize(L + V),
// L and V the unit vectors from P towards the light and the eye. Both
// cosines are clamped at 0, and there is no highlight where N.L <= 0 (the
// light is behind the surface).
vec3 blinn_phong(vec3 N, vec3 P) {
    // BEGIN SOLUTION
    // STUDENT: return abs(N);  // TODO: the model above (abs(N) shows the normals meanwhile)
    vec3 L = normalize(u_light - P);
    vec3 V = normalize(u_eye - P);
    vec3 H = normalize(L + V);
    float diffuse = max(dot(N, L), 0.0);
    float specular = dot(N, L) > 0.0 ? pow(max(dot(N, H), 0.0), u_shine) : 0.0;
    return u_ka * u_la + (u_kd * diffuse + u_ks * specular) * u_le;
    // END SOLUTION
}

void main() {
    v_position = a_position;
    v_normal = a_normal;
    v_gouraud = blinn_phong(normalize(a_normal), a_position);
    gl_Position = u_view_projection * vec4(a_position, 1.0);
}
