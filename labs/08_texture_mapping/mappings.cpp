// Lab 8's student mappings and level of detail (mappings.hpp says what each
// returns).
#include "mappings.hpp"

#include <algorithm>
#include <cmath>
#include <glm/gtc/constants.hpp>

namespace texture_mapping {

glm::vec2 planar(glm::vec3 p) {
    // BEGIN SOLUTION
    // STUDENT: (void)p;
    // STUDENT: return glm::vec2(0.0f);  // TODO: (0.5 x + 0.5, 0.5 y + 0.5)
    return 0.5f * glm::vec2(p.x, p.y) + 0.5f;
    // END SOLUTION
}

glm::vec2 cylindrical(glm::vec3 p) {
    // BEGIN SOLUTION
    // STUDENT: (void)p;
    // STUDENT: return glm::vec2(0.0f);  // TODO: (atan2(x, z) / (2 pi) + 0.5, 0.5 y + 0.5)
    return {std::atan2(p.x, p.z) / glm::two_pi<float>() + 0.5f, 0.5f * p.y + 0.5f};
    // END SOLUTION
}

glm::vec2 spherical(glm::vec3 p) {
    // BEGIN SOLUTION
    // STUDENT: (void)p;
    // STUDENT: // TODO: (atan2(x, z) / (2 pi) + 0.5, asin(y / |p|) / pi + 0.5)
    // STUDENT: return glm::vec2(0.0f);
    const float r = glm::length(p);
    if (r == 0.0f) return glm::vec2(0.5f);
    return {std::atan2(p.x, p.z) / glm::two_pi<float>() + 0.5f,
            std::asin(std::clamp(p.y / r, -1.0f, 1.0f)) / glm::pi<float>() + 0.5f};
    // END SOLUTION
}

float level_of_detail(glm::vec2 d_dx, glm::vec2 d_dy, int width, int height) {
    const glm::vec2 size(static_cast<float>(width), static_cast<float>(height));
    // BEGIN SOLUTION
    // STUDENT: (void)d_dx, (void)d_dy, (void)size;
    // STUDENT: return 0.0f;  // TODO: log2 of the longer side of the pixel in texels
    const float rho = std::max(glm::length(d_dx * size), glm::length(d_dy * size));
    return std::log2(rho);
    // END SOLUTION
}

}  // namespace texture_mapping
