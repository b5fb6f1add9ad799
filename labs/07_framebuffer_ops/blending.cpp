// Lab 7's student arithmetic: the blend equation and the back-to-front order
// (blending.hpp says what each returns).
#include "blending.hpp"

#include <algorithm>
#include <numeric>

namespace framebuffer_ops {

namespace {

// The factor `f` as a vec4 for a fragment `src` meeting `dst` (table 17.2).
glm::vec4 factor(BlendFactor f, glm::vec4 src, glm::vec4 dst) {
    // BEGIN SOLUTION
    // STUDENT: (void)f, (void)src, (void)dst;
    // STUDENT: return glm::vec4(1.0f);  // TODO: the factor table 17.2 gives, for each BlendFactor
    switch (f) {
        case BlendFactor::Zero:
            return glm::vec4(0.0f);
        case BlendFactor::One:
            return glm::vec4(1.0f);
        case BlendFactor::SrcColor:
            return src;
        case BlendFactor::OneMinusSrcColor:
            return glm::vec4(1.0f) - src;
        case BlendFactor::DstColor:
            return dst;
        case BlendFactor::OneMinusDstColor:
            return glm::vec4(1.0f) - dst;
        case BlendFactor::SrcAlpha:
            return glm::vec4(src.a);
        case BlendFactor::OneMinusSrcAlpha:
            return glm::vec4(1.0f - src.a);
        case BlendFactor::DstAlpha:
            return glm::vec4(dst.a);
        case BlendFactor::OneMinusDstAlpha:
            return glm::vec4(1.0f - dst.a);
    }
    return glm::vec4(0.0f);
    // END SOLUTION
}

}  // namespace

glm::vec4 blend(glm::vec4 src, glm::vec4 dst, BlendFactor src_factor, BlendFactor dst_factor,
                BlendEquation equation) {
    const glm::vec4 s = src * factor(src_factor, src, dst);
    const glm::vec4 d = dst * factor(dst_factor, src, dst);
    glm::vec4 out(0.0f);
    // BEGIN SOLUTION
    // STUDENT: (void)s, (void)d, (void)equation;
    // STUDENT: out = src;  // TODO: combine s and d as `equation` says (table 17.1)
    switch (equation) {
        case BlendEquation::Add:
            out = s + d;
            break;
        case BlendEquation::Subtract:
            out = s - d;
            break;
        case BlendEquation::ReverseSubtract:
            out = d - s;
            break;
        // MIN and MAX compare the colours themselves: the factors play no part.
        case BlendEquation::Min:
            out = glm::min(src, dst);
            break;
        case BlendEquation::Max:
            out = glm::max(src, dst);
            break;
    }
    // END SOLUTION
    return glm::clamp(out, 0.0f, 1.0f);
}

std::vector<int> back_to_front(const std::vector<glm::vec3>& centres, glm::vec3 eye) {
    std::vector<int> order(centres.size());
    std::iota(order.begin(), order.end(), 0);
    // BEGIN SOLUTION
    // STUDENT: (void)eye;  // TODO: sort `order` so that the centre farthest from the eye comes
    // STUDENT: // first (std::stable_sort keeps the listed order of equal distances)
    const auto farther = [&](int i, int j) {
        return glm::distance(centres[i], eye) > glm::distance(centres[j], eye);
    };
    std::stable_sort(order.begin(), order.end(), farther);
    // END SOLUTION
    return order;
}

std::vector<int> back_to_front4(glm::vec3 eye, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
    return back_to_front({a, b, c, d}, eye);
}

}  // namespace framebuffer_ops
