#version 430 core
// Lab 10, scene clip: the unit sphere seen along -z, cut by a user clip
// plane. A clip distance below 0 puts the vertex outside the plane, and the
// rasterizer clips each triangle where the interpolated distance is 0,
// exactly as it clips against the view volume.

// A_POSITION, A_NORMAL: the attribute locations, shared with the lab.
#include "shared.glsl"

layout(location = A_POSITION) in vec3 a_position;
layout(location = A_NORMAL) in vec3 a_normal;

uniform mat4 u_projection;  // world -> clip coordinates (the sphere's model is the identity)
uniform vec4 u_plane;       // (n, d): the points p with n . p + d >= 0 are kept

out vec3 v_normal;

void main() {
    vec4 world = vec4(a_position, 1.0);
    v_normal = a_normal;
    gl_Position = u_projection * world;
    // BEGIN SOLUTION
    // STUDENT: // TODO: gl_ClipDistance[0]: the signed distance of the world position from u_plane
    gl_ClipDistance[0] = dot(u_plane, world);
    // END SOLUTION
}
