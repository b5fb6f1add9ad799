// Lab 9's particles: their start, their buffers, and the two ways the GPU
// advances them (student parts: advance_with_feedback, advance_with_compute).
#include "particles.hpp"

#include <glm/gtc/constants.hpp>

// A_POSITION, A_VELOCITY: the attribute locations, shared with the shaders.
#include "shared.glsl"

namespace buffers {

std::vector<Particle> initial_particles(int count) {
    std::vector<Particle> out;
    for (int i = 0; i < count; ++i) {
        const double phi = glm::radians(30.0 + 120.0 * (i + 0.5) / count);
        out.push_back({kSource, glm::vec3(3.0 * std::cos(phi), 3.0 * std::sin(phi), 0.0)});
    }
    return out;
}

FeedbackPair make_feedback_pair() {
    return make_capture_pair(kMaxParticles * sizeof(Particle),
                             fw::VertexLayout::of<Particle>()
                                 .attr(A_POSITION, &Particle::position)
                                 .attr(A_VELOCITY, &Particle::velocity),
                             "particles");
}

int advance_with_feedback(FeedbackPair& pair, const fw::Program& step, int count, int steps) {
    // Each step draws the particles of one buffer as points, with nothing
    // rasterized, while the other buffer captures what the vertex shader
    // wrote; then the two swap roles.
    // BEGIN SOLUTION
    // STUDENT: (void)pair, (void)step, (void)count, (void)steps;
    // STUDENT: return 0;  // TODO: GL_RASTERIZER_DISCARD, then each step: bind, capture, draw
    step.use();
    glEnable(GL_RASTERIZER_DISCARD);
    int from = 0;
    for (int n = 0; n < steps; ++n) {
        const int to = 1 - from;
        glBindVertexArray(pair.vertices[from].id());
        glBindTransformFeedback(GL_TRANSFORM_FEEDBACK, pair.capture[to].id());
        glBeginTransformFeedback(GL_POINTS);
        glDrawArrays(GL_POINTS, 0, count);
        glEndTransformFeedback();
        from = to;
    }
    glBindTransformFeedback(GL_TRANSFORM_FEEDBACK, 0);
    glDisable(GL_RASTERIZER_DISCARD);
    return from;
    // END SOLUTION
}

ComputeParticles make_compute_particles() {
    ComputeParticles c;
    fw::BufferDesc desc;
    desc.target = GL_SHADER_STORAGE_BUFFER;
    desc.size = (kMaxParticles + kMaxGuard) * sizeof(GpuParticle);
    desc.usage = GL_DYNAMIC_COPY;
    desc.label = "compute particles";
    c.buffer = fw::Buffer(desc);
    c.vertices = fw::VertexArray(fw::VertexArrayDesc{
        .vertices = &c.buffer,
        .layout = fw::VertexLayout::of<GpuParticle>().attr(A_POSITION, &GpuParticle::position),
        .label = "compute particles"});
    return c;
}

std::vector<GpuParticle> make_guarded(const std::vector<Particle>& particles, int guard) {
    std::vector<GpuParticle> out;
    for (const Particle& q : particles)
        out.push_back({glm::vec4(q.position, 1.0f), glm::vec4(q.velocity, 0.0f)});
    // A value no step of the motion makes.
    const GpuParticle sentinel{glm::vec4(-1.0e30f), glm::vec4(-1.0e30f)};
    out.insert(out.end(), static_cast<std::size_t>(guard), sentinel);
    return out;
}

int advance_with_compute(const fw::Program& advance, int count, int steps) {
    // As many work groups as cover every particle: the size of one comes from
    // the program (GL_COMPUTE_WORK_GROUP_SIZE). A dispatch must see what the
    // one before wrote, and the draw must see what the last one wrote: each
    // needs a barrier for the way it reads the buffer next.
    // BEGIN SOLUTION
    // STUDENT: (void)advance, (void)count, (void)steps;
    // STUDENT: return 0;  // TODO: glGetProgramiv, groups, glDispatchCompute, glMemoryBarrier
    GLint size[3] = {1, 1, 1};
    glGetProgramiv(advance.id(), GL_COMPUTE_WORK_GROUP_SIZE, size);
    const int groups = (count + size[0] - 1) / size[0];
    for (int n = 0; n < steps; ++n) {
        glDispatchCompute(static_cast<GLuint>(groups), 1, 1);
        glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT);
    }
    glMemoryBarrier(GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT);
    return groups;
    // END SOLUTION
}

}  // namespace buffers
