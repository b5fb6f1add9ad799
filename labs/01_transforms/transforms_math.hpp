// Lab 1's matrices, written by hand: the student parts of the lab, kept apart
// from the drawing code so that tests and the grader can call them directly.
//
// Column vectors, as GLSL and GLM store them: a point p becomes M * p, and in
// a product A * B * p the matrix next to p (B) acts first. Angles are degrees;
// positive turns counter-clockwise seen from the axis' positive end.
#pragma once

#include <glm/glm.hpp>
#include <string>

#include "framework/names.hpp"

namespace transforms {

// The values of the `order` parameter, in the order it lists them: the six
// permutations of "trs", each named by its letters (the name compose() takes).
enum class Order { Trs, Tsr, Rts, Rst, Str, Srt };
constexpr fw::Choice<Order> kOrders[] = {{Order::Trs, "trs"}, {Order::Tsr, "tsr"},
                                         {Order::Rts, "rts"}, {Order::Rst, "rst"},
                                         {Order::Str, "str"}, {Order::Srt, "srt"}};

// glm::mat4(...) takes its 16 numbers column by column; from_rows() takes them
// row by row, as a matrix is written on paper and on the slides.
// clang-format off
glm::mat4 from_rows(float m00, float m01, float m02, float m03,
                    float m10, float m11, float m12, float m13,
                    float m20, float m21, float m22, float m23,
                    float m30, float m31, float m32, float m33);
// clang-format on

// Student parts (transforms_math.cpp). None may call glm::translate,
// glm::scale, glm::rotate or anything else from glm/gtc/matrix_transform.hpp.
glm::mat4 translate(glm::vec3 t);
glm::mat4 scale(glm::vec3 s);
glm::mat4 rotateX(float degrees);
glm::mat4 rotateY(float degrees);
glm::mat4 rotateZ(float degrees);
// Rotation about `axis` (any length but zero: it is normalised first). A
// zero axis names no direction to turn about and gives the identity.
glm::mat4 rotate(float degrees, glm::vec3 axis);
// The product, left to right, of the matrices named by `order`, a permutation
// of "trs": compose("trs", T, R, S) = T * R * S. Throws fw::UsageError for
// any other string.
glm::mat4 compose(const std::string& order, const glm::mat4& T, const glm::mat4& R,
                  const glm::mat4& S);

// The lab's model matrix M: compose(the name of `order`, translate(tx, ty, 0),
// rotateZ(angle), scale(sx, sy, 1)). The grader evaluates it as the unit
// function "compose", passing `order` by its name.
glm::mat4 model_matrix(float tx, float ty, float angle, float sx, float sy, Order order);

}  // namespace transforms

// Order's names, for the `order` parameter and for the grader.
template <>
struct fw::ChoicesOf<transforms::Order> {
    static constexpr const auto& list = transforms::kOrders;
};
