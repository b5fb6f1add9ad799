#version 430 core
// Lab 8, scenes wrap, magnify, minify and lightmap: a square textured by
// u_texture (texture unit 0) with the sampler state the lab set; in scene
// lightmap the base texture modulated by the light map (texture unit 1).

// MAPS_*: the values of u_maps, shared with texture_mapping.cpp.
#include "shared.glsl"

in vec2 v_uv;

uniform sampler2D u_texture;    // the base texture
uniform sampler2D u_light_map;  // scene lightmap only
uniform int u_maps;             // scene lightmap: a MAPS_* value; else MAPS_BASE

layout(location = 0) out vec4 frag_color;

void main() {
    vec3 base = texture(u_texture, v_uv).rgb;
    vec3 color = base;
    if (u_maps != MAPS_BASE) {
        vec3 light = texture(u_light_map, v_uv).rgb;
        // A light map modulates: the base colour times the light that falls there.
        // BEGIN SOLUTION
        // STUDENT: color = light;  // TODO: the light map alone, or the base times the light map
        color = u_maps == MAPS_LIGHT ? light : base * light;
        // END SOLUTION
    }
    frag_color = vec4(color, 1.0);
}
