// Lab 13's figures for scene raycast (compare.hpp).
#include "compare.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>

namespace surface_detail {

namespace {

// The surface of triangle k (-1: none): the first triangle of its plane and colour.
int surface(const std::vector<Triangle>& scene, int k) {
    if (k < 0 || k >= static_cast<int>(scene.size())) return -1;
    const Triangle& t = scene[static_cast<size_t>(k)];
    for (int s = 0;; ++s) {
        const Triangle& o = scene[static_cast<size_t>(s)];
        if (o.color == t.color && glm::length(o.normal() - t.normal()) < 1e-5f &&
            std::abs(glm::dot(o.normal(), o.a - t.a)) < 1e-5f)
            return s;
    }
}

}  // namespace

nlohmann::json compare_stats(const CastImage& cast, const fw::Image& gl, const fw::Image& ids,
                             const std::vector<Triangle>& scene, int lights) {
    const int triangles = static_cast<int>(scene.size());
    int hits = 0, differ = 0, shadowed = 0, color_differ = 0, unshadowed = 0;
    for (size_t k = 0; k < cast.triangle.size(); ++k) {
        hits += cast.triangle[k] >= 0 ? 1 : 0;
        differ += surface(scene, cast.triangle[k]) != surface(scene, ids.pixels[k].r - 1) ? 1 : 0;
        shadowed += cast.shadowed[k] ? 1 : 0;
        const fw::Rgba8 a = cast.color.pixels[k], b = gl.pixels[k];
        const int d = std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
        if (d <= 2) continue;
        ++color_differ;
        unshadowed += cast.shadowed[k] ? 0 : 1;
    }
    const Counts& c = cast.counts;
    return {
        {"rays", {{"primary", c.primary}, {"shadow", c.shadow}, {"total", c.primary + c.shadow}}},
        {"intersection_tests", c.tests},
        {"triangles", triangles},
        {"lights", lights},
        {"hits", hits},
        {"differ", differ},
        {"shadowed", shadowed},
        {"color_differ", color_differ},
        {"color_differ_unshadowed", unshadowed}};
}

}  // namespace surface_detail
