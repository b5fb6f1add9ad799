// Lab 10 `advanced-geometry`: the declaration, the instances and the clip
// plane against the sheet's closed forms (labs/10_advanced_geometry/README.md),
// and the checkpoints; test_layers_outline.cpp has the cube map and the
// silhouette. Every expectation is computed here from the sheet's numbers,
// never read from a reference image or the lab's code.
#include <algorithm>
#include <cmath>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "framework/checkpoints.hpp"
#include "tests/support/test_support.hpp"

namespace {

using Lab = fw::test::LabUnderTest;
using fw::test::near;
using fw::test::rgb_at;
constexpr double kPi = 3.14159265358979323846;

// World x or y of a pixel centre in the clip scene:
// [-1.25, 1.25] across 512 pixels.
double world_of(int pixel) { return (pixel + 0.5) / 512.0 * 2.5 - 1.25; }

}  // namespace

TEST_CASE("advanced-geometry: the declaration has the sheet's parameters and defaults") {
    const fw::RegisteredLab& lab = fw::test::this_lab();
    const fw::ParamValues p = fw::default_params(lab);
    CHECK(p.text("scene") == "instances");
    CHECK(p.integer("columns") == 5);
    CHECK(p.integer("rows") == 4);
    CHECK(p.number("clip_angle") == 30.0f);
    CHECK(p.number("clip_offset") == 0.25f);
    CHECK(p.integer("face_size") == 128);
    CHECK(p.number("yaw") == 30.0f);
    CHECK(p.number("pitch") == 25.0f);
    for (const fw::Param& param : lab.info.params) {
        INFO("parameter " << param.name);
        CHECK(!param.help_text.empty());
        CHECK(param.shortcut != 0);
    }
}

TEST_CASE("advanced-geometry: instances: every cell in its instance's colour, the gaps black") {
    Lab lab;
    for (const auto& [columns, rows] :
         std::vector<std::pair<int, int>>{{5, 4}, {3, 7}, {8, 8}, {1, 1}, {8, 1}}) {
        INFO(columns << " x " << rows);
        const fw::RenderOutput out = lab.render({{"scene", "instances"},
                                                 {"columns", std::to_string(columns)},
                                                 {"rows", std::to_string(rows)}});
        CHECK(out.stats["primitives_generated"] == 2 * columns * rows);
        int off = 0;
        for (int r = 0; r < rows; ++r)
            for (int c = 0; c < columns; ++c) {
                const glm::vec3 want(float(c + 1) / float(columns), float(r + 1) / float(rows),
                                     0.3f);
                // Three points across the quad's middle 80%: its centre and near two corners.
                for (const double f : {0.0, -0.35, 0.35}) {
                    const double x = -1.0 + (2.0 * c + 1.0 + 2.0 * f) / columns;
                    const double y = -1.0 + (2.0 * r + 1.0 - 2.0 * f) / rows;
                    const int px = int(std::floor(256.0 + 256.0 * x)),
                              py = int(std::floor(256.0 + 256.0 * y));
                    off += near(rgb_at(out.color, px, py), want, 0.01f) ? 0 : 1;
                }
                // Left of the cell's quad: the gap (the cell's outer 10%).
                const int gap = int(std::floor(256.0 + 256.0 * (-1.0 + (2.0 * c + 0.1) / columns)));
                const int middle = int(std::floor(256.0 + 256.0 * (-1.0 + (2.0 * r + 1.0) / rows)));
                off += near(rgb_at(out.color, gap, middle), glm::vec3(0.0f), 0.0f) ? 0 : 1;
            }
        CHECK(off == 0);
    }
}

TEST_CASE("advanced-geometry: clip: the sphere kept where n . p + d >= 0, the rest black") {
    Lab lab;
    for (const auto& [angle, d] :
         std::vector<std::pair<double, double>>{{30, 0.25}, {150, -0.3}, {-90, 0}, {0, 0.9}}) {
        INFO("clip_angle " << angle << ", clip_offset " << d);
        const fw::RenderOutput out = lab.render({{"scene", "clip"},
                                                 {"clip_angle", std::to_string(angle)},
                                                 {"clip_offset", std::to_string(d)}});
        const glm::dvec2 n(std::cos(angle * kPi / 180.0), std::sin(angle * kPi / 180.0));
        int kept = 0, cut = 0, off = 0;
        for (int py = 0; py < 512; py += 5)
            for (int px = 0; px < 512; px += 5) {
                const double x = world_of(px), y = world_of(py), r2 = x * x + y * y;
                const double distance = n.x * x + n.y * y + d;
                // Two pixels (0.01 world units) clear of the cut and the outline.
                if (std::fabs(distance) < 0.01 || std::fabs(std::sqrt(r2) - 1.0) < 0.01) continue;
                glm::vec3 want(0.0f);
                if (distance > 0.0 && r2 < 1.0) {
                    want = glm::vec3(0.5 + 0.5 * glm::dvec3(x, y, std::sqrt(1.0 - r2)));
                    ++kept;
                } else if (r2 < 1.0) {
                    ++cut;
                }
                off += near(rgb_at(out.color, px, py), want, 0.03f) ? 0 : 1;
            }
        MESSAGE(kept << " pixels of the sphere kept, " << cut << " cut away, " << off << " off");
        CHECK(kept > 50);
        CHECK(cut > 50);
        CHECK(off == 0);
    }
}

TEST_CASE("advanced-geometry: checkpoints.json: its probes and stats hold for the solution") {
    Lab lab;
    std::vector<std::string> scenes;
    fw::test::for_each_checkpoint(
        lab.lab, lab.renderer, 8,
        [&](const fw::Checkpoint& cp, const fw::ParamValues& params, const fw::RenderOutput& out) {
            scenes.push_back(params.text("scene"));
            fw::test::check_probes_and_stats(cp.checks, out);
        });
    for (const std::string scene : {"instances", "clip", "layers", "silhouette"}) {
        INFO("scene " << scene);
        CHECK(std::count(scenes.begin(), scenes.end(), scene) >= 2);
    }
}
