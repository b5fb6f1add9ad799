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
#include "tessellation_test.hpp"
#include "tests/support/test_support.hpp"

using namespace tessellation_test;

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
    CHECK(p.number("detail") == 45.0f);
    CHECK(p.text("lod") == "edges");
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
                    const long expected =
                        params.text("scene") == "lod"
                            ? lod_primitives(params.number("detail"),
                                             params.text("lod") == "centre", rule)
                            : expected_primitives(params.text("scene"), params.number("inner"),
                                                  params.number("outer"), rule);
                    CHECK(check["equals"].get<long>() == expected);
                }
            }
            fw::test::check_probes_and_stats(cp.checks, out);
        });
    for (const char* scene : kScenes) CHECK(std::count(scenes.begin(), scenes.end(), scene) >= 1);
    CHECK(std::count(scenes.begin(), scenes.end(), "lod") >= 1);
}
