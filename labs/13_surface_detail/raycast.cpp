// Lab 13's ray caster, the student parts (raycast.hpp says what each returns).
#include "raycast.hpp"

#include <cmath>

namespace surface_detail {

glm::vec3 pixel_direction(int i, int j) {
    glm::vec3 d = -kCamW;
    // BEGIN SOLUTION
    // STUDENT: (void)i, (void)j;  // TODO: NDC x and y of the pixel's centre, then
    // STUDENT: // d = x tan(fov/2) u + y tan(fov/2) v - w, normalised (raycast.hpp)
    const float x = 2.0f * (static_cast<float>(i) + 0.5f) / kCast - 1.0f;
    const float y = 2.0f * (static_cast<float>(j) + 0.5f) / kCast - 1.0f;
    d = glm::normalize(x * kTanHalfFov * kCamU + y * kTanHalfFov * kCamV - kCamW);
    // END SOLUTION
    return d;
}

float intersect_triangle(glm::vec3 o, glm::vec3 d, glm::vec3 a, glm::vec3 b, glm::vec3 c) {
    // BEGIN SOLUTION
    // STUDENT: (void)o, (void)d, (void)a, (void)b, (void)c;
    // STUDENT: // TODO: Moller-Trumbore: barycentric u, v and t; -1 for a miss
    // STUDENT: return -1.0f;
    const glm::vec3 e1 = b - a, e2 = c - a;
    const glm::vec3 p = glm::cross(d, e2);
    const float det = glm::dot(e1, p);
    if (det == 0.0f) return -1.0f;
    const glm::vec3 s = o - a;
    const float u = glm::dot(s, p) / det;
    if (u < 0.0f || u > 1.0f) return -1.0f;
    const glm::vec3 q = glm::cross(s, e1);
    const float v = glm::dot(d, q) / det;
    if (v < 0.0f || u + v > 1.0f) return -1.0f;
    const float t = glm::dot(e2, q) / det;
    return t > 0.0f ? t : -1.0f;
    // END SOLUTION
}

Hit nearest_hit(const Ray& ray, const std::vector<Triangle>& scene, Counts& counts) {
    Hit nearest;
    for (int k = 0; k < static_cast<int>(scene.size()); ++k) {
        const float t = test_triangle(ray, scene[static_cast<size_t>(k)], counts);
        // BEGIN SOLUTION
        // STUDENT: (void)t;  // TODO: keep the hit with the smallest t > 0 (t is -1 for a miss)
        if (t > 0.0f && (nearest.index < 0 || t < nearest.t)) nearest = {k, t};
        // END SOLUTION
    }
    return nearest;
}

bool in_shadow(glm::vec3 p, glm::vec3 n, glm::vec3 towards, const std::vector<Triangle>& scene,
               Counts& counts) {
    ++counts.shadow;
    // BEGIN SOLUTION
    // STUDENT: (void)p, (void)n, (void)towards, (void)scene;
    // STUDENT: // TODO: a ray from p + kShadowEpsilon n towards the light; shadowed when
    // STUDENT: // nearest_hit() finds a triangle
    // STUDENT: return false;
    const Ray shadow{p + kShadowEpsilon * n, towards};
    return nearest_hit(shadow, scene, counts).index >= 0;
    // END SOLUTION
}

}  // namespace surface_detail
