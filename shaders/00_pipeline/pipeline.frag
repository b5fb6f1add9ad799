#version 430 core
// Lab 0: every fragment gets the colour interpolated from its triangle's
// vertices (or its line's, or its point's), unlit.

in vec3 v_color;

layout(location = 0) out vec4 frag_color;

void main() {
    frag_color = vec4(v_color, 1.0);
}
