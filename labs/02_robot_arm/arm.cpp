// Lab 2's hierarchy (README.md, "What you implement").
#include "arm.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace robot_arm {

glm::mat4 translate(float x, float y) {
    return glm::translate(glm::mat4(1.0f), glm::vec3(x, y, 0.0f));
}

glm::mat4 rotateZ(float degrees) {
    return glm::rotate(glm::mat4(1.0f), glm::radians(degrees), glm::vec3(0.0f, 0.0f, 1.0f));
}

// The lecture builds the arm top-down: each matrix is its parent's times one
// local step, so turning the shoulder carries the hand and fingers along.
//   S = translate(-1.5, -1.5) * rotateZ(shoulder)   (the slides' S := S N)
//   T = translate(2, 0)          the elbow sits at the arm's far end
//   J = S * T
//   R = rotateZ(hand)            the hand turns about the elbow
//   H = J * R
//   fingers: H * translate(1, +-0.1) * rotateZ(+-grip), at the hand's far end
ArmMatrices arm_matrices(float shoulder, float hand, float grip) {
    // BEGIN SOLUTION
    // STUDENT: (void)shoulder, (void)hand, (void)grip;
    // STUDENT: // TODO: S, T, J = S * T, R, H = J * R and the two fingers, with
    // STUDENT: // translate() and rotateZ() above, as the README's hierarchy says.
    // STUDENT: const glm::mat4 S(1.0f), J(1.0f), H(1.0f), upper(1.0f), lower(1.0f);
    const glm::mat4 S = translate(-1.5f, -1.5f) * rotateZ(shoulder);
    const glm::mat4 T = translate(2.0f, 0.0f);
    const glm::mat4 J = S * T;
    const glm::mat4 R = rotateZ(hand);
    const glm::mat4 H = J * R;
    const glm::mat4 upper = H * translate(1.0f, 0.1f) * rotateZ(grip);
    const glm::mat4 lower = H * translate(1.0f, -0.1f) * rotateZ(-grip);
    // END SOLUTION
    return {S, J, H, upper, lower};
}

}  // namespace robot_arm
