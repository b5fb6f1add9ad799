// Lab 13's ray-cast picture (raycast_image.hpp).
#include "raycast_image.hpp"

#include <algorithm>
#include <cmath>

#include "scenes.hpp"

namespace surface_detail {

float test_triangle(const Ray& ray, const Triangle& tri, Counts& counts) {
    ++counts.tests;
    return intersect_triangle(ray.origin, ray.dir, tri.a, tri.b, tri.c);
}

glm::vec3 shade(glm::vec3 albedo, glm::vec3 n, int lights, const bool* visible) {
    float light = 0.2f;
    for (int k = 0; k < lights; ++k)
        if (visible[k]) light += 0.5f * std::max(glm::dot(n, kRayLights[k]), 0.0f);
    return glm::clamp(albedo * light, 0.0f, 1.0f);
}

CastImage cast_scene(const std::vector<Triangle>& scene, int lights) {
    CastImage out;
    out.triangle.assign(kCast * kCast, -1);
    out.shadowed.assign(kCast * kCast, false);
    for (int j = 0; j < kCast; ++j)
        for (int i = 0; i < kCast; ++i) {
            const Ray ray{kEye, pixel_direction(i, j)};
            ++out.counts.primary;
            const Hit hit = nearest_hit(ray, scene, out.counts);
            const size_t at = static_cast<size_t>(j * kCast + i);
            out.triangle[at] = hit.index;
            if (hit.index < 0 || hit.index >= static_cast<int>(scene.size())) {
                out.color.at(i, j) = {0, 0, 0, 255};
                continue;
            }
            const Triangle& tri = scene[static_cast<size_t>(hit.index)];
            const glm::vec3 p = ray.origin + hit.t * ray.dir, n = tri.normal();
            bool visible[2] = {true, true};
            for (int k = 0; k < lights; ++k) {
                visible[k] = !in_shadow(p, n, kRayLights[k], scene, out.counts);
                if (!visible[k]) out.shadowed[at] = true;
            }
            const glm::vec3 c = shade(tri.color, n, lights, visible);
            const auto byte = [](float v) {
                return static_cast<std::uint8_t>(std::floor(v * 255.0f + 0.5f));
            };
            out.color.at(i, j) = {byte(c.r), byte(c.g), byte(c.b), 255};
        }
    return out;
}

}  // namespace surface_detail
