// Lab 10 `advanced-geometry`: the faces' views against table 8.19 and the
// cube map unfolded, the adjacency list against a search of the mesh, and
// the cube's outline, against the sheet's closed forms
// (labs/10_advanced_geometry/README.md), computed here from its numbers.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "layers.hpp"
#include "silhouette.hpp"
#include "tests/support/test_support.hpp"

namespace {

using Lab = fw::test::LabUnderTest;
using fw::test::near;
using fw::test::rgb_at;
constexpr double kPi = 3.14159265358979323846;

// Table 8.19 read backwards: the direction of face f at (s, t).
glm::dvec3 face_direction(int f, double s, double t) {
    const double sc = 2.0 * s - 1.0, tc = 2.0 * t - 1.0;
    const glm::dvec3 d[6] = {{1, -tc, -sc}, {-1, -tc, sc}, {sc, 1, tc},
                             {sc, -1, -tc}, {sc, -tc, 1},  {-sc, -tc, -1}};
    return d[f];
}

// What the cube map shows along d: a marker (the squares |other| <= 0.5 at
// distance 1) in its colour, else the wall 0.2 + 0.2 d / |d|. `edge` is how
// far, in units of the face's [-1, 1], d is from a marker's border.
glm::vec3 world_color(glm::dvec3 d, double& edge) {
    const glm::dvec3 a = glm::abs(d);
    const int k = a.x >= a.y && a.x >= a.z ? 0 : a.y >= a.z ? 1 : 2;
    const double u = a[(k + 1) % 3] / a[k], v = a[(k + 2) % 3] / a[k];
    edge = std::fabs(std::max(u, v) - 0.5);
    if (std::max(u, v) < 0.5) {
        glm::vec3 c(d[k] > 0 ? 0.2f : 1.0f);
        c[k] = d[k] > 0 ? 1.0f : 0.2f;
        return c;
    }
    return glm::vec3(0.2 + 0.2 * glm::normalize(d));
}

// The cube turned by rotateX(pitch) rotateY(yaw), corner i in the window.
std::vector<glm::dvec2> cube_in_window(double yaw, double pitch) {
    const double y = yaw * kPi / 180.0, p = pitch * kPi / 180.0;
    std::vector<glm::dvec2> out;
    for (const glm::vec3& c : advanced_geometry::cube_corners()) {
        const double x1 = std::cos(y) * c.x + std::sin(y) * c.z;
        const double z1 = -std::sin(y) * c.x + std::cos(y) * c.z;
        const double y2 = std::cos(p) * c.y - std::sin(p) * z1;
        out.push_back(glm::dvec2(204.8 * x1 + 256.0, 204.8 * y2 + 256.0));
    }
    return out;
}

double area(glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
    return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

const glm::vec3 kOutline(1.0f, 0.85f, 0.2f);

}  // namespace

TEST_CASE("advanced-geometry: layers: each face's view is table 8.19's, drawn into its face") {
    for (int f = 0; f < 6; ++f) {
        INFO("face " << f);
        const glm::dmat4 view(advanced_geometry::cube_face_view(f));
        // The view takes the face's s direction to +x, t to +y and its axis to -z.
        const glm::dvec3 centre = face_direction(f, 0.5, 0.5);
        const glm::dvec3 s = face_direction(f, 1.0, 0.5) - centre;
        const glm::dvec3 t = face_direction(f, 0.5, 1.0) - centre;
        CHECK(glm::length(glm::dvec3(view * glm::dvec4(s, 0.0)) - glm::dvec3(1, 0, 0)) < 1e-6);
        CHECK(glm::length(glm::dvec3(view * glm::dvec4(t, 0.0)) - glm::dvec3(0, 1, 0)) < 1e-6);
        CHECK(glm::length(glm::dvec3(view * glm::dvec4(centre, 1.0)) - glm::dvec3(0, 0, -1)) <
              1e-6);
    }
    const glm::ivec2 cells[6] = {{256, 192}, {0, 192},   {128, 320},
                                 {128, 64},  {128, 192}, {384, 192}};
    Lab lab;
    for (const int size : {128, 32, 64}) {
        INFO("face_size " << size);
        const fw::RenderOutput out =
            lab.render({{"scene", "layers"}, {"face_size", std::to_string(size)}});
        CHECK(out.stats["primitives_generated"] == 156);
        int checked = 0, off = 0;
        for (int f = 0; f < 6; ++f)
            for (int y = 2; y < 128; y += 4)
                for (int x = 2; x < 128; x += 4) {
                    double edge = 0.0;
                    const glm::vec3 want =
                        world_color(face_direction(f, (x + 0.5) / 128.0, (y + 0.5) / 128.0), edge);
                    // Clear of a marker's border by two of the face's texels.
                    if (edge < 4.0 / size) continue;
                    ++checked;
                    const glm::vec3 seen = rgb_at(out.color, cells[f].x + x, cells[f].y + y);
                    off += near(seen, want, size == 128 ? 0.01f : 0.02f) ? 0 : 1;
                }
        MESSAGE(checked << " pixels of the cross checked, " << off << " off");
        CHECK(checked > 4000);
        CHECK(off == 0);
        CHECK(near(rgb_at(out.color, 64, 64), glm::vec3(0.0f), 0.0f));
        CHECK(near(rgb_at(out.color, 448, 448), glm::vec3(0.0f), 0.0f));
    }
}

TEST_CASE("advanced-geometry: adjacency: each edge's far corner, a border's own third corner") {
    using advanced_geometry::adjacency_indices;
    const std::vector<std::uint32_t> cube = advanced_geometry::cube_triangles();
    const std::vector<std::uint32_t> adjacency = adjacency_indices(cube);
    REQUIRE(adjacency.size() == 2 * cube.size());
    for (std::size_t t = 0; t < cube.size(); t += 3)
        for (std::size_t e = 0; e < 3; ++e) {
            const std::uint32_t a = cube[t + e], b = cube[t + (e + 1) % 3];
            INFO("triangle " << t / 3 << ", edge " << a << "-" << b);
            CHECK(adjacency[2 * (t + e)] == a);
            // The one other triangle with the edge b -> a, and its third corner.
            int found = 0;
            for (std::size_t u = 0; u < cube.size(); u += 3)
                for (std::size_t k = 0; k < 3; ++k)
                    if (cube[u + k] == b && cube[u + (k + 1) % 3] == a) {
                        ++found;
                        CHECK(adjacency[2 * (t + e) + 1] == cube[u + (k + 2) % 3]);
                    }
            CHECK(found == 1);
        }
    // Two triangles sharing the edge 1-2: every other edge is a border.
    CHECK(adjacency_indices({0, 1, 2, 2, 1, 3}) ==
          std::vector<std::uint32_t>{0, 2, 1, 3, 2, 1, 2, 0, 1, 2, 3, 1});
}

TEST_CASE("advanced-geometry: silhouette: the six outline edges drawn, nothing else") {
    Lab lab;
    const std::vector<std::uint32_t> cube = advanced_geometry::cube_triangles();
    for (const auto& [yaw, pitch] :
         std::vector<std::pair<double, double>>{{30, 25}, {-50, -35}, {120, 40}, {-160, -15}}) {
        INFO("yaw " << yaw << ", pitch " << pitch);
        const fw::RenderOutput out = lab.render({{"scene", "silhouette"},
                                                 {"yaw", std::to_string(yaw)},
                                                 {"pitch", std::to_string(pitch)}});
        const std::vector<glm::dvec2> w = cube_in_window(yaw, pitch);
        // The outline: edges of a front triangle (counter-clockwise in the
        // window) whose neighbour is not.
        std::vector<std::pair<glm::dvec2, glm::dvec2>> edges;
        for (std::size_t t = 0; t < cube.size(); t += 3) {
            if (area(w[cube[t]], w[cube[t + 1]], w[cube[t + 2]]) <= 0.0) continue;
            for (std::size_t u = 0; u < cube.size(); u += 3)
                for (std::size_t e = 0; e < 3; ++e)
                    for (std::size_t k = 0; k < 3; ++k)
                        if (cube[u + k] == cube[t + (e + 1) % 3] &&
                            cube[u + (k + 1) % 3] == cube[t + e] &&
                            area(w[cube[u]], w[cube[u + 1]], w[cube[u + 2]]) <= 0.0)
                            edges.push_back({w[cube[t + e]], w[cube[t + (e + 1) % 3]]});
        }
        REQUIRE(edges.size() == 6);
        CHECK(out.stats["primitives_generated"] == 12 + 6);
        // Along each edge, a pixel of the outline's colour within one pixel.
        double length = 0.0;
        int missed = 0;
        for (const auto& [a, b] : edges) {
            length += std::max(std::fabs(b.x - a.x), std::fabs(b.y - a.y));
            for (double f = 0.1; f < 0.95; f += 0.05) {
                const glm::dvec2 q = a + f * (b - a);
                bool seen = false;
                for (int dy = -1; dy <= 1; ++dy)
                    for (int dx = -1; dx <= 1; ++dx)
                        seen = seen || near(rgb_at(out.color, int(q.x) + dx, int(q.y) + dy),
                                            kOutline, 0.01f);
                missed += seen ? 0 : 1;
            }
        }
        int outline = 0;
        for (int y = 0; y < 512; ++y)
            for (int x = 0; x < 512; ++x) outline += near(rgb_at(out.color, x, y), kOutline, 0.01f);
        MESSAGE(outline << " outline pixels for 6 lines of " << length << " pixels along");
        CHECK(missed == 0);
        // A line is a pixel a step along its major axis, ends shared.
        CHECK(std::fabs(outline - length) < 12.0);
    }
}
