// Test shader: compiles but for the error in the file it includes.
#version 430 core
#include "broken_shared.glsl"
out vec4 o_color;

void main() {
    o_color = vec4(WHITE * kGrey, 1.0);
}
