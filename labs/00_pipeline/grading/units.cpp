// References for lab 0's unit checks (labs/00_pipeline/checkpoints.json).
#include <vector>

#include "grading/units/reference.hpp"

namespace {

// The quad a b c d as the triangles (a, b, c) and (a, c, d): one position per
// index of {0, 1, 2, 0, 2, 3}.
std::vector<glm::vec3> expand_quad(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
    return {a, b, c, a, c, d};
}

}  // namespace

COURSE_REFERENCE(expand_quad, &expand_quad,
                 {grading::vec(3, -10, 10), grading::vec(3, -10, 10), grading::vec(3, -10, 10),
                  grading::vec(3, -10, 10)});
