// Lab 7's geometry and cameras; the numbers are those of
// labs/07_framebuffer_ops/README.md.
#include "scenes.hpp"

#include <cmath>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace framebuffer_ops {

namespace {

constexpr float kNear = 0.1f, kFar = 100.0f;
constexpr int kDiscSegments = 64;

}  // namespace

std::vector<Vertex> square_vertices() {
    return {{{0, 0, 0}, {0, 0}}, {{1, 0, 0}, {1, 0}}, {{1, 1, 0}, {1, 1}}, {{0, 1, 0}, {0, 1}}};
}

std::vector<GLuint> square_indices() { return {0, 1, 2, 0, 2, 3}; }

glm::mat4 rect(float x0, float y0, float x1, float y1, float z) {
    return glm::scale(glm::translate(glm::mat4(1.0f), {x0, y0, z}), {x1 - x0, y1 - y0, 1.0f});
}

glm::mat4 quad_a() { return rect(-0.7f, -0.7f, 0.3f, 0.3f, 0.0f); }
glm::mat4 quad_b() { return rect(-0.3f, -0.3f, 0.7f, 0.7f, 0.0f); }

std::vector<Pane> panes() {
    return {{{-0.3f, -0.3f, 0.5f}, 0.5f, {0.9f, 0.1f, 0.1f, 0.5f}},
            {{0.0f, 0.0f, 0.0f}, 0.5f, {0.1f, 0.9f, 0.1f, 0.5f}},
            {{0.3f, 0.3f, -0.5f}, 0.5f, {0.1f, 0.1f, 0.9f, 0.5f}}};
}

glm::mat4 sorting_view_projection() {
    const glm::mat4 view = glm::lookAt(kSortingEye, glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    return glm::perspective(glm::radians(45.0f), 1.0f, kNear, kFar) * view;
}

glm::mat4 pane_model(const Pane& pane) {
    const glm::vec3 c = pane.centre;
    const float h = pane.half_size;
    return rect(c.x - h, c.y - h, c.x + h, c.y + h, c.z);
}

glm::mat4 fence() { return rect(-0.8f, -0.8f, 0.8f, 0.8f, -0.5f); }
glm::mat4 back_quad() { return rect(-0.6f, -0.6f, 0.6f, 0.6f, 0.5f); }

std::vector<Vertex> disc_vertices() {
    std::vector<Vertex> v{{{0, 0, 0}, {0.5f, 0.5f}}};
    for (int i = 0; i <= kDiscSegments; ++i) {
        const float a = glm::two_pi<float>() * float(i) / float(kDiscSegments);
        v.push_back({{std::cos(a), std::sin(a), 0.0f}, {0.5f, 0.5f}});
    }
    return v;
}

std::vector<Band> bands() {
    return {{-1.0f, -0.2f, {0.9f, 0.2f, 0.2f, 1.0f}},
            {-0.2f, 0.2f, {0.2f, 0.9f, 0.2f, 1.0f}},
            {0.2f, 1.0f, {0.2f, 0.2f, 0.9f, 1.0f}}};
}

glm::mat4 disc(float radius) { return glm::scale(glm::mat4(1.0f), {radius, radius, 1.0f}); }

std::vector<Vertex> box_vertices() {
    // Each face: its centre c, and r and u with r x u along the outward
    // normal, so that c - r - u, c + r - u, c + r + u, c - r + u runs
    // counter-clockwise seen from outside.
    struct Face {
        glm::vec3 c, r, u;
    };
    const Face faces[] = {
        {{0, 0, 0.5f}, {0.5f, 0, 0}, {0, 0.5f, 0}},    // front, +z
        {{0.5f, 0, 0}, {0, 0, -0.5f}, {0, 0.5f, 0}},   // right, +x
        {{0, 0, -0.5f}, {-0.5f, 0, 0}, {0, 0.5f, 0}},  // back, -z
        {{-0.5f, 0, 0}, {0, 0, 0.5f}, {0, 0.5f, 0}},   // left, -x
        {{0, -0.5f, 0}, {0.5f, 0, 0}, {0, 0, 0.5f}},   // bottom, -y
    };
    std::vector<Vertex> v;
    for (const Face& f : faces) {
        v.push_back({f.c - f.r - f.u, {0, 0}});
        v.push_back({f.c + f.r - f.u, {1, 0}});
        v.push_back({f.c + f.r + f.u, {1, 1}});
        v.push_back({f.c - f.r + f.u, {0, 1}});
    }
    return v;
}

std::vector<GLuint> box_indices() {
    std::vector<GLuint> i;
    for (GLuint f = 0; f < 5; ++f)
        for (GLuint k : {0u, 1u, 2u, 0u, 2u, 3u}) i.push_back(4 * f + k);
    return i;
}

glm::mat4 box_view_projection() {
    const glm::mat4 view =
        glm::lookAt(kBoxEye, glm::vec3(0.0f, -0.3f, 0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    return glm::perspective(glm::radians(45.0f), 1.0f, kNear, kFar) * view;
}

}  // namespace framebuffer_ops
