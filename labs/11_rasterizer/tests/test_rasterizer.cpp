// Lab 11 `rasterizer`. The CPU rasterizer against pixels worked out by hand
// from the sheet's rules (labs/11_rasterizer/README.md), and the
// checkpoints' probes and stats for the solution.
#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "framework/checkpoints.hpp"
#include "raster.hpp"
#include "tests/support/test_support.hpp"

namespace {

using rasterizer::Canvas;
using Pixels = std::set<std::pair<int, int>>;

Pixels written(const Canvas& c) {
    Pixels out;
    for (int y = 0; y < c.height; ++y)
        for (int x = 0; x < c.width; ++x)
            if (c.writes[static_cast<size_t>(c.index(x, y))] > 0) out.insert({x, y});
    return out;
}

int max_writes(const Canvas& c) {
    int m = 0;
    for (int w : c.writes) m = std::max(m, w);
    return m;
}

}  // namespace

TEST_CASE("rasterizer: lines from (0, 0) to (5, 2) and back, by DDA and Bresenham") {
    // y = 2x / 5 at x = 0..5 is 0, 0.4, 0.8, 1.2, 1.6, 2: nearest rows 0 0 1 1 2 2.
    const Pixels want = {{0, 0}, {1, 0}, {2, 1}, {3, 1}, {4, 2}, {5, 2}};
    for (bool reverse : {false, true}) {
        const glm::ivec2 a = reverse ? glm::ivec2(5, 2) : glm::ivec2(0, 0);
        const glm::ivec2 b = reverse ? glm::ivec2(0, 0) : glm::ivec2(5, 2);
        Canvas dda(8, 8), bres(8, 8);
        rasterizer::line_dda(dda, a, b, glm::vec3(1));
        rasterizer::line_bresenham(bres, a, b, glm::vec3(1));
        INFO("reverse " << reverse);
        CHECK(written(dda) == want);
        CHECK(written(bres) == want);
    }
    // y-major, towards -x: (6, 0) to (4, 5); x = 6 - 2y / 5 at y = 0..5 is
    // 6, 5.6, 5.2, 4.8, 4.4, 4: nearest columns 6 6 5 5 4 4.
    Canvas steep(8, 8);
    rasterizer::line_bresenham(steep, {6, 0}, {4, 5}, glm::vec3(1));
    CHECK(written(steep) == Pixels{{6, 0}, {6, 1}, {5, 2}, {5, 3}, {4, 4}, {4, 5}});
}

TEST_CASE("rasterizer: a quad as two triangles fills each covered pixel centre once") {
    // Counter-clockwise, y up: a top edge runs towards -x, a left edge down.
    CHECK(rasterizer::top_left({3, 1}, {1, 1}));
    CHECK_FALSE(rasterizer::top_left({1, 1}, {3, 1}));
    CHECK(rasterizer::top_left({1, 3}, {1, 1}));
    CHECK_FALSE(rasterizer::top_left({1, 1}, {1, 3}));
    CHECK(rasterizer::top_left({2, 3}, {1, 1}));
    CHECK_FALSE(rasterizer::top_left({1, 1}, {2, 3}));
    // The square [1, 5] x [1, 4] split along its diagonal: centres 1.5..4.5 by
    // 1.5..3.5, 4 x 3 = 12 pixels, the diagonal's centres owned by one side.
    for (bool clockwise : {false, true}) {
        Canvas c(8, 8);
        const glm::vec2 q[4] = {{1, 1}, {5, 1}, {5, 4}, {1, 4}};
        for (const auto& t : {std::vector<int>{0, 1, 2}, std::vector<int>{0, 2, 3}}) {
            rasterizer::WindowVertex v[3];
            for (int i = 0; i < 3; ++i)
                v[i] = {{q[t[clockwise ? 2 - i : i]], 0.5f}, 1.0f, glm::vec3(1)};
            rasterizer::fill_triangle(c, v, true, false);
        }
        INFO("clockwise " << clockwise);
        CHECK(written(c).size() == 12u);
        CHECK(max_writes(c) == 1);
    }
    // A vertical shared edge through the centres x = 2.5: the left edge of the
    // right triangle (owned), the right edge of the left one (not).
    Canvas c(8, 8);
    const rasterizer::WindowVertex left[3] = {{{0, 0, 0.5f}, 1, glm::vec3(1, 0, 0)},
                                              {{2.5f, 0, 0.5f}, 1, glm::vec3(1, 0, 0)},
                                              {{2.5f, 4, 0.5f}, 1, glm::vec3(1, 0, 0)}};
    const rasterizer::WindowVertex right[3] = {{{2.5f, 0, 0.5f}, 1, glm::vec3(0, 1, 0)},
                                               {{5, 0, 0.5f}, 1, glm::vec3(0, 1, 0)},
                                               {{2.5f, 4, 0.5f}, 1, glm::vec3(0, 1, 0)}};
    rasterizer::fill_triangle(c, left, true, false);
    rasterizer::fill_triangle(c, right, true, false);
    CHECK(max_writes(c) == 1);
    CHECK(c.color[static_cast<size_t>(c.index(2, 1))] == glm::vec3(0, 1, 0));
}

TEST_CASE("rasterizer: the scanline fill writes what the edge-function fill writes") {
    // Edges through pixel centres (the square (0.5, 0.5)-(4.5, 4.5) cut along
    // its diagonal, both windings), then triangles from a fixed sequence of
    // numbers, partly off the canvas, with depth and perspective-correct colour.
    std::vector<glm::vec2> corners = {{0.5f, 0.5f}, {4.5f, 0.5f}, {4.5f, 4.5f}, {0.5f, 0.5f},
                                      {4.5f, 4.5f}, {0.5f, 4.5f}, {0.5f, 0.5f}, {4.5f, 4.5f},
                                      {4.5f, 0.5f}, {3.5f, 3.5f}, {0.5f, 3.5f}, {0.5f, 0.5f}};
    unsigned state = 12345u;
    const auto next = [&state] {
        state = state * 1103515245u + 12345u;
        return static_cast<float>((state >> 8) % 12000u) / 1000.0f - 2.0f;
    };
    for (int i = 0; i < 600; ++i) corners.emplace_back(next(), next());
    Canvas edge(8, 8), scan(8, 8);
    for (size_t t = 0; t + 2 < corners.size(); t += 3) {
        rasterizer::WindowVertex v[3];
        for (int i = 0; i < 3; ++i)
            v[i] = {{corners[t + i], 0.1f * static_cast<float>(i + t % 7)},
                    1.0f + static_cast<float>(i),
                    glm::vec3(i == 0, i == 1, i == 2)};
        rasterizer::fill_triangle(edge, v, true, true);
        rasterizer::fill_triangle_scanline(scan, v, true, true);
        INFO("triangle " << t / 3);
        REQUIRE(scan.writes == edge.writes);
        REQUIRE(scan.color == edge.color);
        REQUIRE(scan.depth == edge.depth);
    }
}

TEST_CASE("rasterizer: perspective-correct colour and the near-plane clip") {
    const rasterizer::WindowVertex v[3] = {{{0, 0, 0.2f}, 1.0f, glm::vec3(1, 0, 0)},
                                           {{4, 0, 0.6f}, 3.0f, glm::vec3(0, 1, 0)},
                                           {{0, 4, 0.2f}, 1.0f, glm::vec3(0, 0, 1)}};
    // Halfway along the edge 0-1: affine (0.5, 0.5, 0); perspective weights
    // 0.5 / 1 and 0.5 / 3, so green = (1/6) / (1/2 + 1/6) = 0.25. Depth 0.4.
    const glm::vec3 bary(0.5f, 0.5f, 0.0f);
    const rasterizer::Fragment affine = rasterizer::interpolate(v, bary, false);
    const rasterizer::Fragment correct = rasterizer::interpolate(v, bary, true);
    CHECK(fw::test::near(affine.color, glm::vec3(0.5f, 0.5f, 0), 1e-6f));
    CHECK(fw::test::near(correct.color, glm::vec3(0.75f, 0.25f, 0), 1e-6f));
    CHECK(std::abs(correct.depth - 0.4f) < 1e-6f);
    // One corner behind the near plane (z + w < 0) -> 4 vertices; two -> 3.
    const rasterizer::ClipVertex one[3] = {{{-0.8f, -0.8f, 0, 1}, glm::vec3(1, 0, 0)},
                                           {{1.6f, -1.6f, 0, 2}, glm::vec3(0, 1, 0)},
                                           {{0, 0.8f, -3, 1}, glm::vec3(0, 0, 1)}};
    const std::vector<rasterizer::ClipVertex> quad = rasterizer::clip_near(one);
    REQUIRE(quad.size() == 4u);
    // Edge 1-2: d = z + w is 2 then -2, t = 0.5: (0.8, -0.4, -1.5, 1.5).
    CHECK(fw::test::near(glm::vec3(quad[2].clip), glm::vec3(0.8f, -0.4f, -1.5f), 1e-6f));
    const rasterizer::WindowVertex w = rasterizer::to_window(quad[2], 32, 32);
    // NDC (0.5333, -0.2667, -1) -> window (24.533, 11.733, 0).
    CHECK(fw::test::near(w.window, glm::vec3(24.5333f, 11.7333f, 0.0f), 1e-3f));
    rasterizer::ClipVertex two[3] = {one[0], one[1], one[2]};
    two[1].clip = {0.8f, -0.8f, -3, 1};
    CHECK(rasterizer::clip_near(two).size() == 3u);
}

namespace {

// The stats' bounds (`min`, `max`), which check_probes_and_stats() leaves
// to the caller; it gets the probes and the `equals` stats.
void check_bounds(const nlohmann::json& checks, const fw::RenderOutput& out) {
    for (const nlohmann::json& check : checks) {
        if (check.at("kind") != "stat" || check.contains("equals")) continue;
        const std::string path = check.at("stat").get<std::string>();
        const nlohmann::json value = out.stats.at(
            nlohmann::json::json_pointer("/" + std::regex_replace(path, std::regex("\\."), "/")));
        INFO(path << " = " << value.dump());
        if (check.contains("min")) CHECK(value.get<double>() >= check["min"].get<double>());
        if (check.contains("max")) CHECK(value.get<double>() <= check["max"].get<double>());
    }
}

}  // namespace

TEST_CASE("rasterizer: checkpoints.json: its probes and stats hold for the solution") {
    fw::test::LabUnderTest lab;
    fw::test::for_each_checkpoint(
        lab.lab, lab.renderer, 8,
        [&](const fw::Checkpoint& cp, const fw::ParamValues&, const fw::RenderOutput& out) {
            nlohmann::json exact = nlohmann::json::array();
            for (const nlohmann::json& check : cp.checks)
                if (check.at("kind") != "stat" || check.contains("equals")) exact.push_back(check);
            fw::test::check_probes_and_stats(exact, out);
            check_bounds(cp.checks, out);
        });
}
