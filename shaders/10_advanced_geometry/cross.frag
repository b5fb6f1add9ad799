#version 430 core
// Lab 10, scene layers: a face's square samples the cube map along the
// direction that GL maps to (s, t) of that face (GL 4.3 core, table 8.19),
// with (s, t) running across the square from its lower-left corner: each
// face as its view drew it.

in vec2 v_st;
flat in int v_face;

uniform samplerCube u_cube;

layout(location = 0) out vec4 frag_color;

// The direction whose face is `face` and whose coordinates there are (s, t):
// table 8.19 read backwards, sc = 2 s - 1 and tc = 2 t - 1.
vec3 direction(int face, vec2 st) {
    float sc = 2.0 * st.x - 1.0, tc = 2.0 * st.y - 1.0;
    switch (face) {
        case 0: return vec3(1.0, -tc, -sc);
        case 1: return vec3(-1.0, -tc, sc);
        case 2: return vec3(sc, 1.0, tc);
        case 3: return vec3(sc, -1.0, -tc);
        case 4: return vec3(sc, -tc, 1.0);
        default: return vec3(-sc, -tc, -1.0);
    }
}

void main() { frag_color = texture(u_cube, direction(v_face, v_st)); }
