#version 430 core
// Lab 4, mode wireframe: a fragment within kHalfWidth pixels of an edge of
// its triangle is the edge colour; any other is shaded as in lambert.frag.

in vec3 g_normal;
in vec3 g_color;
noperspective in vec3 g_edge_distance;  // pixels to each edge, from wireframe.geom

uniform vec3 u_light_dir;   // world space, unit length, towards the light
uniform vec3 u_edge_color;  // white

layout(location = 0) out vec4 frag_color;

// Both triangles on an edge draw their side of it: lines 2 pixels wide.
const float kHalfWidth = 1.0;

void main() {
    float nearest = min(g_edge_distance.x, min(g_edge_distance.y, g_edge_distance.z));
    if (nearest < kHalfWidth) {
        frag_color = vec4(u_edge_color, 1.0);
        return;
    }
    float diffuse = max(dot(normalize(g_normal), u_light_dir), 0.0);
    frag_color = vec4(g_color * diffuse, 1.0);
}
