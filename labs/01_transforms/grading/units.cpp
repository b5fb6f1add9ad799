// Lab 1 `transforms`: course's references for the student's matrices, from
// GLM's own transform helpers (never the lab's code), and what three usual
// mistakes give, for the report to name them: an axis left unnormalised or
// divided by its length squared, the product in reverse order.
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>

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

// Rodrigues' formula with the axis as given, not normalised: what rotate()
// gives when it forgets to normalise.
glm::mat4 ref_rotate_unnormalised(float degrees, glm::vec3 a) {
    const float c = std::cos(glm::radians(degrees)), s = std::sin(glm::radians(degrees));
    // The cross-product matrix of a, column by column: K v = a x v.
    const glm::mat3 K(0, a.z, -a.y, -a.z, 0, a.x, a.y, -a.x, 0);
    return glm::mat4(c * glm::mat3(1.0f) + (1.0f - c) * glm::outerProduct(a, a) + s * K);
}

// Rodrigues' formula with the axis divided by its length squared: what
// rotate() gives when it divides by dot(axis, axis) to normalise.
glm::mat4 ref_rotate_length_squared(float degrees, glm::vec3 axis) {
    if (axis == glm::vec3(0.0f)) return kIdentity;
    return ref_rotate_unnormalised(degrees, axis / glm::dot(axis, axis));
}

// "compose" takes the order by its name (transforms_math.hpp lists the names
// of the lab's `order` parameter; course uses the names, not the lab's code).
// M is the product left to right (`reversed`: right to left).
glm::mat4 product(float tx, float ty, float angle, float sx, float sy, transforms::Order order,
                  bool reversed) {
    const glm::mat4 T = ref_translate({tx, ty, 0}), R = ref_rotate_z(angle),
                    S = ref_scale({sx, sy, 1});
    glm::mat4 M = kIdentity;
    for (const char* c = fw::choice_name(order); *c; ++c) {
        const glm::mat4& F = *c == 't' ? T : *c == 'r' ? R : S;
        M = reversed ? F * M : M * F;
    }
    return M;
}

glm::mat4 ref_compose(float tx, float ty, float angle, float sx, float sy,
                      transforms::Order order) {
    return product(tx, ty, angle, sx, sy, order, false);
}
glm::mat4 ref_compose_reversed(float tx, float ty, float angle, float sx, float sy,
                               transforms::Order order) {
    return product(tx, ty, angle, sx, sy, order, true);
}

}  // namespace

COURSE_REFERENCE(translate, &ref_translate, {grading::vec(3, -10, 10)})
COURSE_REFERENCE(scale, &ref_scale, {grading::vec(3, -10, 10)})
COURSE_REFERENCE(rotateX, &ref_rotate_x, {grading::degrees(-720, 720)})
COURSE_REFERENCE(rotateY, &ref_rotate_y, {grading::degrees(-720, 720)})
COURSE_REFERENCE(rotateZ, &ref_rotate_z, {grading::degrees(-720, 720)})
COURSE_REFERENCE(rotate, &ref_rotate, {grading::degrees(-720, 720), grading::vec(3, -10, 10)},
                 grading::not_normalised(&ref_rotate_unnormalised),
                 grading::length_squared(&ref_rotate_length_squared))
COURSE_REFERENCE(compose, &ref_compose,
                 {grading::scalar(-2, 2), grading::scalar(-2, 2), grading::degrees(-360, 360),
                  grading::scalar(-3, 3), grading::scalar(-3, 3),
                  grading::choice<transforms::Order>()},
                 grading::reversed_product(&ref_compose_reversed))
