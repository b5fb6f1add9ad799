// Lab 9 `buffers`: the declaration, each scene's buffer against the sheet's
// closed forms (labs/09_buffers/README.md), the frames' pixels where the
// sheet puts them, std140 against the driver, and the checkpoints. Every
// expectation is computed here from the sheet's numbers, never read from a
// reference image or the lab's code.
#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "block.hpp"
#include "framework/checkpoints.hpp"
#include "tests/support/test_support.hpp"

namespace {

using Lab = fw::test::LabUnderTest;
using Settings = fw::test::Settings;
constexpr double kPi = 3.14159265358979323846;

// Particle i of n after `steps` steps: the sheet's closed form.
glm::dvec3 particle(int i, int n, int steps) {
    const double phi = (30.0 + 120.0 * (i + 0.5) / n) * kPi / 180.0, t = 0.02 * steps;
    return {3.0 * std::cos(phi) * t, -1.5 + 3.0 * std::sin(phi) * t - 2.0 * t * t, 0.0};
}

// The buffer the lab wrote for the frame just rendered with `settings`.
fw::LabBuffer rendered_buffer(Lab& lab, const Settings& settings, const std::string& name) {
    lab.render(settings);
    const fw::ParamValues p = lab.params(settings);
    for (fw::LabBuffer& b : lab.renderer.lab().buffers(p, fw::Frame{}))
        if (b.name == name) return b;
    FAIL("the lab wrote no buffer " << name);
    return {};
}

void check_particles(const fw::LabBuffer& b, int n, int steps) {
    INFO(n << " particles, " << steps << " steps");
    CHECK(b.components == 3);
    REQUIRE(b.values.size() == std::size_t(3 * n));
    double worst = 0.0;
    for (int i = 0; i < n; ++i) {
        const glm::dvec3 p = particle(i, n, steps);
        for (int k = 0; k < 3; ++k) worst = std::fmax(worst, std::fabs(b.values[3 * i + k] - p[k]));
    }
    MESSAGE("largest difference from the closed form: " << worst);
    CHECK(worst < 1e-4);
}

// Where the sheet puts a world point: window = 128 (x, y) + 256.
glm::ivec2 window_pixel(glm::dvec3 p) {
    return {int(std::floor(128.0 * p.x + 256.0)), int(std::floor(128.0 * p.y + 256.0))};
}

}  // namespace

TEST_CASE("buffers: the declaration has the sheet's parameters and defaults") {
    const fw::RegisteredLab& lab = fw::test::this_lab();
    const fw::ParamValues p = fw::default_params(lab);
    CHECK(p.text("scene") == "feedback");
    CHECK(p.integer("count") == 100);
    CHECK(p.integer("steps") == 40);
    CHECK(p.integer("passes") == 2);
    CHECK(p.number("angle") == 40.0f);
    std::vector<std::string> names;
    for (const fw::Param& param : lab.info.params) {
        INFO("parameter " << param.name);
        names.push_back(param.name);
        CHECK(!param.help_text.empty());
        CHECK(param.shortcut != 0);
    }
    CHECK(names == std::vector<std::string>{"scene", "count", "steps", "passes", "angle"});
}

TEST_CASE("buffers: feedback: every particle where the closed form puts it, and drawn there") {
    Lab lab;
    for (const auto& [n, steps] :
         std::vector<std::pair<int, int>>{{100, 40}, {37, 73}, {1, 1}, {1000, 100}, {5, 0}}) {
        const Settings s = {
            {"scene", "feedback"}, {"count", std::to_string(n)}, {"steps", std::to_string(steps)}};
        check_particles(rendered_buffer(lab, s, "particles"), n, steps);
    }
    const Settings s = {{"scene", "feedback"}};
    const fw::RenderOutput out = lab.render(s);
    CHECK(out.stats["lab_stats"]["primitives_written"] == 4000);
    int drawn = 0;
    for (int i = 0; i < 100; ++i) {
        const glm::ivec2 w = window_pixel(particle(i, 100, 40));
        if (w.x < 0 || w.x >= 512 || w.y < 0 || w.y >= 512) continue;
        ++drawn;
        INFO("particle " << i << " at pixel (" << w.x << ", " << w.y << ")");
        CHECK(fw::test::near(fw::test::rgb_at(out.color, w.x, w.y), {1.0f, 0.8f, 0.3f}, 0.01f));
    }
    CHECK(drawn > 50);
    CHECK(fw::test::near(fw::test::rgb_at(out.color, 256, 400), {0, 0, 0}, 0.0f));
}

TEST_CASE("buffers: compute: the closed form, 64 invocations a group, as many groups as cover n") {
    Lab lab;
    for (const auto& [n, steps] :
         std::vector<std::pair<int, int>>{{100, 40}, {64, 10}, {65, 10}, {1000, 100}}) {
        const Settings s = {
            {"scene", "compute"}, {"count", std::to_string(n)}, {"steps", std::to_string(steps)}};
        check_particles(rendered_buffer(lab, s, "particles"), n, steps);
        const fw::RenderOutput out = lab.render(s);
        CHECK(out.stats["lab_stats"]["work_group_size"] == 64);
        CHECK(out.stats["lab_stats"]["work_groups"] == (n + 63) / 64);
        const glm::ivec2 w = window_pixel(particle(n / 2, n, steps));
        if (w.y < 0) continue;  // fallen out of the frame
        CHECK(fw::test::near(fw::test::rgb_at(out.color, w.x, w.y), {0.3f, 0.8f, 1.0f}, 0.01f));
    }
}

TEST_CASE(
    "buffers: subdivide: 24 4^k vertices on the unit sphere, each triangle split as the sheet "
    "says") {
    Lab lab;
    std::vector<float> before;
    for (int passes = 0; passes <= 4; ++passes) {
        INFO("passes " << passes);
        const Settings s = {{"scene", "subdivide"}, {"passes", std::to_string(passes)}};
        const fw::LabBuffer b = rendered_buffer(lab, s, "vertices");
        std::size_t vertices = 24;
        for (int k = 0; k < passes; ++k) vertices *= 4;
        REQUIRE(b.values.size() == 3 * vertices);
        for (std::size_t v = 0; v < vertices; ++v) {
            const glm::dvec3 p(b.values[3 * v], b.values[3 * v + 1], b.values[3 * v + 2]);
            if (std::fabs(glm::length(p) - 1.0) > 1e-6)
                FAIL_CHECK("vertex " << v << " is off the sphere");
        }
        // Triangle t of the pass before is split into triangles 4t..4t+3:
        // its corners a, b, c are vertices 0, 4 and 8 of the twelve.
        if (passes > 0)
            for (std::size_t t = 0; 9 * t < before.size(); ++t)
                for (int corner = 0; corner < 3; ++corner)
                    for (int k = 0; k < 3; ++k)
                        CHECK(b.values[36 * t + 12 * corner + k] == before[9 * t + 3 * corner + k]);
        if (passes == 0) CHECK(b.values[0] == 1.0f);  // the ring starts at +x
        const fw::RenderOutput out = lab.render(s);
        long written = 0, made = 8;
        for (int k = 0; k < passes; ++k) written += made *= 4;
        CHECK(out.stats["lab_stats"]["primitives_written"] == written);
        before = b.values;
    }
}

TEST_CASE("buffers: block: std140 as the driver lays it out, and the lit ellipsoid") {
    using buffers::GlslType;
    using buffers::std140_place;
    CHECK(std140_place(0, GlslType::Float).end == 4);
    CHECK(std140_place(4, GlslType::Vec3).offset == 16);
    CHECK(std140_place(112, GlslType::Vec3).end == 124);
    CHECK(std140_place(124, GlslType::Float).offset == 124);
    CHECK(std140_place(20, GlslType::Vec2).offset == 24);
    CHECK(std140_place(64, GlslType::Mat3).end == 112);
    CHECK(std140_place(8, GlslType::Mat4).offset == 16);
    Lab lab;
    for (const char* angle : {"40", "-120", "0"}) {
        INFO("angle " << std::string(angle));
        const fw::RenderOutput out = lab.render({{"scene", "block"}, {"angle", angle}});
        const nlohmann::json block = out.stats["lab_stats"]["block"];
        const nlohmann::json sheet = {0, 64, 112, 124, 128, 144};
        CHECK(block["driver"] == sheet);
        CHECK(block["struct"] == sheet);
        CHECK(block["std140_place"] == sheet);
        // Every pixel well inside the outline against the closed form.
        const glm::dvec3 light = glm::normalize(glm::dvec3(1.0));
        int checked = 0, off = 0;
        for (int py = 0; py < 512; py += 7)
            for (int px = 0; px < 512; px += 7) {
                const double x = (px + 0.5) / 512.0 * 2.5 - 1.25,
                             y = (py + 0.5) / 512.0 * 2.5 - 1.25;
                const double r = 1.0 - x * x - (y / 0.6) * (y / 0.6);
                if (r < 0.05) continue;
                const glm::dvec3 n = glm::normalize(glm::dvec3(x, y / 0.36, std::sqrt(r)));
                const double k = 0.2 + 0.8 * std::fmax(glm::dot(n, light), 0.0);
                const glm::vec3 want(0.9 * k, 0.5 * k, 0.2 * k);
                ++checked;
                off += fw::test::near(fw::test::rgb_at(out.color, px, py), want, 0.02f) ? 0 : 1;
            }
        MESSAGE(checked << " pixels checked, " << off << " off by more than 0.02");
        CHECK(checked > 1500);
        CHECK(off == 0);
    }
}

TEST_CASE("buffers: checkpoints.json: its probes and stats hold for the solution") {
    Lab lab;
    std::vector<std::string> scenes;
    fw::test::for_each_checkpoint(
        lab.lab, lab.renderer, 6,
        [&](const fw::Checkpoint& cp, const fw::ParamValues& params, const fw::RenderOutput& out) {
            scenes.push_back(params.text("scene"));
            fw::test::check_probes_and_stats(cp.checks, out);
        });
    for (const std::string scene : {"feedback", "compute", "subdivide", "block"}) {
        INFO("scene " << scene);
        CHECK(std::count(scenes.begin(), scenes.end(), scene) >= 1);
    }
}

TEST_CASE("buffers: a frame after one that left the rasterizer off is cleared and drawn") {
    Lab lab;
    lab.render({{"scene", "feedback"}});
    // As a feedback loop that never turns the rasterizer back on leaves it:
    // glClear would then be ignored too (GL 4.3, 14.1).
    glEnable(GL_RASTERIZER_DISCARD);
    const fw::RenderOutput out = lab.render({{"scene", "block"}});
    CHECK(
        fw::test::near(fw::test::rgb_at(out.color, 256, 256), {0.5995f, 0.3331f, 0.1332f}, 0.02f));
    CHECK(fw::test::near(fw::test::rgb_at(out.color, 5, 5), {0, 0, 0}, 0.0f));
}
