// Lab 5 `tessellation`, the lab of this test's folder. Every expectation is
// computed here from the sheet's numbers (labs/05_tessellation/README.md) and
// from the GL 4.3 specification's tessellation rules (tessellation_count.cpp),
// never read from a reference image or from the lab's own code.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "framework/checkpoints.hpp"
#include "framework/lab.hpp"
#include "framework/render.hpp"
#include "tessellation_count.hpp"
#include "tests/support/test_support.hpp"

using namespace tessellation_test;

namespace {

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

// The sheet's count for a scene: the sphere is 20 triangle patches.
long expected_primitives(const std::string& scene, float inner, float outer, Spacing s) {
    if (scene == "flag" || scene == "param_sphere")
        return quad_patch_triangles({inner, inner}, {outer, outer, outer, outer}, s);
    const long per_patch = triangle_patch_triangles(inner, {outer, outer, outer}, s);
    return scene == "sphere" ? 20 * per_patch : per_patch;
}

glm::vec3 rgb(const fw::Image& img, int x, int y) { return fw::test::rgb_at(img, x, y); }
using fw::test::near;

bool covered(const fw::RenderOutput& out, int x, int y) { return out.depth.at(x, y) < 1.0f; }

std::string text(float v) { return std::to_string(v); }

// Pixel centre in NDC.
glm::vec2 ndc_of(int x, int y) { return glm::vec2(x + 0.5f, y + 0.5f) / (kSize / 2.0f) - 1.0f; }

// Signed distance in pixels from the pixel centre to the line through a, b
// (NDC), positive on the left of a -> b: inside the counter-clockwise triangle.
float pixels_left_of(glm::vec2 a, glm::vec2 b, int x, int y) {
    const glm::vec2 d = glm::normalize(b - a), p = ndc_of(x, y) - a;
    return (d.x * p.y - d.y * p.x) * (kSize / 2.0f);
}

}  // namespace

TEST_CASE("tessellation: the declaration has the sheet's parameters and defaults") {
    const fw::RegisteredLab& lab = fw::test::this_lab();
    const fw::ParamValues p = fw::default_params(lab);
    CHECK(p.text("scene") == "triangle");
    CHECK(p.number("inner") == 4.0f);
    CHECK(p.number("outer") == 4.0f);
    CHECK(p.text("spacing") == "equal");
    CHECK(p.flag("wireframe"));
    CHECK(p.number("D") == doctest::Approx(0.15));
    CHECK(p.number("K") == 2.0f);
    CHECK(p.number("phase") == 0.0f);
    CHECK(!p.flag("animate"));
    for (const fw::Param& param : lab.info.params) {
        INFO("parameter " << param.name);
        CHECK(!param.help_text.empty());
        CHECK(param.shortcut != 0);
        if (param.name == "inner" || param.name == "outer") {
            CHECK(param.type == fw::ParamType::Float);
            CHECK(param.min == 1.0);
            CHECK(param.max == 64.0);
        }
    }
}

TEST_CASE("tessellation: equal spacing, inner = outer = 1..64: the spec's count in every scene") {
    Tessellation lab;
    for (const std::string scene : kScenes)
        for (int n = 1; n <= kMaxLevel; ++n) {
            const auto level = static_cast<float>(n);
            const long expected = expected_primitives(scene, level, level, Spacing::Equal);
            const long observed = lab.primitives(scene, level, level, "equal");
            INFO(scene << " level " << n << ": expected " << expected << " observed " << observed);
            CHECK(observed == expected);
        }
}

TEST_CASE("tessellation: mixed inner and outer levels, equal spacing") {
    Tessellation lab;
    const float levels[] = {1, 2, 3, 4, 5, 7, 16, 33, 64};
    for (const char* scene : {"triangle", "flag"})
        for (float inner : levels)
            for (float outer : levels) {
                const long expected = expected_primitives(scene, inner, outer, Spacing::Equal);
                const long observed = lab.primitives(scene, inner, outer, "equal");
                INFO(scene << " inner " << inner << " outer " << outer << ": expected " << expected
                           << " observed " << observed);
                CHECK(observed == expected);
            }
}

TEST_CASE("tessellation: fractional levels with every spacing: the spec's rounding") {
    Tessellation lab;
    const float levels[] = {1.0f, 1.5f, 2.0f, 2.5f, 3.0f, 3.3f, 4.0f, 7.9f, 12.1f, 63.5f, 64.0f};
    for (const auto& [spacing, rule] : kSpacings)
        for (const char* scene : kScenes)
            for (float inner : levels)
                for (float outer : {inner, 1.0f, 3.3f}) {
                    const long expected = expected_primitives(scene, inner, outer, rule);
                    const long observed = lab.primitives(scene, inner, outer, spacing);
                    INFO(scene << " " << spacing << " inner " << inner << " outer " << outer
                               << ": expected " << expected << " observed " << observed);
                    CHECK(observed == expected);
                }
}

TEST_CASE("tessellation: a fractional level moves vertices without adding triangles") {
    Tessellation lab;
    // 2.5 and 3.5 both round up to 4 segments with fractional_even, but the
    // two short segments grow with the level: same count, another picture.
    const Settings even = {{"spacing", "fractional_even"}};
    auto with = [&](Settings s, float level) {
        s.insert(s.end(), {{"inner", text(level)}, {"outer", text(level)}});
        return lab.render(s);
    };
    const fw::RenderOutput a = with(even, 2.5f), b = with(even, 3.5f);
    CHECK(a.stats["primitives_generated"] == b.stats["primitives_generated"]);
    CHECK(a.color.pixels != b.color.pixels);
    // With equal spacing 3.2 and 4 are the same 4 segments: the same picture.
    const fw::RenderOutput c = with({}, 3.2f), d = with({}, 4.0f);
    CHECK(c.color.pixels == d.color.pixels);
}

TEST_CASE("tessellation: triangle: fill and white edges inside the patch, black outside") {
    Tessellation lab;
    const glm::vec2 corners[] = {{-0.9f, -0.8f}, {0.9f, -0.8f}, {0.0f, 0.9f}};
    // The centroid (0, -0.7 / 3) lies in pixel (256, 196). An even inner
    // level puts a vertex there (the innermost ring is a point), where edges
    // meet; an odd one leaves the innermost triangle, 1/n of the patch's size
    // around it, filled. Inner 1 with outer 4 counts as 1 + epsilon, 2.
    for (int inner = 1; inner <= 9; ++inner) {
        CAPTURE(inner);
        const fw::RenderOutput out = lab.render({{"inner", std::to_string(inner)}});
        const bool vertex = inner == 1 || inner % 2 == 0;
        CHECK(fw::test::probe_rgb(out.color, 256, 196, vertex ? kWhite : kFill));
    }
    // All levels 1: the patch alone, filled at its centroid.
    const fw::RenderOutput whole = lab.render({{"inner", "1"}, {"outer", "1"}});
    CHECK(fw::test::probe_rgb(whole.color, 256, 196, kFill));
    for (bool wireframe : {true, false})
        for (int level : {1, 4, 13}) {
            CAPTURE(wireframe);
            CAPTURE(level);
            const fw::RenderOutput out = lab.render({{"inner", std::to_string(level)},
                                                     {"outer", std::to_string(level)},
                                                     {"wireframe", wireframe ? "true" : "false"}});
            long wrong = 0, white = 0, inside = 0;
            for (int y = 0; y < kSize; ++y)
                for (int x = 0; x < kSize; ++x) {
                    float d = 1e9f;  // pixels inside the nearest edge
                    for (int i = 0; i < 3; ++i)
                        d = std::min(d, pixels_left_of(corners[i], corners[(i + 1) % 3], x, y));
                    if (std::abs(d) < 0.05f) continue;  // the rasterizer's rounding decides
                    const glm::vec3 c = rgb(out.color, x, y);
                    if (d < 0.0f) {
                        wrong += !near(c, kBlack, 0.0f);
                        continue;
                    }
                    ++inside;
                    const bool is_white = near(c, kWhite, 0.0f);
                    white += is_white;
                    // Within 1 px of the patch's border: an edge of the outer ring.
                    if (wireframe && d < 0.95f)
                        wrong += !is_white;
                    else if (!wireframe)
                        wrong += !near(c, kFill, 1.0f / 255.0f);
                    else
                        wrong += !is_white && !near(c, kFill, 1.0f / 255.0f);
                }
            INFO("pixels wrong: " << wrong << ", white " << white << " of " << inside);
            CHECK(wrong == 0);
            if (wireframe) CHECK(white > inside / 100);
        }
}

TEST_CASE("tessellation: sphere: the silhouette fills the disc as the levels grow") {
    Tessellation lab;
    double last = 0.0;
    for (int level : {1, 2, 4, 8, 16}) {
        const fw::RenderOutput out = lab.render({{"scene", "sphere"},
                                                 {"inner", std::to_string(level)},
                                                 {"outer", std::to_string(level)}});
        long disc = 0, hit = 0, outside = 0;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                const float r = glm::length(glm::vec2(x + 0.5f, y + 0.5f) - glm::vec2(256.0f));
                if (r <= kSilhouette) {
                    ++disc;
                    hit += covered(out, x, y);
                } else if (r > kSilhouette + 1.0f) {
                    outside += covered(out, x, y);
                }
            }
        const double fraction = double(hit) / double(disc);
        std::printf("sphere level %d: %.4f of the disc's %ld pixels covered\n", level, fraction,
                    disc);
        INFO("level " << level << ": covered " << fraction << ", previous " << last);
        // Every generated vertex lies on the sphere: nothing outside the disc.
        CHECK(outside == 0);
        CHECK(fraction >= last);
        if (level == 1) CHECK(fraction < 0.95);
        if (level == 16) CHECK(fraction >= 0.99);
        last = fraction;
    }
}

namespace {

// The flag as README.md defines it: r(u, v) = (u W, v H, sin(K pi u + phase) D),
// W = 2, H = 1.2, seen through lookAt((-0.2, 1.3, 2.6), (1, 0.6, 0), (0, 1, 0))
// and perspective(45 deg, 1, 0.1, 100).
struct Flag {
    float D = 0.15f, K = 2.0f, phase_degrees = 0.0f;
    static constexpr float W = 2.0f, H = 1.2f;

    float z_at(float u) const { return std::sin(K * kPi * u + glm::radians(phase_degrees)) * D; }
    glm::vec3 normal_at(float u) const {
        const float a = K * kPi * u + glm::radians(phase_degrees);
        return glm::normalize(
            glm::cross(glm::vec3(W, 0.0f, K * kPi * D * std::cos(a)), glm::vec3(0.0f, H, 0.0f)));
    }
    // Where the ray through pixel (x, y)'s centre first meets the flag, as
    // (u, v); nullopt if it misses. The flag is a height field over the
    // plane z = 0, so march along the ray until z - z_at(u) changes sign.
    std::optional<glm::vec2> hit(int x, int y) const {
        const glm::mat4 view_projection =
            glm::perspective(glm::radians(45.0f), 1.0f, 0.1f, 100.0f) *
            glm::lookAt(glm::vec3(-0.2f, 1.3f, 2.6f), glm::vec3(1.0f, 0.6f, 0.0f),
                        glm::vec3(0.0f, 1.0f, 0.0f));
        const glm::mat4 inverse = glm::inverse(view_projection);
        const glm::vec2 ndc = ndc_of(x, y);
        const glm::vec4 a = inverse * glm::vec4(ndc, -1.0f, 1.0f);
        const glm::vec4 b = inverse * glm::vec4(ndc, 1.0f, 1.0f);
        const glm::vec3 origin = glm::vec3(a) / a.w;
        const glm::vec3 dir = glm::normalize(glm::vec3(b) / b.w - origin);
        auto g = [&](float t) {
            const glm::vec3 p = origin + t * dir;
            return p.z - z_at(p.x / W);
        };
        // Only the slab |z| <= D can hold the surface; the ray runs towards -z.
        const float enter = (D - origin.z) / dir.z, leave = (-D - origin.z) / dir.z;
        constexpr float kStep = 1e-3f;
        for (float t = enter - kStep; t < leave + kStep; t += kStep) {
            // A root in [t, t + kStep]: the ray passes through the surface,
            // from the front or (beside the flag, or from behind) the back.
            const bool above = g(t) > 0.0f;
            if (above == (g(t + kStep) > 0.0f)) continue;
            float lo = t, hi = t + kStep;
            for (int i = 0; i < 30; ++i) {
                const float mid = 0.5f * (lo + hi);
                ((g(mid) > 0.0f) == above ? lo : hi) = mid;
            }
            const glm::vec3 p = origin + hi * dir;
            const glm::vec2 uv(p.x / W, p.y / H);
            if (uv.x >= 0.0f && uv.x <= 1.0f && uv.y >= 0.0f && uv.y <= 1.0f) return uv;
            // The ray crossed the wave's extension beside the flag: go on.
        }
        return std::nullopt;
    }
};

}  // namespace

TEST_CASE("tessellation: flag: normals from the partial derivatives, pixel by pixel") {
    Tessellation lab;
    struct Case {
        Flag flag;
        const char* D;
        const char* K;
        const char* phase;
    };
    const Case cases[] = {{{0.15f, 2.0f, 0.0f}, "0.15", "2", "0"},
                          {{0.3f, 3.0f, 90.0f}, "0.3", "3", "90"}};
    for (const Case& c : cases) {
        CAPTURE(c.K);
        const fw::RenderOutput out = lab.render({{"scene", "flag"},
                                                 {"show", "normals"},
                                                 {"wireframe", "false"},
                                                 {"inner", "64"},
                                                 {"outer", "64"},
                                                 {"D", c.D},
                                                 {"K", c.K},
                                                 {"phase", c.phase}});
        std::vector<std::optional<glm::vec2>> hits;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) hits.push_back(c.flag.hit(x, y));
        auto hit = [&](int x, int y) { return hits[static_cast<std::size_t>(y * kSize + x)]; };
        long compared = 0, bad = 0, coverage_wrong = 0;
        for (int y = 1; y < kSize - 1; ++y)
            for (int x = 1; x < kSize - 1; ++x) {
                const std::optional<glm::vec2> uv = hit(x, y);
                const bool inside = uv && glm::all(glm::greaterThan(*uv, glm::vec2(0.01f))) &&
                                    glm::all(glm::lessThan(*uv, glm::vec2(0.99f)));
                // Covered although neither this pixel nor a neighbour sees the flag.
                if (!uv)
                    coverage_wrong += covered(out, x, y) && !hit(x + 1, y) && !hit(x - 1, y) &&
                                      !hit(x, y + 1) && !hit(x, y - 1);
                if (!inside) continue;
                coverage_wrong += !covered(out, x, y);
                ++compared;
                const glm::vec3 expected = 0.5f * c.flag.normal_at(uv->x) + 0.5f;
                const glm::vec3 observed = rgb(out.color, x, y);
                if (near(observed, expected, 3.0f / 255.0f)) continue;
                if (++bad <= 5)
                    MESSAGE("pixel (" << x << ", " << y << ") u " << uv->x << ": expected ("
                                      << expected.x << ", " << expected.y << ", " << expected.z
                                      << ") observed (" << observed.x << ", " << observed.y << ", "
                                      << observed.z << ")");
            }
        INFO(compared << " pixels compared, " << bad << " differ, " << coverage_wrong
                      << " covered where the flag is not or the reverse");
        CHECK(compared > 20000);
        CHECK(bad == 0);
        CHECK(coverage_wrong == 0);
    }
}

TEST_CASE("tessellation: lit spheres: Lambert as lab 4 where the ray meets the unit sphere") {
    Tessellation lab;
    // The ray through a pixel centre meets the unit sphere at the normal N;
    // the colour is 0.8 max(N . L, 0). Fine levels shade within 0.02 of it.
    const glm::mat4 inverse =
        glm::inverse(glm::perspective(glm::radians(45.0f), 1.0f, 0.1f, 100.0f) *
                     glm::lookAt(glm::vec3(0, 0, 4), glm::vec3(0.0f), glm::vec3(0, 1, 0)));
    auto expected = [&](int x, int y) {
        const glm::vec4 far = inverse * glm::vec4(ndc_of(x, y), 1.0f, 1.0f);
        const glm::vec3 eye(0, 0, 4), d = glm::normalize(glm::vec3(far) / far.w - eye);
        const float b = glm::dot(eye, d), c = glm::dot(eye, eye) - 1.0f;
        const glm::vec3 n = eye + (-b - std::sqrt(b * b - c)) * d;
        return glm::vec3(0.8f * std::max(glm::dot(n, kLight), 0.0f));
    };
    for (const std::string scene : {"sphere", "param_sphere"}) {
        CAPTURE(scene);
        const fw::RenderOutput out = lab.render(
            {{"scene", scene}, {"inner", "32"}, {"outer", "32"}, {"wireframe", "false"}});
        for (const glm::ivec2 at :
             {glm::ivec2(256, 256), glm::ivec2(340, 340), glm::ivec2(200, 300),
              glm::ivec2(300, 180), glm::ivec2(160, 170)})
            CHECK(fw::test::probe_rgb(out.color, at.x, at.y, expected(at.x, at.y), 0.02f));
        CHECK(fw::test::probe_rgb(out.color, 20, 20, kBlack));
    }
}

TEST_CASE("tessellation: offscreen frames do not depend on animate (time is 0)") {
    Tessellation lab;
    const Settings flag = {{"scene", "flag"}, {"phase", "45"}};
    Settings animated = flag;
    animated.push_back({"animate", "true"});
    CHECK(lab.render(flag).color.pixels == lab.render(animated).color.pixels);
    CHECK(lab.render(flag).color.pixels != lab.render({{"scene", "flag"}}).color.pixels);
}

TEST_CASE("tessellation: checkpoints.json: its probes and stats hold for the solution") {
    Tessellation lab;
    std::vector<std::string> scenes;
    fw::test::for_each_checkpoint(
        lab.lab, lab.renderer, 5,
        [&](const fw::Checkpoint& cp, const fw::ParamValues& params, const fw::RenderOutput& out) {
            scenes.push_back(params.text("scene"));
            for (const nlohmann::json& check : cp.checks) {
                CAPTURE(check.dump());
                if (check["kind"] == "stat") {
                    // Every stat check is primitives_generated, recomputed here
                    // from the checkpoint's parameters by the spec's rules.
                    CHECK(check["stat"] == "primitives_generated");
                    Spacing rule = Spacing::Equal;
                    for (const auto& [name, r] : kSpacings)
                        if (params.text("spacing") == name) rule = r;
                    CHECK(check["equals"].get<long>() ==
                          expected_primitives(params.text("scene"), params.number("inner"),
                                              params.number("outer"), rule));
                }
            }
            fw::test::check_probes_and_stats(cp.checks, out);
        });
    for (const char* scene : kScenes) CHECK(std::count(scenes.begin(), scenes.end(), scene) >= 1);
}
