// Lab 13's student numbers: the normal map by central differences and the
// tangent frame from the UVs (surface_math.hpp says what each returns).
#include "surface_math.hpp"

namespace surface_detail {

float HeightMap::at(int i, int j) const {
    const int wi = ((i % size) + size) % size, wj = ((j % size) + size) % size;
    return h[static_cast<size_t>(wj * size + wi)];
}

std::vector<glm::vec3> normal_map(const HeightMap& map, float scale) {
    std::vector<glm::vec3> normals(map.h.size(), glm::vec3(0.0f, 0.0f, 1.0f));
    for (int j = 0; j < map.size; ++j)
        for (int i = 0; i < map.size; ++i) {
            glm::vec3& n = normals[static_cast<size_t>(j * map.size + i)];
            // BEGIN SOLUTION
            // STUDENT: (void)scale, (void)n;  // TODO: n from the central differences of
            // STUDENT: // map.at() around (i, j), times -scale (surface_math.hpp)
            const float dh_du = (map.at(i + 1, j) - map.at(i - 1, j)) / 2.0f;
            const float dh_dv = (map.at(i, j + 1) - map.at(i, j - 1)) / 2.0f;
            n = glm::normalize(glm::vec3(-scale * dh_du, -scale * dh_dv, 1.0f));
            // END SOLUTION
        }
    return normals;
}

glm::mat3 tangent_frame(glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec2 uv0, glm::vec2 uv1,
                        glm::vec2 uv2, glm::vec3 n) {
    const glm::vec3 e1 = p1 - p0, e2 = p2 - p0;
    const glm::vec2 d1 = uv1 - uv0, d2 = uv2 - uv0;
    glm::vec3 t(1.0f, 0.0f, 0.0f), b(0.0f, 1.0f, 0.0f);
    // BEGIN SOLUTION
    // STUDENT: (void)e1, (void)e2, (void)d1, (void)d2;
    // STUDENT: // TODO: solve the two edge equations for T and B (Cramer's rule), then
    // STUDENT: // Gram-Schmidt against n in the order N, T, B
    const float r = 1.0f / (d1.x * d2.y - d2.x * d1.y);
    t = (e1 * d2.y - e2 * d1.y) * r;
    b = (e2 * d1.x - e1 * d2.x) * r;
    t = glm::normalize(t - glm::dot(n, t) * n);
    b = glm::normalize(b - glm::dot(n, b) * n - glm::dot(t, b) * t);
    // END SOLUTION
    return glm::mat3(t, b, n);
}

}  // namespace surface_detail
