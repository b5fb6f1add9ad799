// Lab 2 `robot-arm`: course's reference for arm_matrices, in closed form.
// Every part of the arm is a rigid motion of the plane: a turn by the sum of
// the angles above it, then a shift to the point where it is attached. The
// attachment points follow from trigonometry along the chain, without any
// matrix product. The products in reverse order, for the report to name that
// mistake, are GLM's.
#include <cmath>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "arm.hpp"  // ArmMatrices: the result's fields and their names
#include "grading/units/reference.hpp"

namespace {

constexpr double kDegree = 3.14159265358979323846 / 180.0;

// The 4x4 matrix that turns the plane by `turn` radians about the origin and
// then moves the origin to (x, y), column by column (GLM's m[column]).
glm::mat4 rigid(double turn, double x, double y) {
    const float c = float(std::cos(turn)), s = float(std::sin(turn));
    glm::mat4 m(1.0f);
    m[0] = glm::vec4(c, s, 0.0f, 0.0f);                // where the x axis goes
    m[1] = glm::vec4(-s, c, 0.0f, 0.0f);               // where the y axis goes
    m[3] = glm::vec4(float(x), float(y), 0.0f, 1.0f);  // where the origin goes
    return m;
}

// {S, J, H, upper finger, lower finger} (ArmMatrices): the arm turns by `shoulder` about
// (-1.5, -1.5) and is 2 long; the hand turns by a further `hand` at the
// elbow and is 1 long; the fingers sit 0.1 to either side of the hand's end,
// across it, and turn by a further +grip (upper) and -grip (lower).
robot_arm::ArmMatrices ref_arm_matrices(float shoulder, float hand, float grip) {
    const double a = shoulder * kDegree;
    const double b = (double(shoulder) + double(hand)) * kDegree;
    const double elbow_x = -1.5 + 2.0 * std::cos(a), elbow_y = -1.5 + 2.0 * std::sin(a);
    const double end_x = elbow_x + std::cos(b), end_y = elbow_y + std::sin(b);
    // 0.1 along the hand's own +y, which points at angle b + 90 degrees.
    const double side_x = -0.1 * std::sin(b), side_y = 0.1 * std::cos(b);
    return {rigid(a, -1.5, -1.5), rigid(a, elbow_x, elbow_y), rigid(b, elbow_x, elbow_y),
            rigid(b + grip * kDegree, end_x + side_x, end_y + side_y),
            rigid(b - grip * kDegree, end_x - side_x, end_y - side_y)};
}

glm::mat4 move(float x, float y) { return glm::translate(glm::mat4(1.0f), {x, y, 0.0f}); }
glm::mat4 turn(float degrees) {
    return glm::rotate(glm::mat4(1.0f), glm::radians(degrees), {0.0f, 0.0f, 1.0f});
}

// Each matrix the product of its factors in reverse order, its parent
// (S, J, H) right: S = move * turn, J = S * T, H = J * R, finger = H * move *
// turn become turn * move, T * S, R * J and turn * move * H.
robot_arm::ArmMatrices ref_arm_reversed(float shoulder, float hand, float grip) {
    const robot_arm::ArmMatrices m = ref_arm_matrices(shoulder, hand, grip);
    return {turn(shoulder) * move(-1.5f, -1.5f), move(2.0f, 0.0f) * m.S, turn(hand) * m.J,
            turn(grip) * move(1.0f, 0.1f) * m.H, turn(-grip) * move(1.0f, -0.1f) * m.H};
}

// The fingers' own two factors swapped (H * turn * move): each finger turns
// about the elbow, the hand's origin, instead of about its own base.
robot_arm::ArmMatrices ref_arm_fingers_reversed(float shoulder, float hand, float grip) {
    robot_arm::ArmMatrices m = ref_arm_matrices(shoulder, hand, grip);
    m.upper_finger = m.H * turn(grip) * move(1.0f, 0.1f);
    m.lower_finger = m.H * turn(-grip) * move(1.0f, -0.1f);
    return m;
}

}  // namespace

COURSE_REFERENCE(arm_matrices, &ref_arm_matrices,
                 {grading::degrees(-180, 180), grading::degrees(-150, 150),
                  grading::degrees(0, 90)},
                 grading::reversed_product(&ref_arm_reversed),
                 grading::reversed_product(&ref_arm_fingers_reversed))
