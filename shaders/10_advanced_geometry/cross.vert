#version 430 core
// Lab 10, scene layers: the cube map unfolded as a cross, one square of 128
// x 128 pixels per face, drawn as six instances of one square. The frame is
// 4 x 4 squares; face f's square has its lower-left corner at kCell[f]:
//           +y
//      -x   +z   +x   -z
//           -y

// A_POSITION: the attribute location, shared with the lab.
#include "shared.glsl"

layout(location = A_POSITION) in vec2 a_corner;  // (0, 0) .. (1, 1)

const vec2 kCell[6] = vec2[6](vec2(2.0, 1.5), vec2(0.0, 1.5), vec2(1.0, 2.5), vec2(1.0, 0.5),
                              vec2(1.0, 1.5), vec2(3.0, 1.5));

out vec2 v_st;
flat out int v_face;

void main() {
    v_face = gl_InstanceID;
    v_st = a_corner;
    vec2 p = (kCell[gl_InstanceID] + a_corner) / 4.0;
    gl_Position = vec4(2.0 * p - 1.0, 0.0, 1.0);
}
