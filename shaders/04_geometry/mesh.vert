#version 430 core
// Lab 4: the vertex shader of every mode. It only moves one vertex into the
// world and into clip space; the geometry shader after it sees whole
// triangles.

// A_POSITION and A_NORMAL: the attribute locations, shared with geometry.cpp.
#include "shared.glsl"

layout(location = A_POSITION) in vec3 a_position;  // object space, on the unit sphere
layout(location = A_NORMAL) in vec3 a_normal;      // object space, equal to a_position

uniform mat4 u_model;            // rotateY(spin)
uniform mat4 u_view_projection;  // P * V

// World space, for the geometry shader.
out vec3 v_position;
out vec3 v_normal;

void main() {
    vec4 world = u_model * vec4(a_position, 1.0);
    v_position = world.xyz;
    // The model is a rotation, which keeps lengths and angles, so it turns
    // normals as it turns positions. (In general normals need the inverse
    // transpose of mat3(u_model).)
    v_normal = mat3(u_model) * a_normal;
    gl_Position = u_view_projection * world;
}
