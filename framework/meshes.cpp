#include "framework/meshes.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>

#include "framework/error.hpp"

namespace fw {

namespace {

constexpr int kMaxSubdiv = 8;

// Appends vertex `p` (already on the unit sphere); its normal is itself.
uint32_t add_vertex(MeshData& mesh, glm::vec3 p) {
    mesh.positions.push_back(p);
    mesh.normals.push_back(p);
    return static_cast<uint32_t>(mesh.positions.size() - 1);
}

// One level of subdivision. `midpoints` remembers the vertex made for each
// edge (keyed by its two vertex indices, smaller first), so the neighbour
// across the edge reuses it instead of adding a copy.
void subdivide(MeshData& mesh) {
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> midpoints;
    auto midpoint = [&](uint32_t a, uint32_t b) {
        const std::pair<uint32_t, uint32_t> key{std::min(a, b), std::max(a, b)};
        const auto found = midpoints.find(key);
        if (found != midpoints.end()) return found->second;
        const glm::vec3 m = glm::normalize(0.5f * (mesh.positions[a] + mesh.positions[b]));
        return midpoints[key] = add_vertex(mesh, m);
    };
    std::vector<uint32_t> next;
    next.reserve(4 * mesh.indices.size());
    for (size_t t = 0; t < mesh.indices.size(); t += 3) {
        const uint32_t a = mesh.indices[t], b = mesh.indices[t + 1], c = mesh.indices[t + 2];
        const uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
        // Each child keeps its parent's counter-clockwise order.
        next.insert(next.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
    }
    mesh.indices = std::move(next);
}

}  // namespace

MeshData icosahedron() {
    const float p = (1.0f + std::sqrt(5.0f)) / 2.0f;
    const glm::vec3 corners[12] = {{-1, p, 0}, {1, p, 0}, {-1, -p, 0}, {1, -p, 0},
                                   {0, -1, p}, {0, 1, p}, {0, -1, -p}, {0, 1, -p},
                                   {p, 0, -1}, {p, 0, 1}, {-p, 0, -1}, {-p, 0, 1}};
    MeshData mesh;
    for (const glm::vec3& c : corners) add_vertex(mesh, glm::normalize(c));
    // Five faces around vertex 0, the five next to them, five around
    // vertex 3 and the five next to those.
    // clang-format off
    mesh.indices = {0, 11, 5,   0, 5, 1,    0, 1, 7,    0, 7, 10,   0, 10, 11,
                    1, 5, 9,    5, 11, 4,   11, 10, 2,  10, 7, 6,   7, 1, 8,
                    3, 9, 4,    3, 4, 2,    3, 2, 6,    3, 6, 8,    3, 8, 9,
                    4, 9, 5,    2, 4, 11,   6, 2, 10,   8, 6, 7,    9, 8, 1};
    // clang-format on
    return mesh;
}

MeshData icosphere(int subdiv) {
    if (subdiv < 0 || subdiv > kMaxSubdiv)
        throw UsageError("icosphere: subdiv " + std::to_string(subdiv) + " is outside [0, " +
                         std::to_string(kMaxSubdiv) + "]; each level multiplies the 20 " +
                         "triangles by 4");
    MeshData mesh = icosahedron();
    for (int level = 0; level < subdiv; ++level) subdivide(mesh);
    return mesh;
}

}  // namespace fw
