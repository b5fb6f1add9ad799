// Lab 3's camera and projection, written by hand: the student parts of the
// lab, kept apart from the drawing code so that tests and the grader can call
// them directly (unit functions "lookAt", "perspective", "orthographic",
// "perspective01" and "viewport").
//
// Column vectors, as GLSL and GLM store them: p' = M * p, and GLM indexes
// m[column][row]. The lecture's last deck writes row vectors, p' = p * M, so
// each matrix there is the transpose of the one here. None of these may call
// glm::lookAt, glm::perspective, glm::ortho, glm::project or their variants;
// glm::normalize, glm::cross and glm::dot are fine.
#pragma once

#include <glm/glm.hpp>

namespace projection {

// The view matrix V of a camera at `eye` looking at `target`, `up` roughly
// up. The lecture's basis: w = normalize(eye - target) (the camera looks
// down -w), u = normalize(up x w) (right), v = w x u (up). V turns world
// coordinates into the camera's: the eye goes to the origin, u to +x, v to
// +y, w to +z, so the target lands on the -z axis.
glm::mat4 lookAt(glm::vec3 eye, glm::vec3 target, glm::vec3 up);

// OpenGL's perspective matrix: vertical field of view `fovy_deg` (degrees),
// aspect = width / height, near and far plane distances n, f > 0. A point at
// z_eye = -n lands at NDC depth -1, one at -f at +1.
glm::mat4 perspective(float fovy_deg, float aspect, float n, float f);

// OpenGL's orthographic matrix: the box [l, r] x [b, t] x [-n, -f] (eye
// space) to the NDC cube [-1, 1]^3, near face at depth -1.
glm::mat4 orthographic(float l, float r, float b, float t, float n, float f);

// The perspective matrix of the last deck, with depth to [0, 1]: near at 0,
// far at 1 (Direct3D's and Vulkan's convention; GL gets it with
// glClipControl). Same x and y as perspective().
glm::mat4 perspective01(float fovy_deg, float aspect, float n, float f);

// The viewport mapping of glViewport(0, 0, width, height) with
// glDepthRange(0, 1): NDC x, y in [-1, 1] to window x in [0, width], y in
// [0, height] (origin bottom-left), NDC depth [-1, 1] to window depth [0, 1].
glm::vec3 viewport(glm::vec3 ndc, int width, int height);

}  // namespace projection
