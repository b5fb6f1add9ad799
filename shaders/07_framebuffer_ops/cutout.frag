#version 430 core
// Lab 7, scene discard: a fence of round holes. Alpha is 0 at the centre of
// each of u_cells x u_cells cells and grows with the distance from it,
// reaching 1 half a cell away. The fence is blended "over" what is behind it.

in vec2 v_uv;

uniform vec3 u_color;
uniform float u_cells;     // cells along u and along v
uniform bool u_alpha_test; // on: discard the fragments whose alpha is below u_cutoff
uniform float u_cutoff;

layout(location = 0) out vec4 frag_color;

void main() {
    vec2 from_centre = fract(v_uv * u_cells) - 0.5;
    float alpha = clamp(2.0 * length(from_centre), 0.0, 1.0);
    // A fragment that is blended away, however transparent, still writes its
    // depth; one that is discarded writes nothing at all, so what is drawn
    // behind it later still passes the depth test there.
    // BEGIN SOLUTION
    // STUDENT: // TODO: with u_alpha_test on, discard the fragment when alpha < u_cutoff
    if (u_alpha_test && alpha < u_cutoff) discard;
    // END SOLUTION
    frag_color = vec4(u_color, alpha);
}
