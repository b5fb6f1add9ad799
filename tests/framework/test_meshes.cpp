// The shared icosahedron and icosphere (framework/meshes.hpp). Expected
// counts come from the closed forms F = 20 * 4^n, E = 30 * 4^n,
// V = 10 * 4^n + 2; geometry is checked against the unit sphere.
#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>

#include "framework/error.hpp"
#include "framework/meshes.hpp"
#include "tests/support/test_support.hpp"

namespace {

long power_of_4(int n) { return 1L << (2 * n); }

// Each undirected edge -> how often it is walked a -> b with a < b (first)
// and b -> a (second).
std::map<std::pair<uint32_t, uint32_t>, std::pair<int, int>> edge_uses(const fw::MeshData& m) {
    std::map<std::pair<uint32_t, uint32_t>, std::pair<int, int>> edges;
    for (size_t t = 0; t < m.indices.size(); t += 3)
        for (int k = 0; k < 3; ++k) {
            const uint32_t a = m.indices[t + k], b = m.indices[t + (k + 1) % 3];
            auto& uses = edges[{std::min(a, b), std::max(a, b)}];
            (a < b ? uses.first : uses.second) += 1;
        }
    return edges;
}

}  // namespace

TEST_CASE("meshes: the icosahedron has 12 unit vertices, 20 faces and 30 equal edges") {
    const fw::MeshData m = fw::icosahedron();
    CHECK(m.positions.size() == 12);
    CHECK(m.normals.size() == 12);
    CHECK(m.indices.size() == 60);
    // Corners (0, +-1, +-p) / sqrt(1 + p^2): neighbours are 2 / sqrt(1 + p^2) apart.
    const double p = (1.0 + std::sqrt(5.0)) / 2.0;
    const double edge = 2.0 / std::sqrt(1.0 + p * p);
    for (size_t t = 0; t < m.indices.size(); t += 3)
        for (int k = 0; k < 3; ++k) {
            const glm::vec3 a = m.positions[m.indices[t + k]];
            const glm::vec3 b = m.positions[m.indices[t + (k + 1) % 3]];
            INFO("triangle " << t / 3 << " edge " << k << ": expected length " << edge
                             << " observed " << glm::length(a - b));
            CHECK(std::abs(glm::length(a - b) - edge) < 1e-5);
        }
    // The sheet of lab 4 relies on edge 4-5 crossing the +z axis.
    const glm::vec3 mid = 0.5f * (m.positions[4] + m.positions[5]);
    CHECK(std::abs(mid.x) < 1e-6f);
    CHECK(std::abs(mid.y) < 1e-6f);
    CHECK(mid.z > 0.8f);
    CHECK(edge_uses(m).count({4, 5}) == 1);
}

TEST_CASE("meshes: icosphere(0) is the icosahedron") {
    const fw::MeshData a = fw::icosahedron(), b = fw::icosphere(0);
    CHECK(a.positions == b.positions);
    CHECK(a.normals == b.normals);
    CHECK(a.indices == b.indices);
}

TEST_CASE("meshes: icosphere counts, unit sphere, outward CCW faces, closed surface") {
    for (int n = 0; n <= 5; ++n) {
        CAPTURE(n);
        const fw::MeshData m = fw::icosphere(n);
        const long expected_f = 20 * power_of_4(n), expected_e = 30 * power_of_4(n);
        const long expected_v = 10 * power_of_4(n) + 2;
        const long v = static_cast<long>(m.positions.size());
        const long f = static_cast<long>(m.indices.size() / 3);
        INFO("expected V " << expected_v << " F " << expected_f << "; observed V " << v << " F "
                           << f);
        CHECK(m.indices.size() % 3 == 0);
        CHECK(f == expected_f);
        CHECK(v == expected_v);
        CHECK(m.normals.size() == m.positions.size());

        int off_sphere = 0, normal_mismatch = 0;
        for (size_t i = 0; i < m.positions.size(); ++i) {
            off_sphere += std::abs(glm::length(m.positions[i]) - 1.0f) > 1e-6f;
            normal_mismatch += m.normals[i] != m.positions[i];
        }
        CHECK(off_sphere == 0);
        CHECK(normal_mismatch == 0);

        // Outward: the face normal cross(b - a, c - a) of a counter-clockwise
        // face points away from the centre, the same way as its centroid.
        int inward = 0, bad_index = 0;
        for (size_t t = 0; t < m.indices.size(); t += 3) {
            if (m.indices[t] >= v || m.indices[t + 1] >= v || m.indices[t + 2] >= v) {
                ++bad_index;
                continue;
            }
            const glm::vec3 a = m.positions[m.indices[t]], b = m.positions[m.indices[t + 1]],
                            c = m.positions[m.indices[t + 2]];
            inward += glm::dot(glm::cross(b - a, c - a), a + b + c) <= 0.0f;
        }
        CHECK(bad_index == 0);
        CHECK(inward == 0);

        // Closed and consistently oriented: every edge is walked exactly once
        // in each direction by the two triangles that share it.
        const auto edges = edge_uses(m);
        int not_manifold = 0;
        for (const auto& [edge, uses] : edges) not_manifold += uses != std::make_pair(1, 1);
        CHECK(not_manifold == 0);
        const long e = static_cast<long>(edges.size());
        INFO("expected E " << expected_e << " observed " << e);
        CHECK(e == expected_e);
        CHECK(v - e + f == 2);
    }
}

TEST_CASE("meshes: each subdivision keeps the previous vertices and halves the edges") {
    const fw::MeshData coarse = fw::icosphere(1), fine = fw::icosphere(2);
    REQUIRE(fine.positions.size() > coarse.positions.size());
    for (size_t i = 0; i < coarse.positions.size(); ++i)
        CHECK(fine.positions[i] == coarse.positions[i]);
    // A midpoint of an icosahedron edge lies on the sphere halfway (in angle)
    // between its ends: the arc of each half is half the arc of the edge.
    const fw::MeshData ico = fw::icosahedron();
    const float full = std::acos(glm::dot(ico.positions[4], ico.positions[5]));
    const glm::vec3 z = coarse.positions[12];  // some midpoint of level 1
    float best = 4.0f;
    for (int i = 0; i < 12; ++i) best = std::min(best, std::acos(glm::dot(z, ico.positions[i])));
    CHECK(std::abs(best - 0.5f * full) < 1e-5f);
}

TEST_CASE("meshes: icosphere names the bad subdivision level and the valid range") {
    for (int bad : {-1, 9}) {
        const std::string message = fw::test::thrown<fw::UsageError>([&] { fw::icosphere(bad); });
        fw::test::check_mentions(message, {"icosphere", "subdiv " + std::to_string(bad), "[0, 8]"});
    }
}
