// Lab 4 `geometry`, the lab of this test's folder. Every expectation is
// computed here from the sheet's numbers (labs/04_geometry/README.md) by
// geometry_scene.cpp, never read from a reference image or from the lab's own
// code.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

#include "framework/checkpoints.hpp"
#include "framework/lab.hpp"
#include "framework/render.hpp"
#include "geometry_scene.hpp"
#include "tests/support/test_support.hpp"

using namespace geometry_test;

namespace {

using fw::test::Settings;

// The lab of this folder, created once per test case.
struct Geometry : fw::test::LabUnderTest {
    // Square frames of `size`.
    fw::RenderOutput render(const Settings& settings, int size = kSize) {
        return LabUnderTest::render(settings, size, size);
    }
};

glm::vec3 rgb(const fw::Image& img, int x, int y) { return fw::test::rgb_at(img, x, y); }
using fw::test::near;

bool covered(const fw::RenderOutput& out, int x, int y) { return out.depth.at(x, y) < 1.0f; }

float distance_from_centre(int x, int y) {
    return glm::length(glm::vec2(x + 0.5f, y + 0.5f) - glm::vec2(kSize / 2.0f));
}

// Compares every pixel with the ray caster's prediction for `faces`; pixels
// within 0.05 px of a projected edge (and, with `wireframe`, within 0.05 px
// of the 1 px edge band's border) are left out. Returns the mismatches,
// logging the first few as Expected/Observed.
int mismatches(const fw::Image& img, const std::vector<Face>& faces, bool wireframe = false) {
    int bad = 0, compared = 0;
    const std::vector<Projected> front = project(faces);
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const Hit hit = cast(front, x, y, 0.05f);
            if (hit.ambiguous) continue;
            if (wireframe && hit.covered && std::abs(hit.edge_distance - 1.0f) < 0.05f) continue;
            glm::vec3 expected = hit.covered ? hit.color : kBlack;
            if (wireframe && hit.covered && hit.edge_distance < 1.0f) expected = kWhite;
            ++compared;
            const glm::vec3 observed = rgb(img, x, y);
            if (near(observed, expected, 2.0f / 255.0f)) continue;
            if (++bad <= 5) {
                char line[200];
                std::snprintf(line, sizeof line,
                              "pixel (%d, %d): expected (%.4f, %.4f, %.4f) observed (%.4f, "
                              "%.4f, %.4f)",
                              x, y, expected.r, expected.g, expected.b, observed.r, observed.g,
                              observed.b);
                MESSAGE(line);
            }
        }
    MESSAGE(compared << " pixels compared, " << bad << " differ");
    CHECK(compared > kSize * kSize * 9 / 10);
    return bad;
}

}  // namespace

TEST_CASE("geometry: the declaration has the sheet's parameters and defaults") {
    const fw::RegisteredLab& lab = fw::test::this_lab();
    const fw::ParamValues p = fw::default_params(lab);
    CHECK(p.text("mode") == "passthrough");
    CHECK(p.integer("subdiv") == 2);
    CHECK(p.number("spin") == 0.0f);
    CHECK(p.number("amount") == doctest::Approx(0.2));
    CHECK(p.number("offset_x") == doctest::Approx(1.5));
    CHECK(p.number("offset_y") == 0.0f);
    CHECK(p.number("offset_z") == doctest::Approx(-1.5));
    CHECK(p.number("length") == doctest::Approx(0.15));
    for (const fw::Param& param : lab.info.params) {
        INFO("parameter " << param.name);
        CHECK(!param.help_text.empty());
        CHECK(param.shortcut != 0);
    }
    const fw::Param& subdiv = lab.info.params[1];
    CHECK(subdiv.name == "subdiv");
    CHECK(subdiv.min == 0);
    CHECK(subdiv.max == 5);
}

TEST_CASE("geometry: primitives generated: T, 2T, T, T + 3T, T at every subdivision") {
    Geometry lab;
    const std::pair<const char*, int> modes[] = {
        {"passthrough", 1}, {"duplicate", 2}, {"explode", 1}, {"normals", 4}, {"wireframe", 1}};
    for (int subdiv = 0; subdiv <= 5; ++subdiv) {
        const long t = 20L << (2 * subdiv);  // 20 * 4^subdiv
        for (const auto& [mode, per_triangle] : modes) {
            CAPTURE(subdiv);
            CAPTURE(mode);
            const fw::RenderOutput out =
                lab.render({{"mode", mode}, {"subdiv", std::to_string(subdiv)}}, 64);
            INFO("expected " << per_triangle * t << " observed "
                             << out.stats["primitives_generated"]);
            CHECK(out.stats["primitives_generated"] == per_triangle * t);
            CHECK(out.stats["lab_stats"]["triangles"] == t);
            CHECK(out.stats["lab_stats"]["vertices"] == (10L << (2 * subdiv)) + 2);
        }
    }
}

TEST_CASE("geometry: subdiv 0: every pixel of passthrough, duplicate, explode, wireframe") {
    Geometry lab;
    for (float spin : {0.0f, 30.0f}) {
        CAPTURE(spin);
        const glm::mat3 model = rotate_y(spin);
        const std::vector<Face> ico = icosahedron_faces(model);
        REQUIRE(ico.size() == 20);
        const Settings base = {{"subdiv", "0"}, {"spin", std::to_string(spin)}};
        auto with = [&](Settings more) {
            more.insert(more.begin(), base.begin(), base.end());
            return lab.render(more).color;
        };
        CHECK(mismatches(with({{"mode", "passthrough"}}), ico) == 0);
        // The copy is moved by the offset in object space: model * offset in the world.
        std::vector<Face> both = ico;
        for (const Face& f : moved(ico, model * glm::vec3(1.5f, 0.0f, -1.5f), kTint))
            both.push_back(f);
        CHECK(mismatches(with({{"mode", "duplicate"}}), both) == 0);
        both = ico;
        for (const Face& f : moved(ico, model * glm::vec3(-0.5f, 1.0f, 0.5f), kTint))
            both.push_back(f);
        CHECK(mismatches(with({{"mode", "duplicate"},
                               {"offset_x", "-0.5"},
                               {"offset_y", "1"},
                               {"offset_z", "0.5"}}),
                         both) == 0);
        CHECK(mismatches(with({{"mode", "explode"}}), exploded(ico, 0.2f)) == 0);
        CHECK(mismatches(with({{"mode", "explode"}, {"amount", "0.6"}}), exploded(ico, 0.6f)) == 0);
        CHECK(mismatches(with({{"mode", "wireframe"}}), ico, true) == 0);
    }
}

TEST_CASE("geometry: duplicate: the tinted copy where the offset puts it, grey at the centre") {
    Geometry lab;
    // spin 90 turns the object-space offset (1.5, 0, -1.5) to (-1.5, 0, -1.5).
    for (float spin : {0.0f, 90.0f}) {
        CAPTURE(spin);
        const glm::vec3 centre = rotate_y(spin) * glm::vec3(1.5f, 0.0f, -1.5f);
        const glm::ivec2 at = pixel_of(to_window(centre));
        const fw::RenderOutput out =
            lab.render({{"mode", "duplicate"}, {"spin", std::to_string(spin)}});
        // The facets differ from the true sphere by a few degrees: 0.03.
        CHECK(distance_from_centre(at.x, at.y) > silhouette_radius(1.0f) + 2.0f);
        const auto copy = sphere_color(at.x, at.y, centre, kTint);
        REQUIRE(copy);
        CHECK(fw::test::probe_rgb(out.color, at.x, at.y, *copy, 0.03f));
        const auto original = sphere_color(kSize / 2, kSize / 2, glm::vec3(0.0f), kGrey);
        CHECK(fw::test::probe_rgb(out.color, kSize / 2, kSize / 2, *original, 0.03f));
        // Half-way between the two centres on screen only the original is seen.
        const glm::ivec2 mid = pixel_of(0.5f * (to_window(centre) + glm::vec2(kSize / 2.0f)));
        CHECK(fw::test::probe_rgb(out.color, mid.x, mid.y,
                                  *sphere_color(mid.x, mid.y, glm::vec3(0.0f), kGrey), 0.03f));
    }
}

TEST_CASE("geometry: explode opens gaps inside the silhouette, none at amount 0") {
    Geometry lab;
    const fw::RenderOutput whole = lab.render({{"mode", "passthrough"}});
    // Depth, not colour, tells surface from background: with Lambert alone
    // the side turned away from the light is black too.
    auto gaps = [&](const fw::RenderOutput& out) {
        long n = 0;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) n += covered(whole, x, y) && !covered(out, x, y);
        return n;
    };
    auto beyond = [&](const fw::RenderOutput& out, float radius) {
        long n = 0;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x)
                n += covered(out, x, y) && distance_from_centre(x, y) > radius + 1.0f;
        return n;
    };
    const fw::RenderOutput open = lab.render({{"mode", "explode"}, {"amount", "0.2"}});
    const fw::RenderOutput closed = lab.render({{"mode", "explode"}, {"amount", "0"}});
    const long open_gaps = gaps(open), closed_gaps = gaps(closed);
    INFO("gaps: amount 0.2: " << open_gaps << ", amount 0: " << closed_gaps);
    // About 160 front faces, each edge opening a gap a few pixels wide.
    CHECK(open_gaps > 5000);
    CHECK(closed_gaps == 0);
    // Every moved vertex stays within the sphere of radius 1 + amount.
    CHECK(beyond(whole, silhouette_radius(1.0f)) == 0);
    CHECK(beyond(open, silhouette_radius(1.2f)) == 0);
    CHECK(beyond(open, silhouette_radius(1.0f)) > 0);
}

TEST_CASE("geometry: normals: yellow lines beyond the rim, the sphere unchanged") {
    Geometry lab;
    const fw::RenderOutput whole = lab.render({{"mode", "passthrough"}});
    const fw::RenderOutput out = lab.render({{"mode", "normals"}});
    const float rim = silhouette_radius(1.0f), tips = silhouette_radius(1.15f);
    long outside = 0, too_far = 0, other_changes = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const bool yellow = near(rgb(out.color, x, y), kYellow, 1.0f / 255.0f);
            const float r = distance_from_centre(x, y);
            outside += yellow && r > rim + 2.0f;
            too_far += yellow && r > tips + 2.0f;
            other_changes += !yellow && out.color.at(x, y) != whole.color.at(x, y);
        }
    INFO("yellow beyond the rim: " << outside << ", beyond the tips: " << too_far
                                   << ", other pixels changed: " << other_changes);
    CHECK(outside > 100);
    CHECK(too_far == 0);
    CHECK(other_changes == 0);
    // Longer lines reach further out.
    const fw::RenderOutput longer = lab.render({{"mode", "normals"}, {"length", "0.4"}});
    long far_out = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x)
            far_out += near(rgb(longer.color, x, y), kYellow, 1.0f / 255.0f) &&
                       distance_from_centre(x, y) > tips + 4.0f;
    CHECK(far_out > 100);
}

TEST_CASE("geometry: wireframe: white edges, the fill still the passthrough's grey") {
    Geometry lab;
    const fw::RenderOutput whole = lab.render({{"mode", "passthrough"}});
    const fw::RenderOutput out = lab.render({{"mode", "wireframe"}});
    long white = 0, inside = 0, fill_differs = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            inside += covered(whole, x, y);
            if (out.color.at(x, y) == fw::Rgba8{255, 255, 255, 255})
                ++white;
            else
                fill_differs += out.color.at(x, y) != whole.color.at(x, y);
        }
    INFO("white " << white << " of " << inside << " covered; fill pixels differing "
                  << fill_differs);
    CHECK(white > inside / 20);
    CHECK(white < inside / 3);
    CHECK(fill_differs == 0);
    // The icosahedron's edge 4-5 runs along x = 0 through the centre; each
    // subdivision keeps it (split in two). The pixels on both sides of
    // x = 256 are within 1 px of it.
    for (int y : {236, 256, 276})
        for (int x : {255, 256}) CHECK(fw::test::probe_rgb(out.color, x, y, kWhite));
}

TEST_CASE("geometry: checkpoints.json: its probes and stats hold for the solution") {
    Geometry lab;
    std::vector<std::string> modes;
    fw::test::for_each_checkpoint(
        lab.lab, lab.renderer, 5,
        [&](const fw::Checkpoint& cp, const fw::ParamValues& params, const fw::RenderOutput& out) {
            modes.push_back(params.text("mode"));
            fw::test::check_probes_and_stats(cp.checks, out);
        });
    for (const char* mode : {"passthrough", "duplicate", "explode", "normals", "wireframe"})
        CHECK(std::count(modes.begin(), modes.end(), mode) >= 1);
}
