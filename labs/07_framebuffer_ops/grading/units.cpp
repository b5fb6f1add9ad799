// Lab 7 `framebuffer-ops`: the course's references for the student's blend
// equation and back-to-front order, written from the GL specification
// (section 17.3.8, tables 17.1 and 17.2), never from the lab's code.
#include <algorithm>
#include <array>
#include <numeric>

#include "blending.hpp"
#include "grading/units/reference.hpp"

namespace {

using framebuffer_ops::BlendEquation;
using framebuffer_ops::BlendFactor;

// Table 17.2, one row per factor: (R, G, B) and A of the factor for a source
// colour s meeting a destination colour d.
glm::vec4 ref_factor(BlendFactor f, glm::vec4 s, glm::vec4 d) {
    const glm::vec4 one(1.0f);
    switch (f) {
        case BlendFactor::Zero:
            return glm::vec4(0.0f);
        case BlendFactor::One:
            return one;
        case BlendFactor::SrcColor:
            return s;
        case BlendFactor::OneMinusSrcColor:
            return one - s;
        case BlendFactor::DstColor:
            return d;
        case BlendFactor::OneMinusDstColor:
            return one - d;
        case BlendFactor::SrcAlpha:
            return glm::vec4(s.a);
        case BlendFactor::OneMinusSrcAlpha:
            return glm::vec4(1.0f - s.a);
        case BlendFactor::DstAlpha:
            return glm::vec4(d.a);
        case BlendFactor::OneMinusDstAlpha:
            return glm::vec4(1.0f - d.a);
    }
    return glm::vec4(0.0f);
}

// Table 17.1, per component, then the clamp of a fixed-point buffer.
glm::vec4 ref_blend(glm::vec4 s, glm::vec4 d, BlendFactor sf, BlendFactor df, BlendEquation eq) {
    const glm::vec4 a = s * ref_factor(sf, s, d), b = d * ref_factor(df, s, d);
    glm::vec4 out(0.0f);
    for (int i = 0; i < 4; ++i) {
        switch (eq) {
            case BlendEquation::Add:
                out[i] = a[i] + b[i];
                break;
            case BlendEquation::Subtract:
                out[i] = a[i] - b[i];
                break;
            case BlendEquation::ReverseSubtract:
                out[i] = b[i] - a[i];
                break;
            case BlendEquation::Min:
                out[i] = std::min(s[i], d[i]);
                break;
            case BlendEquation::Max:
                out[i] = std::max(s[i], d[i]);
                break;
        }
        out[i] = std::clamp(out[i], 0.0f, 1.0f);
    }
    return out;
}

// The farthest from the eye first; equal distances keep the listed order.
std::vector<int> ref_back_to_front(glm::vec3 eye, glm::vec3 a, glm::vec3 b, glm::vec3 c,
                                   glm::vec3 d) {
    const std::array<glm::vec3, 4> centres{a, b, c, d};
    std::array<float, 4> squared{};
    for (int i = 0; i < 4; ++i) {
        const glm::vec3 e = centres[i] - eye;
        squared[i] = glm::dot(e, e);
    }
    std::vector<int> order(4);
    std::iota(order.begin(), order.end(), 0);
    const auto farther = [&](int i, int j) { return squared[i] > squared[j]; };
    std::stable_sort(order.begin(), order.end(), farther);
    return order;
}

}  // namespace

COURSE_REFERENCE(blend, &ref_blend,
                 {grading::vec(4, 0, 1), grading::vec(4, 0, 1), grading::choice<BlendFactor>(),
                  grading::choice<BlendFactor>(), grading::choice<BlendEquation>()})
COURSE_REFERENCE(back_to_front, &ref_back_to_front,
                 {grading::vec(3, -10, 10), grading::vec(3, -10, 10), grading::vec(3, -10, 10),
                  grading::vec(3, -10, 10), grading::vec(3, -10, 10)})
