#version 430 core
// Lab 9, scene feedback: one time step of one particle. Nothing is drawn:
// transform feedback captures v_position and v_velocity, in that order,
// into the other buffer of the pair, and the next step reads them back.

// A_POSITION, A_VELOCITY: the attribute locations, shared with the lab.
#include "shared.glsl"

layout(location = A_POSITION) in vec3 a_position;
layout(location = A_VELOCITY) in vec3 a_velocity;

uniform float u_dt;       // seconds per step
uniform vec3 u_gravity;  // the acceleration, the same for every particle

out vec3 v_position;
out vec3 v_velocity;

void main() {
    // Constant acceleration g over a step of dt: the position moves by
    // v dt + g dt^2 / 2 and the velocity by g dt, exactly.
    // BEGIN SOLUTION
    // STUDENT: v_position = a_position;  // TODO: move by one step of the sheet's motion
    // STUDENT: v_velocity = a_velocity;  // TODO: and change the velocity by gravity
    v_position = a_position + a_velocity * u_dt + 0.5 * u_gravity * u_dt * u_dt;
    v_velocity = a_velocity + u_gravity * u_dt;
    // END SOLUTION
    gl_Position = vec4(v_position, 1.0);
}
