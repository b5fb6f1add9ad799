#version 430 core
// Lab 4, mode normals: the normal lines in one colour, unlit.

uniform vec3 u_color;  // yellow

layout(location = 0) out vec4 frag_color;

void main() {
    frag_color = vec4(u_color, 1.0);
}
