// Lab 1's student parts: the lecture's transformation matrices, written out
// entry by entry (see README.md for the formulas in this lab's notation).
// Student parts: every function marked TODO.
#include "transforms_math.hpp"

#include <cmath>

#include "framework/error.hpp"

namespace transforms {

namespace {

bool is_order(const std::string& order) {
    for (const fw::Choice<Order>& o : kOrders)
        if (order == o.name) return true;
    return false;
}

}  // namespace

// Matrices below are laid out as on paper, one row per line.
// clang-format off
glm::mat4 from_rows(float m00, float m01, float m02, float m03,
                    float m10, float m11, float m12, float m13,
                    float m20, float m21, float m22, float m23,
                    float m30, float m31, float m32, float m33) {
    // GLM indexes m[column][row]: each glm::vec4 below is one column.
    return glm::mat4(glm::vec4(m00, m10, m20, m30), glm::vec4(m01, m11, m21, m31),
                     glm::vec4(m02, m12, m22, m32), glm::vec4(m03, m13, m23, m33));
}

// The translation lives in the last column; it reaches a point because the
// point's w is 1 (a direction, w = 0, is not moved).
glm::mat4 translate(glm::vec3 t) {
    // BEGIN SOLUTION
    // STUDENT: (void)t;  // TODO: the identity with t in the last column (from_rows)
    // STUDENT: return glm::mat4(1.0f);
    return from_rows(1, 0, 0, t.x,
                     0, 1, 0, t.y,
                     0, 0, 1, t.z,
                     0, 0, 0, 1);
    // END SOLUTION
}

glm::mat4 scale(glm::vec3 s) {
    // BEGIN SOLUTION
    // STUDENT: (void)s;  // TODO: s.x, s.y, s.z on the diagonal, 1 in the corner
    // STUDENT: return glm::mat4(1.0f);
    return from_rows(s.x, 0, 0, 0,
                     0, s.y, 0, 0,
                     0, 0, s.z, 0,
                     0, 0, 0, 1);
    // END SOLUTION
}

// Each rotation about a coordinate axis leaves that axis' row and column
// alone and turns the other two coordinates as in 2D: y -> z for X, z -> x
// for Y, x -> y for Z (counter-clockwise seen from the axis' positive end).
glm::mat4 rotateX(float degrees) {
    // BEGIN SOLUTION
    // STUDENT: (void)degrees;  // TODO: turn y towards z
    // STUDENT: return glm::mat4(1.0f);
    const float c = std::cos(glm::radians(degrees)), s = std::sin(glm::radians(degrees));
    return from_rows(1, 0, 0, 0,
                     0, c, -s, 0,
                     0, s, c, 0,
                     0, 0, 0, 1);
    // END SOLUTION
}

glm::mat4 rotateY(float degrees) {
    // BEGIN SOLUTION
    // STUDENT: (void)degrees;  // TODO: turn z towards x (mind the sign of sin)
    // STUDENT: return glm::mat4(1.0f);
    const float c = std::cos(glm::radians(degrees)), s = std::sin(glm::radians(degrees));
    return from_rows(c, 0, s, 0,
                     0, 1, 0, 0,
                     -s, 0, c, 0,
                     0, 0, 0, 1);
    // END SOLUTION
}

glm::mat4 rotateZ(float degrees) {
    // BEGIN SOLUTION
    // STUDENT: (void)degrees;  // TODO: turn x towards y
    // STUDENT: return glm::mat4(1.0f);
    const float c = std::cos(glm::radians(degrees)), s = std::sin(glm::radians(degrees));
    return from_rows(c, -s, 0, 0,
                     s, c, 0, 0,
                     0, 0, 1, 0,
                     0, 0, 0, 1);
    // END SOLUTION
}

// Rodrigues: with a = (x, y, z) the unit axis, c = cos, s = sin,
//   R = c I + (1 - c) a a^T + s [a]x,   [a]x = | 0 -z  y |
//                                               | z  0 -x |
//                                               |-y  x  0 |
// ([a]x v = a x v). rotate(d, (0,0,1)) must equal rotateZ(d), and so on.
glm::mat4 rotate(float degrees, glm::vec3 axis) {
    // BEGIN SOLUTION
    // STUDENT: (void)degrees;  // TODO: normalise axis (a zero axis: the identity), then Rodrigues
    // STUDENT: (void)axis;
    // STUDENT: return glm::mat4(1.0f);
    const float length = std::sqrt(axis.x * axis.x + axis.y * axis.y + axis.z * axis.z);
    if (length == 0.0f) return glm::mat4(1.0f);
    const float x = axis.x / length, y = axis.y / length, z = axis.z / length;
    const float c = std::cos(glm::radians(degrees)), s = std::sin(glm::radians(degrees));
    const float k = 1.0f - c;
    return from_rows(c + k * x * x, k * x * y - s * z, k * x * z + s * y, 0,
                     k * y * x + s * z, c + k * y * y, k * y * z - s * x, 0,
                     k * z * x - s * y, k * z * y + s * x, c + k * z * z, 0,
                     0, 0, 0, 1);
    // END SOLUTION
}

// clang-format on

glm::mat4 compose(const std::string& order, const glm::mat4& T, const glm::mat4& R,
                  const glm::mat4& S) {
    if (!is_order(order))
        throw fw::UsageError("compose: order '" + order +
                             "' is not a permutation of \"trs\"; use one of trs, tsr, rts, "
                             "rst, str, srt");
    // BEGIN SOLUTION
    // STUDENT: (void)T;  // TODO: M = the named matrices multiplied left to right
    // STUDENT: (void)R;
    // STUDENT: (void)S;
    // STUDENT: return glm::mat4(1.0f);
    glm::mat4 M(1.0f);
    for (char name : order) M = M * (name == 't' ? T : name == 'r' ? R : S);
    return M;
    // END SOLUTION
}

glm::mat4 model_matrix(float tx, float ty, float angle, float sx, float sy, Order order) {
    return compose(fw::choice_name(order), translate({tx, ty, 0.0f}), rotateZ(angle),
                   scale({sx, sy, 1.0f}));
}

}  // namespace transforms
