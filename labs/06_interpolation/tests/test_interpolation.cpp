// Lab 6 `interpolation`: the declaration and the scenes triangle and plane.
// Every expectation is computed here from the sheet's numbers
// (labs/06_interpolation/README.md) and the GL spec's interpolation rules,
// never read from a reference image or from the lab's own code.
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "framework/checkpoints.hpp"
#include "interpolation_test.hpp"

using namespace interpolation_test;

namespace {

// scene=triangle: A, B, C in window coordinates, drawn in that order.
const glm::vec2 kTriangle[3] = {to_window({-0.8f, -0.8f, 0, 1}), to_window({0.8f, -0.8f, 0, 1}),
                                to_window({0.0f, 0.8f, 0, 1})};

float cross(glm::vec2 u, glm::vec2 v) { return u.x * v.y - u.y * v.x; }

// Barycentric coordinates of p in the window triangle (a, b, c).
glm::vec3 barycentric(glm::vec2 p, glm::vec2 a, glm::vec2 b, glm::vec2 c) {
    const float area = cross(b - a, c - a);
    return {cross(b - p, c - p) / area, cross(c - p, a - p) / area, cross(a - p, b - p) / area};
}

// The smallest distance in pixels from p to an edge of the window triangle
// (a, b, c); negative outside.
float edge_distance(glm::vec2 p, glm::vec2 a, glm::vec2 b, glm::vec2 c) {
    const glm::vec3 w = barycentric(p, a, b, c);
    const float twice_area = std::fabs(cross(b - a, c - a));
    return glm::min(
        w.x * twice_area / glm::length(c - b),
        glm::min(w.y * twice_area / glm::length(a - c), w.z * twice_area / glm::length(b - a)));
}

// Checks every pixel of the triangle scene whose centre lies at least one
// pixel inside the triangle against `expected(barycentrics)`, and every
// pixel at least one pixel outside against black.
template <class Expected>
void check_triangle_pixels(const fw::Image& img, const char* what, Expected expected) {
    PixelTally inside{what, 2.0f / 255.0f}, outside{"background", 0.0f};
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const glm::vec2 p(x + 0.5f, y + 0.5f);
            const float d = edge_distance(p, kTriangle[0], kTriangle[1], kTriangle[2]);
            if (d >= 1.0f)
                inside.check(x, y,
                             expected(barycentric(p, kTriangle[0], kTriangle[1], kTriangle[2])),
                             rgb(img, x, y));
            else if (d <= -1.0f)
                outside.check(x, y, glm::vec3(0), rgb(img, x, y));
        }
    inside.report();
    outside.report();
    CHECK(inside.tested > 60000);  // the triangle covers 409.6^2 / 2 = 83886 pixels
    CHECK(inside.failed == 0);
    CHECK(outside.failed == 0);
}

// scene=plane: the floor's corners (world), their uv, the triangles.
const glm::vec3 kFloor[4] = {{-2, -1, -4}, {2, -1, -4}, {2, -1, -16}, {-2, -1, -16}};
const glm::vec2 kFloorUv[4] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
const int kFloorTriangles[2][3] = {{0, 1, 2}, {0, 2, 3}};

// How the lab should find the floor's uv at a point of the window; false
// where the floor is not.
enum class Rule { RayCast, Affine, Provoking };

// The plane's camera, once: the inverse of P * V for the ray cast, and the
// floor's corners in window coordinates.
struct PlaneCamera {
    glm::mat4 inverse_clip = glm::inverse(plane_clip());
    glm::vec2 corners[4];
    PlaneCamera() {
        for (int i = 0; i < 4; ++i) corners[i] = to_window(plane_clip() * glm::vec4(kFloor[i], 1));
    }
};
const PlaneCamera& plane_camera() {
    static const PlaneCamera camera;
    return camera;
}

bool floor_uv(Rule rule, glm::vec2 p, glm::vec2& uv) {
    const PlaneCamera& camera = plane_camera();
    if (rule == Rule::RayCast) {
        // Perspective-correct: the uv of the floor point the pixel sees.
        const Ray ray = window_ray(camera.inverse_clip, p);
        if (ray.direction.y >= 0.0f) return false;
        const glm::vec3 hit = ray.origin + (-1.0f - ray.origin.y) / ray.direction.y * ray.direction;
        if (hit.x < -2 || hit.x > 2 || hit.z > -4 || hit.z < -16) return false;
        uv = {(hit.x + 2) / 4, (-hit.z - 4) / 12};
        return true;
    }
    // Affine: screen-space barycentrics of the projected corners; flat: the
    // uv of the triangle's last (provoking) vertex.
    for (const auto& t : kFloorTriangles) {
        const glm::vec3 b =
            barycentric(p, camera.corners[t[0]], camera.corners[t[1]], camera.corners[t[2]]);
        if (b.x < 0 || b.y < 0 || b.z < 0) continue;
        uv = rule == Rule::Provoking
                 ? kFloorUv[t[2]]
                 : b.x * kFloorUv[t[0]] + b.y * kFloorUv[t[1]] + b.z * kFloorUv[t[2]];
        return true;
    }
    return false;
}

int cell(glm::vec2 uv, int checks) {
    return int(std::floor(uv.x * checks) + std::floor(uv.y * checks)) % 2;
}
glm::vec3 cell_color(int c) { return glm::vec3(c == 0 ? 0.9f : 0.1f); }

// The predicted cell of pixel (x, y), or -1 where it is not safely inside
// one: the centre and the points one pixel away in x and y must all be on
// the floor and in the same cell.
int predicted_cell(Rule rule, int x, int y, int checks) {
    int c = -1;
    for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
            glm::vec2 uv;
            if (!floor_uv(rule, {x + 0.5f + dx, y + 0.5f + dy}, uv)) return -1;
            const int here = cell(uv, checks);
            if (c >= 0 && here != c) return -1;
            c = here;
        }
    return c;
}

// Pixels whose colour differs from `rule`'s prediction, of those it predicts.
PixelTally check_plane(const fw::Image& img, Rule rule, int checks, const char* what) {
    PixelTally tally{what, 2.0f / 255.0f};
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const int c = predicted_cell(rule, x, y, checks);
            if (c >= 0) tally.check(x, y, cell_color(c), rgb(img, x, y));
        }
    tally.report();
    return tally;
}

}  // namespace

TEST_CASE("interpolation: the declaration has the sheet's parameters and defaults") {
    const fw::RegisteredLab& lab = fw::test::this_lab();
    const fw::ParamValues p = fw::default_params(lab);
    CHECK(p.text("scene") == "triangle");
    CHECK(p.text("qualifier") == "smooth");
    CHECK(p.color("color_a") == glm::vec3(1, 0, 0));
    CHECK(p.color("color_b") == glm::vec3(1, 1, 1));
    CHECK(p.color("color_c") == glm::vec3(1, 1, 1));
    CHECK(p.integer("checks") == 8);
    CHECK(p.integer("subdiv") == 3);
    CHECK(p.number("light_x") == 2.0f);
    CHECK(p.number("light_y") == 2.0f);
    CHECK(p.number("light_z") == 3.0f);
    for (const fw::Param& param : lab.info.params) {
        INFO("parameter " << param.name);
        CHECK(!param.help_text.empty());
        if (param.type != fw::ParamType::Color) CHECK(param.shortcut != 0);
    }
}

TEST_CASE("interpolation: triangle: the centroid of red, white, white is pink (1, 2/3, 2/3)") {
    Lab lab;
    const fw::RenderOutput out = lab.render({});
    const glm::vec2 centroid = (kTriangle[0] + kTriangle[1] + kTriangle[2]) / 3.0f;
    CHECK(fw::test::probe_rgb(out.color, int(centroid.x), int(centroid.y),
                              {1.0f, 2.0f / 3.0f, 2.0f / 3.0f}, 1.0f / 255.0f));
    CHECK(out.stats["primitives_generated"] == 1);
}

TEST_CASE("interpolation: triangle: every inner pixel is the barycentric mix of the corners") {
    Lab lab;
    struct Colors {
        const char *a, *b, *c;
        glm::vec3 ca, cb, cc;
    };
    const Colors sets[] = {
        {"ff0000", "ffffff", "ffffff", {1, 0, 0}, {1, 1, 1}, {1, 1, 1}},
        {"ff0000", "00ff00", "0000ff", {1, 0, 0}, {0, 1, 0}, {0, 0, 1}},
        {"336699", "ffcc00", "000000", {0.2f, 0.4f, 0.6f}, {1, 0.8f, 0}, {0, 0, 0}}};
    // With the identity matrices every w is 1: smooth and noperspective agree.
    for (const std::string qualifier : {"smooth", "noperspective"})
        for (const Colors& s : sets) {
            const std::string colors = std::string(s.a) + " " + s.b + " " + s.c;
            CAPTURE(qualifier);
            CAPTURE(colors);
            const fw::RenderOutput out = lab.render(
                {{"qualifier", qualifier}, {"color_a", s.a}, {"color_b", s.b}, {"color_c", s.c}});
            check_triangle_pixels(out.color, "barycentric colour", [&](glm::vec3 w) {
                return w.x * s.ca + w.y * s.cb + w.z * s.cc;
            });
        }
}

TEST_CASE("interpolation: triangle: flat shows the provoking vertex C, the last one drawn") {
    Lab lab;
    // A flat input takes its value from the provoking vertex, by default
    // the last vertex of each triangle (GL 4.3, Flatshading).
    for (const std::string c : {"0000ff", "ffffff"}) {
        CAPTURE(c);
        glm::vec3 expected;
        REQUIRE(fw::parse_hex_color(c, expected));
        const fw::RenderOutput out = lab.render(
            {{"qualifier", "flat"}, {"color_a", "ff0000"}, {"color_b", "00ff00"}, {"color_c", c}});
        check_triangle_pixels(out.color, "provoking vertex colour",
                              [&](glm::vec3) { return expected; });
    }
}

TEST_CASE("interpolation: plane: smooth is perspective-correct, as a ray cast sees the floor") {
    Lab lab;
    for (int checks : {8, 5}) {
        CAPTURE(checks);
        const fw::RenderOutput out =
            lab.render({{"scene", "plane"}, {"checks", std::to_string(checks)}});
        const PixelTally cast = check_plane(out.color, Rule::RayCast, checks, "ray cast");
        CHECK(cast.tested > 30000);
        CHECK(cast.failed == 0);
        // The affine prediction differs enough that this test tells them apart.
        CHECK(check_plane(out.color, Rule::Affine, checks, "affine (must differ)").failed > 2000);
        CHECK(out.stats["primitives_generated"] == 2);
    }
}

TEST_CASE("interpolation: plane: noperspective is affine in window coordinates") {
    Lab lab;
    for (int checks : {8, 5}) {
        CAPTURE(checks);
        const fw::RenderOutput out = lab.render({{"scene", "plane"},
                                                 {"qualifier", "noperspective"},
                                                 {"checks", std::to_string(checks)}});
        const PixelTally affine = check_plane(out.color, Rule::Affine, checks, "affine");
        CHECK(affine.tested > 30000);
        CHECK(affine.failed == 0);
        CHECK(check_plane(out.color, Rule::RayCast, checks, "ray cast (must differ)").failed >
              2000);
    }
}

TEST_CASE("interpolation: plane: flat gives each triangle the uv of its last corner") {
    Lab lab;
    // Corner 2 has uv (1, 1), corner 3 (0, 1): with 8 checks both land in
    // light cells (16 and 8 are even); with 3 checks the second triangle is
    // dark (3 is odd).
    for (int checks : {8, 3}) {
        CAPTURE(checks);
        const fw::RenderOutput out = lab.render(
            {{"scene", "plane"}, {"qualifier", "flat"}, {"checks", std::to_string(checks)}});
        const PixelTally flat = check_plane(out.color, Rule::Provoking, checks, "provoking uv");
        CHECK(flat.tested > 30000);
        CHECK(flat.failed == 0);
    }
}

TEST_CASE("interpolation: checkpoints.json: its probes and stats hold for the solution") {
    Lab lab;
    std::vector<std::string> scenes;
    fw::test::for_each_checkpoint(
        lab.lab, lab.renderer, 5,
        [&](const fw::Checkpoint& cp, const fw::ParamValues& params, const fw::RenderOutput& out) {
            scenes.push_back(params.text("scene"));
            fw::test::check_probes_and_stats(cp.checks, out);
        });
    for (const char* scene : {"triangle", "plane", "shading"})
        CHECK(std::count(scenes.begin(), scenes.end(), scene) >= 3);
}
