#version 430 core
// Lab 10, scene layers: a vertex of the room or a marker, handed on in world
// coordinates; layers.geom places it in each face of the cube map.

// A_POSITION: the attribute location, shared with the lab.
#include "shared.glsl"

layout(location = A_POSITION) in vec3 a_position;

out vec3 v_world;

void main() {
    v_world = a_position;
    gl_Position = vec4(a_position, 1.0);
}
