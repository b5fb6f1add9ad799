// Lab 12's student numbers: the shadow matrix and the fog factor
// (shadow_math.hpp says what each returns).
#include "shadow_math.hpp"

#include <algorithm>
#include <cmath>

namespace shadows {

glm::mat4 shadow_matrix(glm::vec4 light) {
    // BEGIN SOLUTION
    // STUDENT: (void)light;
    // STUDENT: // TODO: (P . L) I - L P^T with the ground plane P = (0, 1, 0, 0); in GLM
    // STUDENT: // m[c] is column c
    // STUDENT: return glm::mat4(1.0f);
    const glm::vec4 plane(0.0f, 1.0f, 0.0f, 0.0f);
    glm::mat4 m(glm::dot(plane, light));
    for (int c = 0; c < 4; ++c) m[c] -= plane[c] * light;
    return m;
    // END SOLUTION
}

float fog_factor(Fog mode, float d, float start, float end, float density) {
    float f = 1.0f;
    // BEGIN SOLUTION
    // STUDENT: (void)mode, (void)d, (void)start, (void)end, (void)density;
    // STUDENT: // TODO: f for `mode` (shadow_math.hpp), clamped to [0, 1]
    switch (mode) {
        case Fog::None:
            break;
        case Fog::Linear:
            f = (end - d) / (end - start);
            break;
        case Fog::Exp:
            f = std::exp(-density * d);
            break;
        case Fog::Exp2:
            f = std::exp(-(density * d) * (density * d));
            break;
    }
    f = std::clamp(f, 0.0f, 1.0f);
    // END SOLUTION
    return f;
}

}  // namespace shadows
