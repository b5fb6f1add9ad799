// Lab 12 `shadows`. Every expectation is computed here from the sheet's
// numbers (labs/12_shadows/README.md, docs/labs.md), by hand or by tracing
// rays on the CPU, never read from a reference image or from the lab's code.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "framework/checkpoints.hpp"
#include "framework/lab.hpp"
#include "framework/render.hpp"
#include "shadow_math.hpp"
#include "tests/support/test_support.hpp"

namespace {

using Lab = fw::test::LabUnderTest;
using fw::test::Settings;

constexpr float kTol = 1.5f / 255.0f;

// A ground-plane point flattened by `m` (homogeneous, divided by w).
glm::vec3 flatten(const glm::mat4& m, glm::vec3 p) {
    const glm::vec4 q = m * glm::vec4(p, 1.0f);
    return glm::vec3(q) / q.w;
}

// The signed distance inside the rectangle [x0, x1] x [z0, z1] (negative outside).
float inside(float x, float z, float x0, float x1, float z0, float z1) {
    return std::fmin(std::fmin(x - x0, x1 - x), std::fmin(z - z0, z1 - z));
}

// How many of the casters (A: y = 1, [-0.5, 0.5]^2; B: y = 2, [0, 1]^2) the
// ray from ground point (x, 0, z) towards the light meets; -1 when the ray
// passes within `margin` of a caster's edge.
int shadow_layers(float x, float z, bool point, float margin) {
    int n = 0;
    struct Caster {
        float h, x0, x1, z0, z1;
    };
    for (const Caster c : {Caster{1, -0.5f, 0.5f, -0.5f, 0.5f}, Caster{2, 0, 1, 0, 1}}) {
        // Directional (1, 1, 0): (x + h, h, z); point (2, 4, 0): g + (l - g) h / 4.
        const float px = point ? x + (2.0f - x) * c.h / 4.0f : x + c.h;
        const float pz = point ? z - z * c.h / 4.0f : z;
        const float d = inside(px, pz, c.x0, c.x1, c.z0, c.z1);
        if (std::fabs(d) < margin) return -1;
        n += d > 0.0f;
    }
    return n;
}

}  // namespace

TEST_CASE("shadows: shadow_matrix() flattens points onto the sheet's ground points") {
    // Directional (1, 1, 0): (x, y, z) -> (x - y, 0, z).
    const glm::mat4 d = shadows::shadow_matrix({1, 1, 0, 0});
    CHECK(glm::length(flatten(d, {0.5f, 1, 0.5f}) - glm::vec3(-0.5f, 0, 0.5f)) < 1e-5f);
    CHECK(glm::length(flatten(d, {1, 2, 1}) - glm::vec3(-1, 0, 1)) < 1e-5f);
    // Point (2, 4, 0): ((4x - 2y) / (4 - y), 0, 4z / (4 - y)).
    const glm::mat4 p = shadows::shadow_matrix({2, 4, 0, 1});
    CHECK(glm::length(flatten(p, {0.5f, 1, -0.5f}) - glm::vec3(0, 0, -2.0f / 3.0f)) < 1e-5f);
    CHECK(glm::length(flatten(p, {1, 2, 1}) - glm::vec3(0, 0, 2)) < 1e-5f);
    // A point on the ground stays where it is.
    CHECK(glm::length(flatten(p, {-1.25f, 0, 0.75f}) - glm::vec3(-1.25f, 0, 0.75f)) < 1e-5f);
}

TEST_CASE("shadows: fog_factor() at the sheet's depths") {
    using shadows::Fog;
    CHECK(shadows::fog_factor(Fog::Linear, 2, 1, 9, 0.25f) == doctest::Approx(0.875));
    CHECK(shadows::fog_factor(Fog::Linear, 8, 1, 9, 0.25f) == doctest::Approx(0.125));
    // 9/8 and -3/8, clamped.
    CHECK(shadows::fog_factor(Fog::Linear, 0, 1, 9, 0.25f) == doctest::Approx(1.0));
    CHECK(shadows::fog_factor(Fog::Linear, 12, 1, 9, 0.25f) == doctest::Approx(0.0));
    CHECK(shadows::fog_factor(Fog::Exp, 4, 1, 9, 0.25f) == doctest::Approx(0.367879));
    CHECK(shadows::fog_factor(Fog::Exp, 2, 1, 9, 0.5f) == doctest::Approx(0.367879));
    CHECK(shadows::fog_factor(Fog::Exp2, 6, 1, 9, 0.25f) == doctest::Approx(0.105399));
    CHECK(shadows::fog_factor(Fog::Exp2, 2, 1, 9, 0.25f) == doctest::Approx(0.778801));
    CHECK(shadows::fog_factor(Fog::None, 8, 1, 9, 0.25f) == doctest::Approx(1.0));
}

TEST_CASE("shadows: planar: every pixel's shadow layers, traced towards the light") {
    Lab lab;
    for (const bool point : {false, true})
        for (const bool stencil : {true, false}) {
            const Settings s = {{"scene", "planar"},
                                {"light", point ? "point" : "directional"},
                                {"stencil", stencil ? "true" : "false"}};
            const fw::RenderOutput out = lab.render(s);
            int checked = 0, failed = 0, doubled = 0;
            for (int y = 2; y < 512; y += 4)
                for (int x = 2; x < 512; x += 4) {
                    const float gx = (x + 0.5f) / 128.0f - 2.0f, gz = 2.0f - (y + 0.5f) / 128.0f;
                    // Skip the casters seen from above, and near their edges.
                    if (inside(gx, gz, -0.55f, 0.55f, -0.55f, 0.55f) > 0.0f ||
                        inside(gx, gz, -0.05f, 1.05f, -0.05f, 1.05f) > 0.0f)
                        continue;
                    const int n = shadow_layers(gx, gz, point, 0.03f);
                    if (n < 0) continue;
                    const float g = 0.8f * std::pow(0.5f, stencil ? std::fmin(n, 1) : n);
                    ++checked;
                    doubled += n == 2;
                    if (!fw::test::near(fw::test::rgb_at(out.color, x, y), glm::vec3(g), kTol)) {
                        if (failed++ < 5) MESSAGE("pixel (" << x << ", " << y << ") not " << g);
                    }
                }
            INFO("point " << point << ", stencil " << stencil);
            CHECK(checked > 10000);
            CHECK(doubled > 100);
            CHECK(failed == 0);
        }
}

TEST_CASE("shadows: fog: each plane is mix(fog, surface, f) of its depth") {
    Lab lab;
    const glm::vec3 fog(0.5f, 0.6f, 0.7f), surface(0.9f, 0.3f, 0.1f);
    // Linear from 3 to 7 puts the first plane before the start (f 1.25,
    // clamped to 1) and the last beyond the end (f -0.25, clamped to 0).
    struct Case {
        const char* mode;
        float start, end;
    };
    for (const Case c : {Case{"linear", 1, 9}, Case{"linear", 3, 7}, Case{"exp", 1, 9},
                         Case{"exp2", 1, 9}, Case{"none", 1, 9}}) {
        const std::string mode = c.mode;
        const fw::RenderOutput out = lab.render({{"scene", "fog"},
                                                 {"fog", mode},
                                                 {"fog_density", "0.3"},
                                                 {"fog_start", std::to_string(c.start)},
                                                 {"fog_end", std::to_string(c.end)}});
        for (int k = 0; k < 4; ++k) {
            const float d = 2.0f + 2.0f * k, m = 0.3f * d;
            const float f = mode == "linear"
                                ? std::clamp((c.end - d) / (c.end - c.start), 0.0f, 1.0f)
                            : mode == "exp"  ? std::exp(-m)
                            : mode == "exp2" ? std::exp(-m * m)
                                             : 1.0f;
            INFO(mode << " from " << c.start << " to " << c.end << ", plane at depth " << d);
            for (const int y : {100, 256, 400})
                CHECK(fw::test::probe_rgb(out.color, 64 + 128 * k, y, glm::mix(fog, surface, f),
                                          kTol));
        }
    }
}

TEST_CASE("shadows: shadowmap: acne without a bias, none with the sheet's bias") {
    Lab lab;
    const fw::RenderOutput acne = lab.render({{"scene", "shadowmap"}, {"bias", "0"}});
    const fw::RenderOutput clean = lab.render({{"scene", "shadowmap"}});
    int near_half = 0, far_half = 0;
    for (int x = 260; x < 500; ++x) {
        // The ground's light y, and where it falls in its texel row.
        const double gx = (x + 0.5) / 128.0 - 2.0, yl = -gx / std::sqrt(2.0);
        const double t = 16.0 * yl + 32.0, frac = t - std::floor(t);
        const glm::vec3 lit(0.8f), dark(0.4f);
        CHECK(fw::test::probe_rgb(clean.color, x, 128, lit, kTol));
        if (frac > 0.1 && frac < 0.4) {
            ++near_half;
            CHECK(fw::test::probe_rgb(acne.color, x, 128, lit, kTol));
        } else if (frac > 0.6 && frac < 0.9) {
            ++far_half;
            CHECK(fw::test::probe_rgb(acne.color, x, 128, dark, kTol));
        }
    }
    CHECK(near_half > 50);
    CHECK(far_half > 50);
}

TEST_CASE("shadows: checkpoints.json: its probes and stats hold for the solution") {
    Lab lab;
    fw::test::for_each_checkpoint(
        lab.lab, lab.renderer, 10,
        [&](const fw::Checkpoint& cp, const fw::ParamValues&, const fw::RenderOutput& out) {
            fw::test::check_probes_and_stats(cp.checks, out);
        });
}
