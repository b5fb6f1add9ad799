// Meshes several labs share: the icosahedron and the icosphere built from it.
//
//   fw::MeshData sphere = fw::icosphere(2);   // 320 triangles, 162 vertices
//
// Both have radius 1 and normals equal to positions; every face runs
// counter-clockwise seen from outside (a front face under glFrontFace(GL_CCW)).
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace fw {

// An indexed triangle list: positions[i] and normals[i] describe vertex i,
// each three consecutive indices one triangle.
struct MeshData {
    std::vector<glm::vec3> positions;
    std::vector<glm::vec3> normals;
    std::vector<uint32_t> indices;
};

// The regular icosahedron on the unit sphere: 12 vertices, 20 faces, 30 edges.
// Vertices 0-11 are (-1, p, 0), (1, p, 0), (-1, -p, 0), (1, -p, 0),
// (0, -1, p), (0, 1, p), (0, -1, -p), (0, 1, -p), (p, 0, -1), (p, 0, 1),
// (-p, 0, -1), (-p, 0, 1), each divided by its length sqrt(1 + p^2), where
// p = (1 + sqrt(5)) / 2 is the golden ratio. Edge 4-5 crosses the +z axis.
MeshData icosahedron();

// The icosahedron subdivided `subdiv` times: every triangle (a, b, c) becomes
// (a, ab, ca), (b, bc, ab), (c, ca, bc), (ab, bc, ca), where ab is the
// midpoint of edge a-b pushed out to the unit sphere, normalize((a + b) / 2).
// A midpoint is one vertex shared by both triangles on its edge, so the mesh
// stays closed: F = 20 * 4^n triangles, E = 30 * 4^n edges,
// V = 10 * 4^n + 2 vertices (V - E + F = 2). Each level keeps the vertices
// of the one before and appends its midpoints. Throws UsageError unless
// 0 <= subdiv <= 8 (level 8 has 1.3 million triangles).
MeshData icosphere(int subdiv);

}  // namespace fw
