// Lab 13's bump-mapping numbers: the normal map from the height map and the
// tangent frame of a triangle. Student parts (surface_math.cpp); the lab
// draws with both, and the grader checks both against its own references.
#pragma once

#include <glm/glm.hpp>
#include <vector>

namespace surface_detail {

// A square height map, size x size texels, texel (i, j) at h[j * size + i]
// (i along u, j along v), heights in [0, 1].
struct HeightMap {
    int size = 0;
    std::vector<float> h;
    // Texel (i, j), the indices wrapped into [0, size) (the map repeats).
    float at(int i, int j) const;
};

// The tangent-space normal of every texel, in the order of h: by central
// differences, dh/du = (h(i + 1, j) - h(i - 1, j)) / 2 and dh/dv = (h(i,
// j + 1) - h(i, j - 1)) / 2 (heights per texel, neighbours wrapped), then
// n = normalize(-scale dh/du, -scale dh/dv, 1).
std::vector<glm::vec3> normal_map(const HeightMap& map, float scale);

// The frame of the triangle p0 p1 p2 with texture coordinates uv0 uv1 uv2,
// at a vertex of normal n (unit length): the columns T, B, N of the matrix
// that takes tangent space to the model's. T = dp/du and B = dp/dv solve
// p1 - p0 = du1 T + dv1 B, p2 - p0 = du2 T + dv2 B; then Gram-Schmidt in the
// order N, T, B: T' = normalize(T - (N . T) N), B' = normalize(B - (N . B) N -
// (T' . B) T').
glm::mat3 tangent_frame(glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec2 uv0, glm::vec2 uv1,
                        glm::vec2 uv2, glm::vec3 n);

}  // namespace surface_detail
