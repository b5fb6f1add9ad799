#version 430 core
// Lab 12, every pass: a world-space position (the meshes are stored in world
// coordinates) moved to clip space by u_view_projection, with its eye-space
// position for the fog and its light clip-space position for the shadow map.

// A_POSITION: the attribute location, shared with shadows.cpp.
#include "shared.glsl"

layout(location = A_POSITION) in vec3 a_position;

uniform mat4 u_model;            // object -> world (the planar shadow's flattening)
uniform mat4 u_view;             // world -> eye
uniform mat4 u_projection;       // eye -> clip
uniform mat4 u_light_view_proj;  // world -> the light's clip space

out vec3 v_eye;
out vec4 v_light;

void main() {
    vec4 world = u_model * vec4(a_position, 1.0);
    vec4 eye = u_view * world;
    v_eye = eye.xyz;
    v_light = u_light_view_proj * world;
    gl_Position = u_projection * eye;
}
