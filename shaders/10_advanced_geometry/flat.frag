#version 430 core
// Lab 10, scene silhouette: each face of the cube in one shade, lit by its own
// plane's normal (from the derivatives of the world position across the
// window): color (0.3 + 0.7 max(n.z, 0)), the light behind the eye.

in vec3 v_world;

uniform vec3 u_color;

layout(location = 0) out vec4 frag_color;

void main() {
    vec3 n = normalize(cross(dFdx(v_world), dFdy(v_world)));
    frag_color = vec4(u_color * (0.3 + 0.7 * max(n.z, 0.0)), 1.0);
}
