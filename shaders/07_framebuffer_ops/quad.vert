#version 430 core
// Lab 7, every scene: a position moved by u_mvp, with its texture
// coordinates and its object-space position handed on to the fragment shader.

// A_POSITION and A_UV: the attribute locations, shared with framebuffer_ops.cpp.
#include "shared.glsl"

layout(location = A_POSITION) in vec3 a_position;
layout(location = A_UV) in vec2 a_uv;

uniform mat4 u_mvp;  // object -> clip coordinates

out vec2 v_uv;
out vec3 v_object;

void main() {
    v_uv = a_uv;
    v_object = a_position;
    gl_Position = u_mvp * vec4(a_position, 1.0);
}
