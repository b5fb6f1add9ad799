// Lab 7 `framebuffer-ops`, shared by its test files: the frame's window
// coordinates, what an RGBA8 buffer stores, and a tally of per-pixel checks.
// The scenes' numbers are the sheet's (labs/07_framebuffer_ops/README.md), as
// scenes.hpp writes them; every GL rule applied to them is written here.
#pragma once

#include <cmath>
#include <glm/glm.hpp>
#include <string>

#include "framework/lab.hpp"
#include "framework/render.hpp"
#include "scenes.hpp"
#include "tests/support/test_support.hpp"

namespace framebuffer_ops_test {

constexpr int kSize = 512;

using fw::test::Settings;

// The lab of this test's folder, created once per test case.
using Lab = fw::test::LabUnderTest;

// The window pixel whose square holds NDC coordinate `ndc` of a kSize frame:
// window x = (ndc + 1) * 256.
inline int pixel(float ndc) { return static_cast<int>(std::floor((ndc + 1.0f) * 0.5f * kSize)); }
// The NDC coordinate of the centre of window pixel `i`.
inline float centre_ndc(int i) { return (float(i) + 0.5f) / (0.5f * kSize) - 1.0f; }
// Clip coordinates -> window coordinates (x, y) and window depth (z) of a
// kSize x kSize frame with glDepthRange(0, 1).
inline glm::vec3 to_window(glm::vec4 clip) {
    const glm::vec3 ndc = glm::vec3(clip) / clip.w;
    return {(ndc.x + 1.0f) * 0.5f * kSize, (ndc.y + 1.0f) * 0.5f * kSize, (ndc.z + 1.0f) * 0.5f};
}

// What an RGBA8 colour buffer keeps of `c`: each channel clamped to [0, 1]
// and rounded to one of its 256 steps (the nearest, on the GPUs we know; the
// tolerances allow a step either way after each draw).
inline glm::vec3 stored(glm::vec3 c) {
    return glm::round(glm::clamp(c, 0.0f, 1.0f) * 255.0f) / 255.0f;
}
// "over" (GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA, GL_FUNC_ADD) of the colour
// `src` with alpha src.a onto `dst`, as the buffer keeps it.
inline glm::vec3 over(glm::vec4 src, glm::vec3 dst) {
    return stored(src.a * glm::vec3(src) + (1.0f - src.a) * dst);
}

// A rectangle in window coordinates, and how far a point is inside it.
struct WindowRect {
    float x0, y0, x1, y1;
    // The distance from p to the nearest side: positive inside, negative
    // outside (where it may underestimate, near a corner).
    float inside_by(glm::vec2 p) const {
        return glm::min(glm::min(p.x - x0, x1 - p.x), glm::min(p.y - y0, y1 - p.y));
    }
};
// The NDC rectangle [x0, x1] x [y0, y1] of a kSize x kSize frame.
inline WindowRect ndc_rect(float x0, float y0, float x1, float y1) {
    const auto w = [](float ndc) { return (ndc + 1.0f) * 0.5f * kSize; };
    return {w(x0), w(y0), w(x1), w(y1)};
}
// The centre of window pixel (x, y).
inline glm::vec2 centre(int x, int y) { return {float(x) + 0.5f, float(y) + 0.5f}; }

inline glm::vec3 rgb(const fw::Image& img, int x, int y) { return fw::test::rgb_at(img, x, y); }

inline float max_difference(glm::vec3 a, glm::vec3 b) {
    const glm::vec3 d = glm::abs(a - b);
    return glm::max(d.r, glm::max(d.g, d.b));
}
inline float max_difference(float a, float b) { return std::fabs(a - b); }

// Counts the pixels where the observed colour (or depth) differs from the
// expected one by more than `tol`, logging Expected/Observed for the first few.
struct PixelTally {
    std::string what;
    float tol;
    long tested = 0, failed = 0;

    template <class T>
    void check(int x, int y, T expected, T observed) {
        ++tested;
        if (max_difference(expected, observed) <= tol) return;
        if (++failed <= 5)
            MESSAGE(what << ": pixel (" << x << ", " << y << "): expected " << text(expected)
                         << " observed " << text(observed));
    }
    // Logs the counts and checks that at least `min_tested` pixels were
    // tested and none failed.
    void require(long min_tested) const {
        MESSAGE(what << ": " << failed << " of " << tested << " pixels off by more than " << tol);
        CHECK(tested >= min_tested);
        CHECK(failed == 0);
    }

private:
    static std::string text(float v) { return std::to_string(v); }
    static std::string text(glm::vec3 c) {
        return "(" + std::to_string(c.r) + ", " + std::to_string(c.g) + ", " + std::to_string(c.b) +
               ")";
    }
};

}  // namespace framebuffer_ops_test
