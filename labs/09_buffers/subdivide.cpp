// Lab 9's subdivision passes: each captures the geometry shader's triangles
// and the next draws them.
#include "subdivide.hpp"

// A_POSITION: the attribute location, shared with the shaders.
#include "shared.glsl"

namespace buffers {

std::vector<glm::vec3> octahedron() {
    const glm::vec3 ring[4] = {{1, 0, 0}, {0, 0, -1}, {-1, 0, 0}, {0, 0, 1}};
    const glm::vec3 top(0, 1, 0), bottom(0, -1, 0);
    std::vector<glm::vec3> v;
    for (int i = 0; i < 4; ++i) v.insert(v.end(), {ring[i], ring[(i + 1) % 4], top});
    for (int i = 0; i < 4; ++i) v.insert(v.end(), {ring[(i + 1) % 4], ring[i], bottom});
    return v;
}

SubdivisionPair make_subdivision_pair() {
    std::size_t most = 8 * 3;
    for (int k = 0; k < kMaxPasses; ++k) most *= 4;
    fw::VertexLayout layout(sizeof(glm::vec3));
    layout.add({A_POSITION, 3, GL_FLOAT, 0, false, false});
    return make_capture_pair(most * sizeof(glm::vec3), layout, "sphere");
}

int subdivide(SubdivisionPair& pair, const fw::Program& program, int passes) {
    program.use();
    glEnable(GL_RASTERIZER_DISCARD);
    int from = 0;
    for (int n = 0; n < passes; ++n) {
        const int to = 1 - from;
        glBindVertexArray(pair.vertices[from].id());
        glBindTransformFeedback(GL_TRANSFORM_FEEDBACK, pair.capture[to].id());
        glBeginTransformFeedback(GL_TRIANGLES);
        if (n == 0)
            glDrawArrays(GL_TRIANGLES, 0, 24);
        else
            glDrawTransformFeedback(GL_TRIANGLES, pair.capture[from].id());
        glEndTransformFeedback();
        from = to;
    }
    glBindTransformFeedback(GL_TRANSFORM_FEEDBACK, 0);
    glDisable(GL_RASTERIZER_DISCARD);
    return from;
}

}  // namespace buffers
