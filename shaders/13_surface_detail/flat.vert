#version 430 core
// Lab 13, scene raycast: GL's z-buffer image of the ray caster's scene, each
// triangle with its own (flat) normal and colour.
#include "shared.glsl"

layout(location = A_POSITION) in vec3 a_position;
layout(location = A_NORMAL) in vec3 a_normal;
layout(location = A_COLOR) in vec3 a_color;

uniform mat4 u_view_projection;

flat out vec3 v_normal;
flat out vec3 v_color;

void main() {
    v_normal = a_normal;
    v_color = a_color;
    gl_Position = u_view_projection * vec4(a_position, 1.0);
}
