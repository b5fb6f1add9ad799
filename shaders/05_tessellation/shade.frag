#version 430 core
// Lab 5: the colour of a fragment. Within 1 pixel of an edge of its
// tessellated triangle it is the edge colour (when `wireframe` is on); else
// the fill colour (scene triangle), Lambert's diffuse term as in lab 4, or
// with show=normals the unit normal as a colour, 0.5 * n + 0.5.

in vec3 g_normal;                       // interpolated, so no longer unit length
noperspective in vec3 g_edge_distance;  // pixels to each edge, from wireframe.geom

// SHADING_FILL, SHADING_LAMBERT, SHADING_NORMAL: the values of u_shading,
// shared with tessellation.cpp (its enum Shading).
#include "shared.glsl"

uniform int u_shading;
uniform vec3 u_color;      // the fill colour, or the Lambert colour
uniform vec3 u_light_dir;  // world space, unit length, towards the light
uniform bool u_wireframe;
uniform vec3 u_edge_color;  // white

layout(location = 0) out vec4 frag_color;

// Both triangles on an edge paint their side of it: lines 2 pixels wide.
const float kHalfWidth = 1.0;

void main() {
    float nearest = min(g_edge_distance.x, min(g_edge_distance.y, g_edge_distance.z));
    vec3 n = normalize(g_normal);
    if (u_wireframe && nearest < kHalfWidth)
        frag_color = vec4(u_edge_color, 1.0);
    else if (u_shading == SHADING_FILL)
        frag_color = vec4(u_color, 1.0);
    else if (u_shading == SHADING_LAMBERT)
        frag_color = vec4(u_color * max(dot(n, u_light_dir), 0.0), 1.0);
    else  // SHADING_NORMAL
        frag_color = vec4(0.5 * n + 0.5, 1.0);
}
