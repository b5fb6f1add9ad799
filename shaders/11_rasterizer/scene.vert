#version 430 core
// Lab 11: GL's side of each scene. The positions are already in clip space;
// the colour goes out twice, perspective-correct and affine.
#include "shared.glsl"

layout(location = A_POSITION) in vec4 a_position;
layout(location = A_COLOR) in vec3 a_color;

smooth out vec3 v_smooth;
noperspective out vec3 v_affine;

void main() {
    v_smooth = a_color;
    v_affine = a_color;
    gl_Position = a_position;
}
