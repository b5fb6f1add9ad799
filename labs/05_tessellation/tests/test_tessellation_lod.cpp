// Lab 5 `tessellation`, scene lod: the levels from the distance to the eye
// and the cracks between patches. Every expectation is computed here from
// the sheet's numbers (labs/05_tessellation/README.md, The scene lod) and the
// GL 4.3 specification's counting rules (tessellation_count.cpp), never read
// from a reference image or from the lab's own code.
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>
#include <string>

#include "tessellation_count.hpp"
#include "tessellation_test.hpp"
#include "tests/support/test_support.hpp"

using namespace tessellation_test;

namespace {

Settings lod(float detail, const char* mode, bool wireframe = false) {
    return {{"scene", "lod"},
            {"detail", text(detail)},
            {"lod", mode},
            {"wireframe", wireframe ? "true" : "false"}};
}

// Where the ray through pixel (x, y)'s centre meets the plane y = h, as (x, z).
glm::vec2 ray_at_height(int x, int y, float h) {
    const glm::mat4 view_projection = glm::perspective(glm::radians(45.0f), 1.0f, 0.1f, 100.0f) *
                                      glm::lookAt(kGroundEye, glm::vec3(0.0f), {0.0f, 1.0f, 0.0f});
    const glm::vec4 far = glm::inverse(view_projection) * glm::vec4(ndc_of(x, y), 1.0f, 1.0f);
    const glm::vec3 dir = glm::vec3(far) / far.w - kGroundEye;
    const glm::vec3 p = kGroundEye + dir * ((h - kGroundEye.y) / dir.y);
    return {p.x, p.z};
}

bool inside_ground(glm::vec2 xz, float margin) {
    return std::abs(xz.x) < 4.0f - margin && std::abs(xz.y) < 4.0f - margin;
}

// The pixels that a ground without cracks must cover: the ray meets both
// planes y = A and y = -A above the ground's square (0.05 inside it). It is
// above the surface (y <= A) where it meets y = A and below it (y >= -A) at
// y = -A, both over the ground, so it crosses the surface in between. Returns
// how many of them show the background (window depth 1).
long uncovered(const fw::RenderOutput& out, long* must_cover) {
    long missing = 0;
    *must_cover = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            if (!inside_ground(ray_at_height(x, y, kRidge), 0.05f) ||
                !inside_ground(ray_at_height(x, y, -kRidge), 0.05f))
                continue;
            ++*must_cover;
            missing += !covered(out, x, y);
        }
    return missing;
}

}  // namespace

TEST_CASE("tessellation: lod: every detail 1..100 in both modes: the sheet's levels and count") {
    Tessellation lab;
    for (const char* mode : {"edges", "centre"})
        for (int detail = 1; detail <= 100; ++detail) {
            const auto k = static_cast<float>(detail);
            const long expected = lod_primitives(k, mode == std::string("centre"), Spacing::Equal);
            const fw::RenderOutput out = lab.render(lod(k, mode), 16);
            const long observed = out.stats["primitives_generated"].get<long>();
            INFO(mode << " detail " << detail << ": expected " << expected << " observed "
                      << observed);
            CHECK(observed == expected);
            CHECK(out.stats["lab_stats"]["patches"] == 16);
        }
}

TEST_CASE("tessellation: lod: the fractional spacings round the same levels up") {
    Tessellation lab;
    for (const auto& [spacing, rule] : kSpacings)
        for (float detail : {5.0f, 11.0f, 24.0f, 30.0f, 45.0f, 100.0f})
            for (const char* mode : {"edges", "centre"}) {
                Settings s = lod(detail, mode);
                s.push_back({"spacing", spacing});
                const long expected = lod_primitives(detail, mode == std::string("centre"), rule);
                const long observed = lab.render(s, 16).stats["primitives_generated"].get<long>();
                INFO(spacing << " " << mode << " detail " << detail << ": expected " << expected
                             << " observed " << observed);
                CHECK(observed == expected);
            }
}

TEST_CASE("tessellation: lod: levels from the edges' midpoints leave no crack, from the centre") {
    Tessellation lab;
    // Levels from the edges: every pixel over the ground is covered.
    for (float detail : {11.0f, 24.0f, 30.0f, 45.0f, 64.0f}) {
        CAPTURE(detail);
        long must_cover = 0;
        const long missing = uncovered(lab.render(lod(detail, "edges")), &must_cover);
        std::printf("lod edges detail %.0f: %ld of %ld pixels over the ground uncovered\n", detail,
                    missing, must_cover);
        CHECK(must_cover > 50000);
        CHECK(missing == 0);
    }
    // Levels from the centre at detail 11: the near row at level 2 has a
    // vertex in each valley of the edge z = 2, the row behind it at level 1
    // runs straight along the crests: a crack the ridges' whole height,
    // through which the background shows.
    long must_cover = 0;
    const fw::RenderOutput cracked = lab.render(lod(11.0f, "centre"));
    const long missing = uncovered(cracked, &must_cover);
    std::printf("lod centre detail 11: %ld of %ld pixels over the ground uncovered\n", missing,
                must_cover);
    CHECK(missing > 500);
    // The sheet's probe: halfway between (-1, -A, 2) and (-1, A, 2) on screen.
    CHECK(!covered(cracked, 167, 153));
    CHECK(covered(lab.render(lod(11.0f, "edges")), 167, 153));
    // At detail 30 the edge z = 0 has level 4 on its near side and 3 behind.
    CHECK(uncovered(lab.render(lod(30.0f, "centre")), &must_cover) > 0);
}

TEST_CASE("tessellation: lod: inner and outer do not change the ground") {
    Tessellation lab;
    const fw::RenderOutput a = lab.render({{"scene", "lod"}});
    const fw::RenderOutput b = lab.render({{"scene", "lod"}, {"inner", "7"}, {"outer", "9"}});
    CHECK(a.color.pixels == b.color.pixels);
    CHECK(a.color.pixels != lab.render({{"scene", "lod"}, {"detail", "30"}}).color.pixels);
}
