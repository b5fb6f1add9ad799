// Lab 1 `transforms`: course's references for the student's matrices, from
// GLM's own transform helpers (never the lab's code).
#include <glm/gtc/matrix_transform.hpp>

#include "framework/error.hpp"
#include "grading/units/reference.hpp"
#include "transforms_math.hpp"

namespace {

const glm::mat4 kIdentity(1.0f);

glm::mat4 ref_translate(glm::vec3 t) { return glm::translate(kIdentity, t); }
glm::mat4 ref_scale(glm::vec3 s) { return glm::scale(kIdentity, s); }
glm::mat4 ref_rotate_x(float degrees) {
    return glm::rotate(kIdentity, glm::radians(degrees), {1, 0, 0});
}
glm::mat4 ref_rotate_y(float degrees) {
    return glm::rotate(kIdentity, glm::radians(degrees), {0, 1, 0});
}
glm::mat4 ref_rotate_z(float degrees) {
    return glm::rotate(kIdentity, glm::radians(degrees), {0, 0, 1});
}

// The lab's README: a zero axis names no direction and gives the identity
// (glm::rotate would divide by its zero length).
glm::mat4 ref_rotate(float degrees, glm::vec3 axis) {
    if (axis == glm::vec3(0.0f)) return kIdentity;
    return glm::rotate(kIdentity, glm::radians(degrees), axis);
}

// "compose" takes an index into kOrders (transforms_math.hpp: the names of
// the lab's `order` parameter; course uses the names, not the lab's code).
// M is the product left to right.

glm::mat4 ref_compose(float tx, float ty, float angle, float sx, float sy, int order) {
    if (order < 0 || order >= transforms::kOrderCount)
        throw fw::Error("compose: order index " + std::to_string(order) + " is not in 0..5");
    const glm::mat4 T = ref_translate({tx, ty, 0}), R = ref_rotate_z(angle),
                    S = ref_scale({sx, sy, 1});
    glm::mat4 M = kIdentity;
    for (const char* c = transforms::kOrders[order]; *c; ++c)
        M = M * (*c == 't' ? T : *c == 'r' ? R : S);
    return M;
}

}  // namespace

COURSE_REFERENCE(translate, &ref_translate, {grading::vec(3, -10, 10)})
COURSE_REFERENCE(scale, &ref_scale, {grading::vec(3, -10, 10)})
COURSE_REFERENCE(rotateX, &ref_rotate_x, {grading::scalar(-720, 720)})
COURSE_REFERENCE(rotateY, &ref_rotate_y, {grading::scalar(-720, 720)})
COURSE_REFERENCE(rotateZ, &ref_rotate_z, {grading::scalar(-720, 720)})
COURSE_REFERENCE(rotate, &ref_rotate, {grading::scalar(-720, 720), grading::vec(3, -10, 10)})
COURSE_REFERENCE(compose, &ref_compose,
                 {grading::scalar(-2, 2), grading::scalar(-2, 2), grading::scalar(-360, 360),
                  grading::scalar(-3, 3), grading::scalar(-3, 3), grading::integer(0, 5)})
