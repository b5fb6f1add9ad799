// Lab 3 `projection`: the course's references for the student's camera and
// projection functions, from GLM (and a closed form for the viewport), never
// from the lab's code. GLM's angles are radians; the lab's are degrees.
#include <glm/gtc/matrix_transform.hpp>

#include "grading/units/reference.hpp"

namespace {

glm::mat4 ref_lookAt(glm::vec3 eye, glm::vec3 target, glm::vec3 up) {
    return glm::lookAt(eye, target, up);
}

glm::mat4 ref_perspective(float fovy_deg, float aspect, float n, float f) {
    return glm::perspectiveRH_NO(glm::radians(fovy_deg), aspect, n, f);
}

glm::mat4 ref_orthographic(float l, float r, float b, float t, float n, float f) {
    return glm::orthoRH_NO(l, r, b, t, n, f);
}

glm::mat4 ref_perspective01(float fovy_deg, float aspect, float n, float f) {
    return glm::perspectiveRH_ZO(glm::radians(fovy_deg), aspect, n, f);
}

// glViewport(0, 0, w, h), glDepthRange(0, 1) (GL 4.3 core, section 13.6.1):
// x_w = (w / 2) x_d + w / 2, y_w = (h / 2) y_d + h / 2, z_w = z_d / 2 + 1 / 2.
glm::vec3 ref_viewport(glm::vec3 ndc, int width, int height) {
    return {0.5f * float(width) * (ndc.x + 1.0f), 0.5f * float(height) * (ndc.y + 1.0f),
            0.5f * (ndc.z + 1.0f)};
}

}  // namespace

// Eye and target anywhere in a 20-unit cube, up a random direction. A draw
// with the view almost parallel to up is ill-conditioned for GLM and the
// student alike; lookAt's tolerance in checkpoints.json (1e-4) allows for
// the rare ones that come close.
COURSE_REFERENCE(lookAt, &ref_lookAt,
                 {grading::vec(3, -10, 10), grading::vec(3, -10, 10), grading::unit_vec(3)})
// Fields of view within the lab's range; far always beyond near.
COURSE_REFERENCE(perspective, &ref_perspective,
                 {grading::scalar(10, 150), grading::scalar(0.25, 4), grading::scalar(0.01, 10),
                  grading::scalar(11, 1000)})
COURSE_REFERENCE(orthographic, &ref_orthographic,
                 {grading::scalar(-10, -0.1), grading::scalar(0.1, 10), grading::scalar(-10, -0.1),
                  grading::scalar(0.1, 10), grading::scalar(-5, 5), grading::scalar(6, 100)})
COURSE_REFERENCE(perspective01, &ref_perspective01,
                 {grading::scalar(10, 150), grading::scalar(0.25, 4), grading::scalar(0.01, 10),
                  grading::scalar(11, 1000)})
COURSE_REFERENCE(viewport, &ref_viewport,
                 {grading::vec(3, -1.5, 1.5), grading::integer(1, 4096), grading::integer(1, 4096)})
