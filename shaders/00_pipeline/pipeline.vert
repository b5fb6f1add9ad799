#version 430 core
// Lab 0: hands each vertex's position and colour down the pipeline. u_mvp is
// the identity in scenes order, indexed and primitives (their positions are
// already NDC) and the cube's projection * view * model in scene culling.

// A_POSITION and A_COLOR: the attribute locations that pipeline.cpp describes.
#include "shared.glsl"

layout(location = A_POSITION) in vec3 a_position;
layout(location = A_COLOR) in vec3 a_color;

uniform mat4 u_mvp;

// Interpolated across each triangle, read by pipeline.frag.
out vec3 v_color;

void main() {
    // BEGIN SOLUTION
    // STUDENT: vec3 position = vec3(0.0);  // TODO: this vertex's position, from a_position
    // STUDENT: v_color = vec3(1.0);        // TODO: this vertex's colour, from a_color
    vec3 position = a_position;
    v_color = a_color;
    // END SOLUTION
    gl_Position = u_mvp * vec4(position, 1.0);
    // Size in pixels of GL_POINTS (scene primitives, primitive points). GL
    // reads it only while GL_PROGRAM_POINT_SIZE is enabled, as the lab does.
    gl_PointSize = 8.0;
}
