#version 430 core
// Lab 10, scene silhouette: a corner of the cube, turned into the world and
// seen along -z; its world position goes on for flat shading (flat.frag).

// A_POSITION: the attribute location, shared with the lab.
#include "shared.glsl"

layout(location = A_POSITION) in vec3 a_position;

uniform mat4 u_model;       // the cube's turn
uniform mat4 u_projection;  // world -> clip coordinates

out vec3 v_world;

void main() {
    vec4 world = u_model * vec4(a_position, 1.0);
    v_world = world.xyz;
    gl_Position = u_projection * world;
}
