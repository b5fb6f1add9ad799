// Lab 12 `shadows`: the course's references for the student's shadow matrix
// and fog factor, written from the sheet's formulas, never from the lab's code.
#include <cmath>

#include "grading/units/reference.hpp"
#include "shadow_math.hpp"

namespace {

// The ray from the light through p meets the plane P . x = 0 where the
// homogeneous M p = (P . L) p - (P . p) L is; here P = (0, 1, 0, 0).
glm::mat4 ref_shadow_matrix(glm::vec4 light) {
    const double plane[4] = {0.0, 1.0, 0.0, 0.0};
    double dot = 0.0;
    for (int i = 0; i < 4; ++i) dot += plane[i] * light[i];
    glm::mat4 m(0.0f);
    for (int column = 0; column < 4; ++column)
        for (int row = 0; row < 4; ++row)
            m[column][row] =
                static_cast<float>((row == column ? dot : 0.0) - light[row] * plane[column]);
    return m;
}

float ref_fog_factor(shadows::Fog mode, float d, float start, float end, float density) {
    double f = 1.0;
    const double k = double(density) * d;
    if (mode == shadows::Fog::Linear) f = (double(end) - d) / (double(end) - start);
    if (mode == shadows::Fog::Exp) f = std::exp(-k);
    if (mode == shadows::Fog::Exp2) f = std::exp(-k * k);
    return static_cast<float>(std::fmin(1.0, std::fmax(0.0, f)));
}

}  // namespace

COURSE_REFERENCE(shadow_matrix, &ref_shadow_matrix, {grading::vec(4, -10, 10)})
COURSE_REFERENCE(fog_factor, &ref_fog_factor,
                 {grading::choice<shadows::Fog>(), grading::scalar(0, 20), grading::scalar(0, 5),
                  grading::scalar(6, 20), grading::scalar(0, 1)})
