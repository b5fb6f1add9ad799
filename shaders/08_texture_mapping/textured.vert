#version 430 core
// Lab 8, every scene: a position moved by u_mvp, with its texture
// coordinates, its object-space position and normal handed on to the
// fragment shader. The coordinates go out twice: perspective-correct
// (smooth, the default, written as no qualifier: in GLSL 4.30 the input of
// the same name must carry the same qualifier) and linear in window
// coordinates (noperspective).

// A_POSITION, A_UV, A_NORMAL: the attribute locations, shared with the lab.
#include "shared.glsl"

layout(location = A_POSITION) in vec3 a_position;
layout(location = A_UV) in vec2 a_uv;
layout(location = A_NORMAL) in vec3 a_normal;

uniform mat4 u_mvp;  // object -> clip coordinates

out vec2 v_uv;  // perspective-correct: no qualifier is smooth
noperspective out vec2 v_uv_affine;
out vec3 v_object;
out vec3 v_normal;

void main() {
    v_uv = a_uv;
    v_uv_affine = a_uv;
    v_object = a_position;
    v_normal = a_normal;
    gl_Position = u_mvp * vec4(a_position, 1.0);
}
