#version 430 core
// Lab 8, scene coordinates: the unit sphere textured with (s, t) stored per
// vertex or computed here, per fragment, from the object-space position by a
// planar, cylindrical or spherical mapping; lit or not.

// MAPPING_*: the values of u_mapping, shared with texture_mapping.cpp.
#include "shared.glsl"

in vec2 v_uv;      // per vertex: spherical(), computed in C++ (mappings.cpp)
in vec3 v_object;  // the fragment's position on the sphere
in vec3 v_normal;

uniform sampler2D u_texture;
uniform int u_mapping;
uniform bool u_lit;
uniform vec3 u_light;  // unit vector towards the light
uniform float u_ka, u_kd;

layout(location = 0) out vec4 frag_color;

const float kPi = 3.14159265358979;

// The lab sheet's three mappings, as mappings.cpp computes them in C++: p is
// a point in object coordinates.
// BEGIN SOLUTION
// STUDENT: vec2 planar(vec3 p) { return vec2(0.0); }       // TODO: along z onto [-1, 1]^2
// STUDENT: vec2 cylindrical(vec3 p) { return vec2(0.0); }  // TODO: angle about y, height
// STUDENT: vec2 spherical(vec3 p) { return vec2(0.0); }    // TODO: longitude, latitude
vec2 planar(vec3 p) { return 0.5 * p.xy + 0.5; }

vec2 cylindrical(vec3 p) { return vec2(atan(p.x, p.z) / (2.0 * kPi) + 0.5, 0.5 * p.y + 0.5); }

vec2 spherical(vec3 p) {
    float r = length(p);
    if (r == 0.0) return vec2(0.5);
    return vec2(atan(p.x, p.z) / (2.0 * kPi) + 0.5, asin(clamp(p.y / r, -1.0, 1.0)) / kPi + 0.5);
}
// END SOLUTION

void main() {
    vec2 st = u_mapping == MAPPING_VERTEX      ? v_uv
            : u_mapping == MAPPING_PLANAR      ? planar(v_object)
            : u_mapping == MAPPING_CYLINDRICAL ? cylindrical(v_object)
                                               : spherical(v_object);
    vec3 texel = texture(u_texture, st).rgb;
    vec3 color = texel;
    if (u_lit) {
        // The texture is the surface's diffuse colour, lit per fragment.
        vec3 N = normalize(v_normal);
        // BEGIN SOLUTION
        // STUDENT: // TODO: color = texel * (u_ka + u_kd * max(N . u_light, 0))
        color = texel * (u_ka + u_kd * max(dot(N, u_light), 0.0));
        // END SOLUTION
    }
    frag_color = vec4(color, 1.0);
}
