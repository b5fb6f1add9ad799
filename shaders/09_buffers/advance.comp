#version 430 core
// Lab 9, scene compute: one time step of every particle, one invocation per
// particle, over a storage buffer that the points are then drawn from.

// B_PARTICLES: the storage buffer binding, shared with the lab.
#include "shared.glsl"

// How many invocations make one work group: the lab reads it back from the
// program (GL_COMPUTE_WORK_GROUP_SIZE) to know how many groups to dispatch.
// BEGIN SOLUTION
// STUDENT: layout(local_size_x = 1) in;  // TODO: 64 invocations per work group
layout(local_size_x = 64) in;
// END SOLUTION

// std430: a vec3 in an array is aligned to 16 bytes, so the particles are
// stored as vec4s (w unused) and the C++ struct says the same.
struct Particle {
    vec4 position;
    vec4 velocity;
};
layout(std430, binding = B_PARTICLES) buffer Particles {
    Particle particles[];
};

uniform uint u_count;     // particles in the buffer
uniform float u_dt;       // seconds per step
uniform vec3 u_gravity;  // the acceleration

void main() {
    uint i = gl_GlobalInvocationID.x;
    // The last work group may run past the end: those invocations do nothing.
    // BEGIN SOLUTION
    // STUDENT: // TODO: leave when i is past the last particle; then one step, as advance.vert
    if (i >= u_count) return;
    vec3 v = particles[i].velocity.xyz;
    particles[i].position.xyz += v * u_dt + 0.5 * u_gravity * u_dt * u_dt;
    particles[i].velocity.xyz = v + u_gravity * u_dt;
    // END SOLUTION
}
