// Lab 8 `texture-mapping`, shared by its test files: the frame's window
// coordinates, a reference sampler with GL's texture rules (GL 4.3 core,
// chapter 8: texel centres at (i + 0.5) / size, the wrap modes, nearest and
// bilinear filtering, glGenerateMipmap's box filter), and a tally of
// per-pixel checks. The scenes' numbers are the sheet's
// (labs/08_texture_mapping/README.md); the textures' texels come from the
// generators of textures.hpp, which the test checks against the sheet.
#pragma once

#include <cmath>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "framework/image.hpp"
#include "framework/lab.hpp"
#include "framework/render.hpp"
#include "sampler_state.hpp"
#include "tests/support/test_support.hpp"

namespace texture_mapping_test {

constexpr int kSize = 512;

// The lab of this test's folder, created once per test case.
using Lab = fw::test::LabUnderTest;

// The centre of window pixel (x, y).
inline glm::vec2 centre(int x, int y) { return {float(x) + 0.5f, float(y) + 0.5f}; }

inline glm::vec3 rgb(const fw::Image& img, int x, int y) { return fw::test::rgb_at(img, x, y); }

inline float max_difference(glm::vec3 a, glm::vec3 b) {
    const glm::vec3 d = glm::abs(a - b);
    return glm::max(d.r, glm::max(d.g, d.b));
}

// What an RGBA8 colour buffer keeps of `c`: each channel clamped to [0, 1]
// and rounded to one of its 256 steps.
inline glm::vec3 stored(glm::vec3 c) {
    return glm::round(glm::clamp(c, 0.0f, 1.0f) * 255.0f) / 255.0f;
}

// How far the texel coordinate u (s times the texture's size) lies from the
// nearest texel edge, in texels.
inline float from_edge(float u) { return std::fabs(u - std::round(u)); }

// A texture level as GL reads it: each texel's bytes / 255, row 0 at t = 0.
struct Level {
    int width = 0, height = 0;
    std::vector<glm::vec3> texels;

    explicit Level(const fw::Image& img) : width(img.width), height(img.height) {
        for (const fw::Rgba8& p : img.pixels) texels.push_back(glm::vec3(p.r, p.g, p.b) / 255.0f);
    }
    Level(int w, int h) : width(w), height(h), texels(size_t(w) * size_t(h)) {}
    glm::vec3& at(int i, int j) { return texels[size_t(j) * width + i]; }
    const glm::vec3& at(int i, int j) const { return texels[size_t(j) * width + i]; }

    // The next level glGenerateMipmap makes of a power-of-two level (GL 4.3
    // section 8.14.4): each texel the mean of the 2 x 2 block it covers.
    Level half() const {
        Level next(glm::max(width / 2, 1), glm::max(height / 2, 1));
        for (int j = 0; j < next.height; ++j)
            for (int i = 0; i < next.width; ++i) {
                glm::vec3 sum(0.0f);
                for (int dj = 0; dj < 2; ++dj)
                    for (int di = 0; di < 2; ++di)
                        sum +=
                            at(glm::min(2 * i + di, width - 1), glm::min(2 * j + dj, height - 1));
                next.at(i, j) = sum / 4.0f;
            }
        return next;
    }
};

// The texel index GL reads on an axis of `size` texels for the integer i
// (floor(u) or floor(u - 1/2)), GL 4.3 section 8.14.2; -1 where
// CLAMP_TO_BORDER reads the border colour.
inline int wrap_index(int i, int size, texture_mapping::Wrap wrap) {
    using texture_mapping::Wrap;
    switch (wrap) {
        case Wrap::Repeat:
            return ((i % size) + size) % size;
        case Wrap::MirroredRepeat: {
            // (size - 1) - mirror((i mod 2 size) - size), mirror(a) = a >= 0 ? a : -(1 + a):
            // every other copy of the texture runs backwards.
            const int a = ((i % (2 * size)) + 2 * size) % (2 * size) - size;
            return size - 1 - (a >= 0 ? a : -(1 + a));
        }
        case Wrap::ClampToEdge:
            return glm::clamp(i, 0, size - 1);
        case Wrap::ClampToBorder:
            return i >= 0 && i < size ? i : -1;
    }
    return -1;
}

const glm::vec3 kBorder{1.0f, 0.0f, 1.0f};  // the sheet's border colour

inline glm::vec3 texel_or_border(const Level& l, int i, int j, texture_mapping::Wrap wrap) {
    const int wi = wrap_index(i, l.width, wrap), wj = wrap_index(j, l.height, wrap);
    return wi < 0 || wj < 0 ? kBorder : l.at(wi, wj);
}

// GL_NEAREST at (s, t): the texel containing (u, v) = (s width, t height).
inline glm::vec3 nearest(const Level& l, glm::vec2 st, texture_mapping::Wrap wrap) {
    return texel_or_border(l, int(std::floor(st.x * float(l.width))),
                           int(std::floor(st.y * float(l.height))), wrap);
}

// GL_LINEAR at (s, t): the four texels whose centres surround (u, v),
// weighted by the fractions of u - 1/2 and v - 1/2 (GL 4.3 section 8.14.2).
inline glm::vec3 bilinear(const Level& l, glm::vec2 st, texture_mapping::Wrap wrap) {
    const glm::vec2 uv = st * glm::vec2(l.width, l.height) - 0.5f;
    const glm::vec2 f = glm::floor(uv), a = uv - f;
    const int i0 = int(f.x), j0 = int(f.y);
    return (1 - a.x) * (1 - a.y) * texel_or_border(l, i0, j0, wrap) +
           a.x * (1 - a.y) * texel_or_border(l, i0 + 1, j0, wrap) +
           (1 - a.x) * a.y * texel_or_border(l, i0, j0 + 1, wrap) +
           a.x * a.y * texel_or_border(l, i0 + 1, j0 + 1, wrap);
}

// Counts the pixels where the observed colour differs from the expected one
// by more than `tol`, logging Expected/Observed for the first few, and keeps
// the largest difference seen (the measured error).
struct PixelTally {
    std::string what;
    float tol;
    long tested = 0, failed = 0;
    float largest = 0.0f;

    void check(int x, int y, glm::vec3 expected, glm::vec3 observed) {
        ++tested;
        const float d = max_difference(expected, observed);
        largest = glm::max(largest, d);
        if (d <= tol) return;
        if (++failed <= 5)
            MESSAGE(what << ": pixel (" << x << ", " << y << "): expected " << text(expected)
                         << " observed " << text(observed));
    }
    // Logs the counts and checks that at least `min_tested` pixels were
    // tested and none failed.
    void require(long min_tested) const {
        MESSAGE(what << ": " << failed << " of " << tested << " pixels off by more than " << tol
                     << " (" << tol * 255.0f << "/255); largest difference " << largest * 255.0f
                     << "/255");
        CHECK(tested >= min_tested);
        CHECK(failed == 0);
    }

private:
    static std::string text(glm::vec3 c) {
        return "(" + std::to_string(c.r) + ", " + std::to_string(c.g) + ", " + std::to_string(c.b) +
               ")";
    }
};

// The ray through NDC point (x, y) of the camera whose P * V has the inverse
// `inverse_clip`: from its point on the near plane towards the far one.
struct Ray {
    glm::vec3 origin, direction;
};
inline Ray ndc_ray(const glm::mat4& inverse_clip, glm::vec2 ndc) {
    const glm::vec4 n = inverse_clip * glm::vec4(ndc, -1.0f, 1.0f);
    const glm::vec4 f = inverse_clip * glm::vec4(ndc, 1.0f, 1.0f);
    const glm::vec3 a = glm::vec3(n) / n.w, b = glm::vec3(f) / f.w;
    return {a, glm::normalize(b - a)};
}

}  // namespace texture_mapping_test
