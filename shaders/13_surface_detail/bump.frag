#version 430 core
// Lab 13, scene bump: a white surface lit 0.1 + 0.9 max(n . l, 0), with the
// normal map's normal against the light in tangent space (bumped), or the
// interpolated normal against the light in world space (interpolated).
#include "shared.glsl"

in vec2 v_uv;
in vec3 v_normal;
in vec3 v_light_tangent;

uniform sampler2D u_normal_map;  // tangent-space normals, as floats
uniform int u_normals;           // NORMALS_*
uniform vec3 u_light;

out vec4 frag_color;

float lambert(vec3 n, vec3 l) { return 0.1 + 0.9 * max(dot(n, l), 0.0); }

void main() {
    float c = u_normals == NORMALS_BUMPED
                  ? lambert(texture(u_normal_map, v_uv).xyz, normalize(v_light_tangent))
                  : lambert(normalize(v_normal), u_light);
    frag_color = vec4(vec3(c), 1.0);
}
