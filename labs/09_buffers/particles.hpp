// Lab 9's particles: where they start (the sheet's closed form), the buffers
// they live in on the GPU, and the two ways the GPU advances them, transform
// feedback (advance_with_feedback) and a compute shader (advance_with_compute):
// student parts, in particles.cpp.
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "capture.hpp"
#include "framework/gl.hpp"

namespace buffers {

// The sheet's motion: every particle starts at kSource, and gravity is the
// only force. Each step of kDt seconds moves a particle by v dt + g dt^2 / 2
// and changes its velocity by g dt, which is exact for a constant g: after n
// steps, at t = n dt, p = kSource + v0 t + g t^2 / 2.
constexpr float kDt = 0.02f;
constexpr glm::vec3 kGravity{0.0f, -4.0f, 0.0f};
constexpr glm::vec3 kSource{0.0f, -1.5f, 0.0f};
constexpr int kMaxParticles = 1000;

// A particle as transform feedback captures it: advance.vert's outputs
// v_position and v_velocity, interleaved in that order (24 bytes).
struct Particle {
    glm::vec3 position;
    glm::vec3 velocity;
};

// Particle i of `count` at t = 0: at kSource, moving at 3 units a second at
// the angle phi = 30 + 120 (i + 0.5) / count degrees from +x towards +y.
std::vector<Particle> initial_particles(int count);

// Two copies of the particles, kMaxParticles each: a step reads one
// (vertices[i] reads buffer[i]) and captures into the other (capture[i]
// captures into buffer[i]).
using FeedbackPair = CapturePair;
FeedbackPair make_feedback_pair();

// Advances the `count` particles in pair.buffer[0] by `steps` steps of
// `step` (advance.vert, linked to capture v_position and v_velocity), with
// the rasterizer off, and returns the index of the buffer that holds the
// result (0 when steps is 0).
int advance_with_feedback(FeedbackPair& pair, const fw::Program& step, int count, int steps);

// A particle in advance.comp's storage buffer (std430): a vec3 in an array
// of structs is aligned to 16 bytes, so both are stored as vec4 (w unused).
struct GpuParticle {
    glm::vec4 position;
    glm::vec4 velocity;
};

// The compute scene's storage buffer and the vertex array that draws its
// positions as points. It holds kMaxParticles GpuParticles and, after the
// particles of a frame, a guard of one work group (at most kMaxGuard): what
// invocations past the count would write into (make_guarded).
constexpr int kMaxGuard = 1024;
struct ComputeParticles {
    fw::Buffer buffer;
    fw::VertexArray vertices;
};
ComputeParticles make_compute_particles();

// `particles` followed by `guard` elements of a sentinel, which no
// invocation may change.
std::vector<GpuParticle> make_guarded(const std::vector<Particle>& particles, int guard);

// Advances the `count` particles of `particles` by `steps` dispatches of
// `advance` (advance.comp, already in use with its uniforms set and the
// buffer bound at B_PARTICLES), one invocation per particle, and leaves them
// ready to be drawn as vertices. Returns the work groups of each dispatch.
int advance_with_compute(const fw::Program& advance, int count, int steps);

// x, y, z of the first `count` particles of a buffer read back, one after
// the other: what the grader compares with the sheet's motion.
template <class P>
std::vector<float> positions_of(const std::vector<P>& particles, int count) {
    std::vector<float> out;
    for (int i = 0; i < count && i < static_cast<int>(particles.size()); ++i)
        for (int k = 0; k < 3; ++k) out.push_back(particles[i].position[k]);
    return out;
}

}  // namespace buffers
