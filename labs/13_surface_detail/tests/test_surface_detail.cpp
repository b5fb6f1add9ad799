// Lab 13 `surface-detail`. Every expectation is computed here from the
// sheet's numbers (labs/13_surface_detail/README.md, docs/labs.md): the
// normals from the height map's formula, the sphere's colours by GL's cube
// map rule (the GL specification, 4.3 core, table 8.19), the ray counts by
// the deck's cost formula; never read from a reference image or the lab.
#include <array>
#include <chrono>
#include <cmath>
#include <string>

#include "framework/checkpoints.hpp"
#include "framework/lab.hpp"
#include "framework/render.hpp"
#include "raycast.hpp"
#include "surface_math.hpp"
#include "tests/support/test_support.hpp"

namespace {

using Lab = fw::test::LabUnderTest;
constexpr float kTol = 1.5f / 255.0f;

// The colour of a white surface lit 0.1 + 0.9 max(n . l, 0).
float lambert(glm::vec3 n, glm::vec3 l) { return 0.1f + 0.9f * std::fmax(glm::dot(n, l), 0.0f); }

// Inside a dome (away from its rim): n = normalize(s x / 18, s y / 18, 1),
// (x, y) the texel centre's offset from the cell's centre.
glm::vec3 dome_normal(int i, int j, float s) {
    const float x = static_cast<float>(i % 16) - 7.5f, y = static_cast<float>(j % 16) - 7.5f;
    return glm::normalize(glm::vec3(s * x / 18.0f, s * y / 18.0f, 1.0f));
}

// GL's cube-map rule (4.3 core, table 8.19): the face, and s, t on it.
struct FaceCoord {
    int face;
    float s, t, margin;  // margin: how far from a face's or a texel's edge
};
FaceCoord cube_coord(glm::vec3 r) {
    const glm::vec3 a = glm::abs(r);
    int face = 0;
    float sc = 0, tc = 0, ma = 0, second = 0;
    if (a.x >= a.y && a.x >= a.z) {
        face = r.x > 0 ? 0 : 1, ma = a.x, sc = r.x > 0 ? -r.z : r.z, tc = -r.y;
        second = std::fmax(a.y, a.z);
    } else if (a.y >= a.z) {
        face = r.y > 0 ? 2 : 3, ma = a.y, sc = r.x, tc = r.y > 0 ? r.z : -r.z;
        second = std::fmax(a.x, a.z);
    } else {
        face = r.z > 0 ? 4 : 5, ma = a.z, sc = r.z > 0 ? r.x : -r.x, tc = -r.y;
        second = std::fmax(a.x, a.y);
    }
    const float s = (sc / ma + 1) / 2, t = (tc / ma + 1) / 2;
    const float margin =
        std::fmin((ma - second) / ma, std::fmin(std::fabs(s - 0.5f), std::fabs(t - 0.5f)));
    return {face, s, t, margin};
}

// The sheet's faces: +x red, -x cyan, +y green, -y magenta, +z blue, -z
// yellow, texel (0, 0) (s < 0.5, t < 0.5) white.
glm::vec3 environment(glm::vec3 r) {
    const glm::vec3 colors[6] = {{1, 0, 0}, {0, 1, 1}, {0, 1, 0}, {1, 0, 1}, {0, 0, 1}, {1, 1, 0}};
    const FaceCoord f = cube_coord(r);
    return f.s < 0.5f && f.t < 0.5f ? glm::vec3(1.0f) : colors[f.face];
}

}  // namespace

TEST_CASE("surface-detail: normal_map() and tangent_frame() at the sheet's numbers") {
    using namespace surface_detail;
    HeightMap map{64, std::vector<float>(64 * 64)};
    for (int j = 0; j < 64; ++j)
        for (int i = 0; i < 64; ++i) {
            const float x = i % 16 - 7.5f, y = j % 16 - 7.5f;
            map.h[static_cast<size_t>(j * 64 + i)] =
                std::fmax(0.0f, 1.0f - (x * x + y * y) / 36.0f);
        }
    const std::vector<glm::vec3> n = normal_map(map, 4.0f);
    for (const glm::ivec2 t : {glm::ivec2(5, 6), glm::ivec2(10, 9), glm::ivec2(40, 24)})
        CHECK(glm::length(n[static_cast<size_t>(t.y * 64 + t.x)] - dome_normal(t.x, t.y, 4)) <
              1e-5f);
    // Between the domes the map is flat.
    CHECK(glm::length(n[0] - glm::vec3(0, 0, 1)) < 1e-6f);
    // Square B: u along +y, v along -x.
    const glm::mat3 b = tangent_frame({0.5f, -1.5f, 0}, {3.5f, -1.5f, 0}, {3.5f, 1.5f, 0}, {0, 1},
                                      {0, 0}, {1, 0}, {0, 0, 1});
    CHECK(glm::length(b[0] - glm::vec3(0, 1, 0)) < 1e-5f);
    CHECK(glm::length(b[1] - glm::vec3(-1, 0, 0)) < 1e-5f);
    // A normal not perpendicular to the triangle: T and B come out perpendicular to it.
    const glm::vec3 tilted = glm::normalize(glm::vec3(0.3f, 0.0f, 1.0f));
    const glm::mat3 g =
        tangent_frame({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0}, {1, 0}, {0, 1}, tilted);
    CHECK(std::fabs(glm::dot(g[0], tilted)) < 1e-5f);
    CHECK(std::fabs(glm::dot(g[1], tilted)) < 1e-5f);
    CHECK(std::fabs(glm::dot(g[0], g[1])) < 1e-5f);
}

TEST_CASE("surface-detail: the ray caster's rays and tests") {
    using namespace surface_detail;
    // The pixels either side of the image's centre are mirror images.
    const glm::vec3 a = pixel_direction(31, 31), b = pixel_direction(32, 32);
    CHECK(std::fabs(a.x + b.x) < 1e-6f);
    CHECK(glm::length(pixel_direction(0, 0)) == doctest::Approx(1.0f));
    // The centre ray lies between them, along -w: its x is half a pixel's.
    CHECK(a.x < 0.0f);
    const glm::vec3 o(0.2f, 0.2f, 1.0f), down(0, 0, -1);
    CHECK(intersect_triangle(o, down, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}) == doctest::Approx(1.0f));
    CHECK(intersect_triangle(o, -down, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}) == -1.0f);
    CHECK(intersect_triangle({0.8f, 0.8f, 1}, down, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}) == -1.0f);
}

TEST_CASE("surface-detail: bump: both squares show the same domes, lit from the same side") {
    Lab lab;
    const fw::RenderOutput out = lab.render({{"scene", "bump"}});
    const fw::RenderOutput flat = lab.render({{"scene", "bump"}, {"normals", "interpolated"}});
    const glm::vec3 light(-0.48f, 0.6f, 0.64f);
    int checked = 0;
    for (int j = 0; j < 64; ++j)
        for (int i = 0; i < 64; ++i) {
            const float x = i % 16 - 7.5f, y = j % 16 - 7.5f;
            // Texels whose neighbours are all in the dome, or all outside it.
            const float d = std::sqrt(x * x + y * y);
            const bool in = d + 1.0f < 6.0f, out_of = d - 1.5f > 6.0f;
            if (!in && !out_of) continue;
            const glm::vec3 n = in ? dome_normal(i, j, 4) : glm::vec3(0, 0, 1);
            // A at (32 + 3i + 1, 160 + 3j + 1); B turned: u along +y, v along -x.
            const glm::vec3 expected(lambert(n, light));
            CHECK(fw::test::probe_rgb(out.color, 33 + 3 * i, 161 + 3 * j, expected, kTol));
            const glm::vec3 nb(-n.y, n.x, n.z);  // B's tangent-space normal in world space
            CHECK(fw::test::probe_rgb(out.color, 478 - 3 * j, 161 + 3 * i,
                                      glm::vec3(lambert(nb, light)), kTol));
            CHECK(fw::test::probe_rgb(flat.color, 33 + 3 * i, 161 + 3 * j,
                                      glm::vec3(lambert({0, 0, 1}, light)), kTol));
            ++checked;
        }
    CHECK(checked > 1000);
}

TEST_CASE("surface-detail: envmap: each pixel is the cube map in reflect() and refract()") {
    Lab lab;
    for (const char* env : {"reflect", "refract", "fresnel"})
        for (const float ior : {1.5f, 1.25f}) {
            const fw::RenderOutput out =
                lab.render({{"scene", "envmap"}, {"env", env}, {"ior", std::to_string(ior)}});
            const std::string mode = env;
            int checked = 0;
            for (int y = 3; y < 512; y += 6)
                for (int x = 3; x < 512; x += 6) {
                    const glm::vec2 p = (glm::vec2(x, y) + 0.5f) / 128.0f - 2.0f;
                    const float r2 = glm::dot(p, p);
                    if (r2 > 2.2f) {
                        if (r2 > 2.3f)
                            CHECK(fw::test::probe_rgb(out.color, x, y, glm::vec3(0), kTol));
                        continue;
                    }
                    const glm::vec3 n(p / 1.5f, std::sqrt(2.25f - r2) / 1.5f), i(0, 0, -1);
                    const glm::vec3 r = glm::reflect(i, n), t = glm::refract(i, n, 1.0f / ior);
                    if (cube_coord(r).margin < 0.02f || cube_coord(t).margin < 0.02f) continue;
                    const float f0 = std::pow((1 - ior) / (1 + ior), 2.0f);
                    const float f = f0 + (1 - f0) * std::pow(1 - n.z, 5.0f);
                    const glm::vec3 c = mode == "reflect" ? environment(r)
                                        : mode == "refract"
                                            ? environment(t)
                                            : glm::mix(environment(t), environment(r), f);
                    INFO(env << ", ior " << ior);
                    CHECK(fw::test::probe_rgb(out.color, x, y, c, 2.5f / 255.0f));
                    ++checked;
                }
            CHECK(checked > 1000);
        }
}

TEST_CASE("surface-detail: raycast: the deck's counts, and GL's image where no shadow falls") {
    Lab lab;
    for (const int lights : {1, 2}) {
        const fw::RenderOutput out = lab.render(
            {{"scene", "raycast"}, {"view", "cpu"}, {"lights", lights == 1 ? "one" : "two"}});
        const nlohmann::json& s = out.stats["lab_stats"];
        INFO(lights << " lights");
        // 64 x 64 pixels, 15 triangles, every pixel hits the ground.
        CHECK(s["rays"]["primary"] == 4096);
        CHECK(s["rays"]["shadow"] == 4096 * lights);
        CHECK(s["intersection_tests"] == 4096 * 15 * (lights + 1));
        CHECK(s["hits"] == 4096);
        CHECK(s["differ"] == 0);
        CHECK(s["color_differ_unshadowed"] == 0);
        CHECK(s["shadowed"] > 50);
    }
}

TEST_CASE("surface-detail: checkpoints.json: its probes and stats hold for the solution") {
    Lab lab;
    fw::test::for_each_checkpoint(
        lab.lab, lab.renderer, 10,
        [&](const fw::Checkpoint& cp, const fw::ParamValues&, const fw::RenderOutput& out) {
            fw::test::check_probes_and_stats(cp.checks, out);
        });
}

TEST_CASE(
    "surface-detail: each checkpoint's frame, warm, in milliseconds (a figure, not a check)") {
    Lab lab;
    fw::test::for_each_checkpoint(
        lab.lab, lab.renderer, 10,
        [&](const fw::Checkpoint& cp, const fw::ParamValues&, const fw::RenderOutput&) {
            fw::test::Settings settings;
            for (const auto& [name, value] : cp.params.items())
                settings.emplace_back(name,
                                      value.is_string() ? value.get<std::string>() : value.dump());
            const auto start = std::chrono::steady_clock::now();
            lab.render(settings);
            const std::chrono::duration<double, std::milli> ms =
                std::chrono::steady_clock::now() - start;
            MESSAGE(cp.name << ": " << ms.count() << " ms");
        });
}
