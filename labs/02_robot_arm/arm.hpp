// Lab 2's hierarchy: the matrices that place each part of the robot arm.
// The parts are designed at the origin (README.md); these matrices move them
// into the world. Column vectors: a part's point p lands at M * p.
#pragma once

#include <cstddef>
#include <glm/glm.hpp>
#include <vector>

namespace robot_arm {

// Given helpers, 4x4 with column vectors (GLM underneath).
// translate(x, y): moves by (x, y, 0).
glm::mat4 translate(float x, float y);
// rotateZ(degrees): counter-clockwise about the z axis, i.e. in the x-y plane.
glm::mat4 rotateZ(float degrees);

// The positions of arm_matrices()'s results.
constexpr std::size_t kS = 0;            // the arm: shoulder frame
constexpr std::size_t kJ = 1;            // the elbow joint, J = S * T
constexpr std::size_t kH = 2;            // the hand, H = J * R
constexpr std::size_t kUpperFinger = 3;  // H * translate(1, +0.1) * rotateZ(+grip)
constexpr std::size_t kLowerFinger = 4;  // H * translate(1, -0.1) * rotateZ(-grip)
constexpr std::size_t kMatrixCount = 5;

// The student part: {S, J, H, upper finger, lower finger} for the joint
// angles in degrees (shoulder, hand: counter-clockwise; grip: how far each
// finger opens away from the other).
std::vector<glm::mat4> arm_matrices(float shoulder, float hand, float grip);

}  // namespace robot_arm
