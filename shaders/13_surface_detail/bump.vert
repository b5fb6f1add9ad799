#version 430 core
// Lab 13, scene bump: the squares (ortho camera), each vertex with its
// tangent frame; the light goes to the fragment shader in tangent space.
#include "shared.glsl"

layout(location = A_POSITION) in vec3 a_position;
layout(location = A_NORMAL) in vec3 a_normal;
layout(location = A_TANGENT) in vec3 a_tangent;
layout(location = A_BITANGENT) in vec3 a_bitangent;
layout(location = A_UV) in vec2 a_uv;

uniform mat4 u_projection;  // world -> clip (V = I)
uniform vec3 u_light;       // unit vector towards the light, world space

out vec2 v_uv;
out vec3 v_normal;         // world space
out vec3 v_light_tangent;  // u_light in the vertex's tangent space

void main() {
    v_uv = a_uv;
    v_normal = a_normal;
    // BEGIN SOLUTION
    // STUDENT: v_light_tangent = vec3(0.0, 0.0, 1.0);
    // STUDENT: // TODO: u_light in tangent space: its components along T, B and N
    v_light_tangent =
        vec3(dot(u_light, a_tangent), dot(u_light, a_bitangent), dot(u_light, a_normal));
    // END SOLUTION
    gl_Position = u_projection * vec4(a_position, 1.0);
}
