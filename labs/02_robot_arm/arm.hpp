// Lab 2's hierarchy: the matrices that place each part of the robot arm.
// The parts are designed at the origin (README.md); these matrices move them
// into the world. Column vectors: a part's point p lands at M * p.
#pragma once

#include <glm/glm.hpp>

#include "framework/names.hpp"

namespace robot_arm {

// Given helpers, 4x4 with column vectors (GLM underneath).
// translate(x, y): moves by (x, y, 0).
glm::mat4 translate(float x, float y);
// rotateZ(degrees): counter-clockwise about the z axis, i.e. in the x-y plane.
glm::mat4 rotateZ(float degrees);

// The matrices that place the parts of the arm (README.md's hierarchy).
struct ArmMatrices {
    glm::mat4 S;             // the arm: shoulder frame
    glm::mat4 J;             // the elbow joint, J = S * T
    glm::mat4 H;             // the hand, H = J * R
    glm::mat4 upper_finger;  // H * translate(1, +0.1) * rotateZ(+grip)
    glm::mat4 lower_finger;  // H * translate(1, -0.1) * rotateZ(-grip)
};

// The student part: {S, J, H, upper finger, lower finger} for the joint
// angles in degrees (shoulder, hand: counter-clockwise; grip: how far each
// finger opens away from the other).
ArmMatrices arm_matrices(float shoulder, float hand, float grip);

}  // namespace robot_arm

// The fields' names, for the grader's report ("your J").
template <>
struct fw::FieldsOf<robot_arm::ArmMatrices> {
    using A = robot_arm::ArmMatrices;
    static constexpr fw::Field<A, glm::mat4> list[] = {{"S", &A::S},
                                                       {"J", &A::J},
                                                       {"H", &A::H},
                                                       {"upper finger", &A::upper_finger},
                                                       {"lower finger", &A::lower_finger}};
};
