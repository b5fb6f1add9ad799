// Lab 10's silhouette: the cube as an indexed triangle list, and the index
// list GL_TRIANGLES_ADJACENCY reads (adjacency_indices, a student part, in
// silhouette.cpp).
#pragma once

#include <cstdint>
#include <glm/glm.hpp>
#include <vector>

namespace advanced_geometry {

// The cube of side 1 around the origin: corner i is (x, y, z) with x = +0.5
// when bit 0 of i is set and -0.5 when not, y by bit 1, z by bit 2; its 12
// triangles, each counter-clockwise seen from outside, two per face:
//   -x (4, 6, 2) (4, 2, 0)   +x (1, 3, 7) (1, 7, 5)   -y (1, 5, 4) (1, 4, 0)
//   +y (2, 6, 7) (2, 7, 3)   -z (2, 3, 1) (2, 1, 0)   +z (4, 5, 7) (4, 7, 6)
std::vector<glm::vec3> cube_corners();
std::vector<std::uint32_t> cube_triangles();

// For each triangle (a, b, c) of `triangles` (three indices each, a closed
// or open mesh wound consistently), six indices: a, x_ab, b, x_bc, c, x_ca,
// where x_ab is the corner of the other triangle on edge a-b that is not on
// that edge (the triangle that runs from b to a). An edge no other triangle
// shares takes the triangle's own third corner (c for a-b): the "neighbour"
// then faces the other way, so a border always counts as outline.
std::vector<std::uint32_t> adjacency_indices(const std::vector<std::uint32_t>& triangles);

}  // namespace advanced_geometry
