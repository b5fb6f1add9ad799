// Lab 6 `interpolation`, shared by its test files: the lab renderer and the
// sheet's numbers (labs/06_interpolation/README.md), written here again so
// that the tests never read them from the lab's code.
#pragma once

#include <glm/gtc/matrix_transform.hpp>
#include <string>
#include <utility>
#include <vector>

#include "framework/lab.hpp"
#include "framework/render.hpp"
#include "tests/support/test_support.hpp"

namespace interpolation_test {

constexpr int kSize = 512;

using fw::test::Settings;

// The lab of this test's folder, created once per test case.
using Lab = fw::test::LabUnderTest;

inline glm::vec3 rgb(const fw::Image& img, int x, int y) { return fw::test::rgb_at(img, x, y); }

inline float max_difference(glm::vec3 a, glm::vec3 b) {
    const glm::vec3 d = glm::abs(a - b);
    return glm::max(d.r, glm::max(d.g, d.b));
}

// Clip coordinates -> GL window coordinates of a kSize x kSize frame.
inline glm::vec2 to_window(glm::vec4 clip) {
    return (glm::vec2(clip) / clip.w + 1.0f) * 0.5f * float(kSize);
}

// Counts the pixels where `observed` and `expected` differ by more than
// `tol`, logging Expected/Observed for the first few.
struct PixelTally {
    const char* what;
    float tol;
    long tested = 0, failed = 0;

    void check(int x, int y, glm::vec3 expected, glm::vec3 observed) {
        ++tested;
        if (max_difference(expected, observed) <= tol) return;
        if (++failed <= 5)
            MESSAGE(std::string(what)
                    << ": pixel (" << x << ", " << y << "): expected (" << expected.r << ", "
                    << expected.g << ", " << expected.b << ") observed (" << observed.r << ", "
                    << observed.g << ", " << observed.b << ")");
    }
    void report() const {
        MESSAGE(std::string(what) << ": " << failed << " of " << tested
                                  << " pixels off by more than " << tol);
    }
};

// scene=plane: P * V from the sheet.
inline glm::mat4 plane_clip() {
    return glm::perspective(glm::radians(60.0f), 1.0f, 0.1f, 100.0f) *
           glm::lookAt(glm::vec3(0, 1.5f, -1), glm::vec3(0, -1, -9), glm::vec3(0, 1, 0));
}

// scene=shading: P * V from the sheet, and the eye.
const glm::vec3 kSphereEye{0, 0, 3};
inline glm::mat4 sphere_clip() {
    return glm::perspective(glm::radians(45.0f), 1.0f, 0.1f, 100.0f) *
           glm::lookAt(kSphereEye, glm::vec3(0), glm::vec3(0, 1, 0));
}

// The ray through window point p (pixel centres at +0.5) of the camera
// whose P * V has the inverse `inverse_clip`: from its point on the near
// plane towards its point on the far one.
struct Ray {
    glm::vec3 origin, direction;
};
inline Ray window_ray(const glm::mat4& inverse_clip, glm::vec2 p) {
    const glm::vec2 ndc = p / float(kSize) * 2.0f - 1.0f;
    const glm::vec4 near = inverse_clip * glm::vec4(ndc, -1.0f, 1.0f);
    const glm::vec4 far = inverse_clip * glm::vec4(ndc, 1.0f, 1.0f);
    const glm::vec3 a = glm::vec3(near) / near.w, b = glm::vec3(far) / far.w;
    return {a, glm::normalize(b - a)};
}

}  // namespace interpolation_test
