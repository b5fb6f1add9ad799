#version 430 core
// Lab 4: Lambert's diffuse term, per fragment, with no ambient term: the
// parts of the sphere turned away from the light are black.

in vec3 g_normal;  // world space, interpolated (so no longer unit length)
in vec3 g_color;   // the Lambert colour: grey, or the duplicate's tint

uniform vec3 u_light_dir;  // world space, unit length, towards the light

layout(location = 0) out vec4 frag_color;

void main() {
    float diffuse = max(dot(normalize(g_normal), u_light_dir), 0.0);
    frag_color = vec4(g_color * diffuse, 1.0);
}
