#version 430 core
// Lab 9, scenes subdivide and block: a surface of the unit sphere, moved by
// the matrices of the uniform block SceneBlock (std140: the lab's C++ struct
// SceneBlock must lay its members out byte for byte the same).

// A_POSITION, A_NORMAL, B_SCENE: shared with the lab.
#include "shared.glsl"

layout(location = A_POSITION) in vec3 a_position;
layout(location = A_NORMAL) in vec3 a_normal;

layout(std140, binding = B_SCENE) uniform SceneBlock {
    mat4 mvp;            // object -> clip coordinates
    mat3 normal_matrix;  // object -> world normals
    vec3 light;          // towards the light, world coordinates, unit length
    float ambient;       // the share of the colour lit from everywhere
    vec4 color;          // the surface's colour
};

out vec3 v_normal;  // world coordinates

void main() {
    v_normal = normal_matrix * a_normal;
    gl_Position = mvp * vec4(a_position, 1.0);
}
