#version 430 core
// Lab 9, scene subdivide: each triangle in one shade, lit by its own plane's
// normal (from the derivatives of the position across the window), every
// other triangle of the draw a little darker (gl_PrimitiveID), so that every
// facet shows, even among triangles that lie in one plane.

in vec3 v_world;

uniform vec3 u_light;  // towards the light, unit length
uniform vec3 u_color;

layout(location = 0) out vec4 frag_color;

void main() {
    vec3 n = normalize(cross(dFdx(v_world), dFdy(v_world)));
    // The facing side, whichever way the triangle winds.
    float diffuse = abs(dot(n, u_light));
    float tint = gl_PrimitiveID % 2 == 0 ? 1.0 : 0.85;
    frag_color = vec4(tint * u_color * (0.25 + 0.75 * diffuse), 1.0);
}
