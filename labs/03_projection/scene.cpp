// Lab 3's scenes: the square they are all made of and where each scene places it.
#include "scene.hpp"

#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

#include "framework/error.hpp"

namespace projection {

namespace {

// scene=zfight: the quads' half-size, distance, tilt and gap (world units
// and degrees). rotateX(-30 deg) leans the top away from the eye.
constexpr float kZfightHalfSize = 8.0f, kZfightDistance = 20.0f;
constexpr float kZfightTiltDegrees = -30.0f, kZfightGap = 0.002f;

std::vector<Object> cards() {
    const float t = std::tan(glm::radians(30.0f));
    const float u[5] = {-0.8f, -0.4f, 0.0f, 0.4f, 0.8f};
    const float d[5] = {2.0f, 4.0f, 8.0f, 16.0f, 32.0f};
    const char* names[5] = {"red", "green", "blue", "yellow", "magenta"};
    const glm::vec3 colors[5] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {1, 0, 1}};
    std::vector<Object> out;
    for (int i = 0; i < 5; ++i) {
        // With the default camera (fov 60, so tan(fov / 2) = t), the centre
        // projects to NDC x = u_i d_i t / (d_i t) = u_i and the half-size to
        // 0.15: every card covers the same 0.3 x 0.3 of NDC, however far.
        const glm::vec3 centre(u[i] * d[i] * t, 0.0f, -d[i]);
        const float half = 0.15f * d[i] * t;
        const glm::mat4 model =
            glm::scale(glm::translate(glm::mat4(1.0f), centre), glm::vec3(half, half, 1.0f));
        out.push_back({names[i], model, colors[i]});
    }
    return out;
}

std::vector<Object> zfight_quads() {
    const glm::mat4 tilted =
        glm::rotate(glm::translate(glm::mat4(1.0f), glm::vec3(0.0f, 0.0f, -kZfightDistance)),
                    glm::radians(kZfightTiltDegrees), glm::vec3(1.0f, 0.0f, 0.0f));
    const glm::vec3 size(kZfightHalfSize, kZfightHalfSize, 1.0f);
    // The square faces +z in its own frame, so "behind along the normal" is
    // -z there, before the tilt and the move.
    const glm::mat4 behind = glm::translate(tilted, glm::vec3(0.0f, 0.0f, -kZfightGap));
    // Blue, the far quad, is drawn first: red covers it only where its depth
    // is strictly less (GL_LESS), that is where the depth buffer can still
    // tell the two apart.
    return {{"blue", glm::scale(behind, size), {0.2f, 0.2f, 0.9f}},
            {"red", glm::scale(tilted, size), {0.9f, 0.2f, 0.2f}}};
}

}  // namespace

std::vector<Vertex> unit_square() {
    return {{{-1, -1, 0}}, {{1, -1, 0}}, {{1, 1, 0}}, {{-1, -1, 0}}, {{1, 1, 0}}, {{-1, 1, 0}}};
}

std::vector<Object> scene_objects(Scene scene) {
    switch (scene) {
        case Scene::Cards:
            return cards();
        case Scene::ZFight:
            return zfight_quads();
    }
    throw fw::Error("lab projection: scene " + std::to_string(static_cast<int>(scene)) +
                    " is not a Scene");
}

}  // namespace projection
