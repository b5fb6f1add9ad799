// Lab 5 `tessellation`, shared by its test files: the lab renderer, the
// sheet's numbers (labs/05_tessellation/README.md) and pixel helpers, written
// here again so that the tests never read them from the lab's code.
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <string>
#include <utility>

#include "framework/render.hpp"
#include "tessellation_count.hpp"
#include "tests/support/test_support.hpp"

namespace tessellation_test {

using fw::test::Settings;

constexpr int kSize = 512;
const glm::vec3 kBlack{0.0f}, kWhite{1.0f}, kFill{0.2f, 0.3f, 0.8f};
const glm::vec3 kLight = glm::normalize(glm::vec3(1.0f, 1.0f, 1.0f));
constexpr float kPi = 3.14159265358979f;
// perspective(45 deg): a sphere of radius 1 seen from distance 4 has the
// silhouette radius f / sqrt(4^2 - 1) in NDC, f = 1 / tan(22.5 deg).
const float kSilhouette = 1.0f / std::tan(glm::radians(22.5f)) / std::sqrt(15.0f) * kSize / 2;

const char* const kScenes[] = {"triangle", "sphere", "flag", "param_sphere"};
const std::pair<const char*, Spacing> kSpacings[] = {{"equal", Spacing::Equal},
                                                     {"fractional_even", Spacing::FractionalEven},
                                                     {"fractional_odd", Spacing::FractionalOdd}};

// The lab of this folder, created once per test case.
struct Tessellation : fw::test::LabUnderTest {
    // Square frames of `size`.
    fw::RenderOutput render(const Settings& settings, int size = kSize) {
        return LabUnderTest::render(settings, size, size);
    }
    long primitives(const std::string& scene, float inner, float outer, const char* spacing) {
        const fw::RenderOutput out = render({{"scene", scene},
                                             {"inner", std::to_string(inner)},
                                             {"outer", std::to_string(outer)},
                                             {"spacing", spacing}},
                                            16);
        return out.stats["primitives_generated"].get<long>();
    }
};

// Scene lod as README.md defines it: 4 x 4 patches of 2 x 2 over x, z in
// [-4, 4], the eye at (0, 5, 7), ridges y = A cos(pi x) with A = 0.25, and
// the level clamp(round(k / d), 1, 64) of a point at distance d from the eye.
const glm::vec3 kGroundEye{0.0f, 5.0f, 7.0f};
constexpr float kRidge = 0.25f;
inline float lod_level(float detail, glm::vec3 p) {
    return std::clamp(std::round(detail / glm::distance(p, kGroundEye)), 1.0f, 64.0f);
}
// The triangles of all 16 patches: the outer levels from the edges'
// midpoints (u = 0, v = 0, u = 1, v = 1 with u along +x, v along -z), or with
// from_centre every level from the patch's centre; the inner ones from it.
inline long lod_primitives(float detail, bool from_centre, Spacing spacing) {
    long triangles = 0;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) {
            const float x0 = -4.0f + 2.0f * i, z0 = -4.0f + 2.0f * j;
            const float x1 = x0 + 2.0f, z1 = z0 + 2.0f, xc = x0 + 1.0f, zc = z0 + 1.0f;
            const float inner = lod_level(detail, {xc, 0.0f, zc});
            std::array<float, 4> outer = {
                lod_level(detail, {x0, 0.0f, zc}), lod_level(detail, {xc, 0.0f, z1}),
                lod_level(detail, {x1, 0.0f, zc}), lod_level(detail, {xc, 0.0f, z0})};
            if (from_centre) outer.fill(inner);
            triangles += quad_patch_triangles({inner, inner}, outer, spacing);
        }
    return triangles;
}

// The sheet's count for a scene: the sphere is 20 triangle patches.
inline long expected_primitives(const std::string& scene, float inner, float outer, Spacing s) {
    if (scene == "flag" || scene == "param_sphere")
        return quad_patch_triangles({inner, inner}, {outer, outer, outer, outer}, s);
    const long per_patch = triangle_patch_triangles(inner, {outer, outer, outer}, s);
    return scene == "sphere" ? 20 * per_patch : per_patch;
}

inline glm::vec3 rgb(const fw::Image& img, int x, int y) { return fw::test::rgb_at(img, x, y); }
using fw::test::near;

inline bool covered(const fw::RenderOutput& out, int x, int y) { return out.depth.at(x, y) < 1.0f; }

inline std::string text(float v) { return std::to_string(v); }

// Pixel centre in NDC.
inline glm::vec2 ndc_of(int x, int y) {
    return glm::vec2(x + 0.5f, y + 0.5f) / (kSize / 2.0f) - 1.0f;
}

// Signed distance in pixels from the pixel centre to the line through a, b
// (NDC), positive on the left of a -> b: inside the counter-clockwise triangle.
inline float pixels_left_of(glm::vec2 a, glm::vec2 b, int x, int y) {
    const glm::vec2 d = glm::normalize(b - a), p = ndc_of(x, y) - a;
    return (d.x * p.y - d.y * p.x) * (kSize / 2.0f);
}

}  // namespace tessellation_test
