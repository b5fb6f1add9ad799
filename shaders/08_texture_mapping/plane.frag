#version 430 core
// Lab 8, scene perspective: the floor's checkerboard texture looked up with
// the perspective-correct coordinates (left half) or the affine ones (right
// half), as u_affine says.

in vec2 v_uv;                      // smooth: perspective-correct
noperspective in vec2 v_uv_affine; // linear in window coordinates

uniform sampler2D u_texture;
uniform bool u_affine;

layout(location = 0) out vec4 frag_color;

void main() {
    // BEGIN SOLUTION
    // STUDENT: vec2 st = v_uv;  // TODO: the affine coordinates where u_affine is set
    vec2 st = u_affine ? v_uv_affine : v_uv;
    // END SOLUTION
    frag_color = vec4(texture(u_texture, st).rgb, 1.0);
}
