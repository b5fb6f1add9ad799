// Lab 10's cube and its adjacency (silhouette.hpp); the student part is
// adjacency_indices().
#include "silhouette.hpp"

#include <map>
#include <utility>

namespace advanced_geometry {

std::vector<glm::vec3> cube_corners() {
    std::vector<glm::vec3> out;
    for (int i = 0; i < 8; ++i)
        out.emplace_back(i & 1 ? 0.5f : -0.5f, i & 2 ? 0.5f : -0.5f, i & 4 ? 0.5f : -0.5f);
    return out;
}

std::vector<std::uint32_t> cube_triangles() {
    return {4, 6, 2, 4, 2, 0, 1, 3, 7, 1, 7, 5, 1, 5, 4, 1, 4, 0,
            2, 6, 7, 2, 7, 3, 2, 3, 1, 2, 1, 0, 4, 5, 7, 4, 7, 6};
}

std::vector<std::uint32_t> adjacency_indices(const std::vector<std::uint32_t>& triangles) {
    // Every triangle of a consistently wound mesh runs along each of its
    // edges in one direction, and its neighbour along the same edge in the
    // other: the neighbour across a -> b is the triangle with the edge b -> a.
    // BEGIN SOLUTION
    // STUDENT: std::vector<std::uint32_t> out;  // TODO: a, x_ab, b, x_bc, c, x_ca per triangle
    // STUDENT: for (std::uint32_t i : triangles) out.insert(out.end(), {i, i});
    // STUDENT: return out;
    // The third corner of the triangle with directed edge (from, to).
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> third;
    for (std::size_t t = 0; t + 2 < triangles.size(); t += 3)
        for (std::size_t e = 0; e < 3; ++e)
            third[{triangles[t + e], triangles[t + (e + 1) % 3]}] = triangles[t + (e + 2) % 3];
    std::vector<std::uint32_t> out;
    for (std::size_t t = 0; t + 2 < triangles.size(); t += 3)
        for (std::size_t e = 0; e < 3; ++e) {
            const std::uint32_t a = triangles[t + e], b = triangles[t + (e + 1) % 3];
            const auto across = third.find({b, a});
            out.push_back(a);
            out.push_back(across != third.end() ? across->second : triangles[t + (e + 2) % 3]);
        }
    return out;
    // END SOLUTION
}

}  // namespace advanced_geometry
