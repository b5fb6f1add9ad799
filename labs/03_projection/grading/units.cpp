// Lab 3 `projection`: the course's references for the student's camera and
// projection functions, from GLM (and a closed form for the viewport), never
// from the lab's code. GLM's angles are radians; the lab's are degrees.
// The view matrix built without normalising its basis is here too, for the
// report to name that mistake.
#include <glm/gtc/matrix_transform.hpp>

#include "grading/units/reference.hpp"

namespace {

glm::mat4 ref_lookAt(glm::vec3 eye, glm::vec3 target, glm::vec3 up) {
    return glm::lookAt(eye, target, up);
}

// The view matrix with rows u, v, w and the eye moved to the origin, from
// w = eye - target and u = up x w, normalised or not.
glm::mat4 view(glm::vec3 eye, glm::vec3 target, glm::vec3 up, bool unit_w, bool unit_u) {
    glm::vec3 w = eye - target;
    if (unit_w) w = glm::normalize(w);
    glm::vec3 u = glm::cross(up, w);
    if (unit_u) u = glm::normalize(u);
    const glm::vec3 v = glm::cross(w, u);
    glm::mat4 m(1.0f);
    for (int c = 0; c < 3; ++c) {
        m[c][0] = u[c];
        m[c][1] = v[c];
        m[c][2] = w[c];
    }
    m[3] = glm::vec4(-glm::dot(u, eye), -glm::dot(v, eye), -glm::dot(w, eye), 1.0f);
    return m;
}
glm::mat4 ref_lookAt_none_normalised(glm::vec3 eye, glm::vec3 target, glm::vec3 up) {
    return view(eye, target, up, false, false);
}
glm::mat4 ref_lookAt_w_not_normalised(glm::vec3 eye, glm::vec3 target, glm::vec3 up) {
    return view(eye, target, up, false, true);
}
glm::mat4 ref_lookAt_u_not_normalised(glm::vec3 eye, glm::vec3 target, glm::vec3 up) {
    return view(eye, target, up, true, false);
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
                 {grading::vec(3, -10, 10), grading::vec(3, -10, 10), grading::unit_vec(3)},
                 grading::not_normalised(&ref_lookAt_none_normalised),
                 grading::not_normalised(&ref_lookAt_w_not_normalised),
                 grading::not_normalised(&ref_lookAt_u_not_normalised))
// Fields of view within the lab's range; far always beyond near.
COURSE_REFERENCE(perspective, &ref_perspective,
                 {grading::degrees(10, 150), grading::scalar(0.25, 4), grading::scalar(0.01, 10),
                  grading::scalar(11, 1000)})
COURSE_REFERENCE(orthographic, &ref_orthographic,
                 {grading::scalar(-10, -0.1), grading::scalar(0.1, 10), grading::scalar(-10, -0.1),
                  grading::scalar(0.1, 10), grading::scalar(-5, 5), grading::scalar(6, 100)})
COURSE_REFERENCE(perspective01, &ref_perspective01,
                 {grading::degrees(10, 150), grading::scalar(0.25, 4), grading::scalar(0.01, 10),
                  grading::scalar(11, 1000)})
COURSE_REFERENCE(viewport, &ref_viewport,
                 {grading::vec(3, -1.5, 1.5), grading::integer(1, 4096), grading::integer(1, 4096)})
