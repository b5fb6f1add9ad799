#version 430 core
// Lab 11: GL's side of each scene: the interpolated colour, or 1/255 per
// fragment, which additive blending sums into a count of fragments a pixel got.
#include "shared.glsl"

smooth in vec3 v_smooth;
noperspective in vec3 v_affine;
uniform int u_output;
out vec4 frag_color;

void main() {
    if (u_output == OUTPUT_COUNT) frag_color = vec4(1.0 / 255.0, 0.0, 0.0, 1.0);
    else frag_color = vec4(u_output == OUTPUT_AFFINE ? v_affine : v_smooth, 1.0);
}
