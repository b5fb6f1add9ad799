// Lab 7 `framebuffer-ops`: the unit functions blend() and back_to_front(),
// called directly (no GL), against the GL specification's tables written
// out here, never against the lab's own code.
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include "blending.hpp"
#include "framebuffer_ops_test.hpp"

using namespace framebuffer_ops;

namespace {
// --- blend() and back_to_front() -------------------------------------------

// Table 17.2 for channel i (3: alpha) of the factor `f`.
float ref_factor(BlendFactor f, glm::vec4 s, glm::vec4 d, int i) {
    switch (f) {
        case BlendFactor::Zero:
            return 0.0f;
        case BlendFactor::One:
            return 1.0f;
        case BlendFactor::SrcColor:
            return s[i];
        case BlendFactor::OneMinusSrcColor:
            return 1.0f - s[i];
        case BlendFactor::DstColor:
            return d[i];
        case BlendFactor::OneMinusDstColor:
            return 1.0f - d[i];
        case BlendFactor::SrcAlpha:
            return s[3];
        case BlendFactor::OneMinusSrcAlpha:
            return 1.0f - s[3];
        case BlendFactor::DstAlpha:
            return d[3];
        case BlendFactor::OneMinusDstAlpha:
            return 1.0f - d[3];
    }
    return -1.0f;
}

// Table 17.1, channel by channel, clamped as an RGBA8 buffer stores it.
glm::vec4 ref_blend(glm::vec4 s, glm::vec4 d, BlendFactor sf, BlendFactor df, BlendEquation eq) {
    glm::vec4 out;
    for (int i = 0; i < 4; ++i) {
        const float a = s[i] * ref_factor(sf, s, d, i), b = d[i] * ref_factor(df, s, d, i);
        float r = 0.0f;
        switch (eq) {
            case BlendEquation::Add:
                r = a + b;
                break;
            case BlendEquation::Subtract:
                r = a - b;
                break;
            case BlendEquation::ReverseSubtract:
                r = b - a;
                break;
            case BlendEquation::Min:
                r = std::min(s[i], d[i]);
                break;
            case BlendEquation::Max:
                r = std::max(s[i], d[i]);
                break;
        }
        out[i] = std::clamp(r, 0.0f, 1.0f);
    }
    return out;
}

std::string text(glm::vec4 c) {
    char s[80];
    std::snprintf(s, sizeof s, "(%.4f, %.4f, %.4f, %.4f)", c.r, c.g, c.b, c.a);
    return s;
}

}  // namespace

TEST_CASE("framebuffer_ops: blend() is tables 17.1 and 17.2 for every factor and equation") {
    std::mt19937 random(7);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const auto colour = [&] {
        return glm::vec4(unit(random), unit(random), unit(random), unit(random));
    };
    long tested = 0, failed = 0;
    for (const auto& sf : kBlendFactors)
        for (const auto& df : kBlendFactors)
            for (const auto& eq : kBlendEquations)
                for (int k = 0; k < 20; ++k) {
                    // Two fixed pairs with 0 and 1 in them, then random ones.
                    const glm::vec4 s = k == 0   ? glm::vec4(1, 0, 0.5f, 0.25f)
                                        : k == 1 ? glm::vec4(0.2f, 0.9f, 1, 1)
                                                 : colour();
                    const glm::vec4 d = k == 0   ? glm::vec4(0, 1, 0.5f, 1)
                                        : k == 1 ? glm::vec4(0.7f, 0.1f, 0, 0)
                                                 : colour();
                    const glm::vec4 expected = ref_blend(s, d, sf.value, df.value, eq.value);
                    const glm::vec4 observed = blend(s, d, sf.value, df.value, eq.value);
                    ++tested;
                    const glm::vec4 diff = glm::abs(expected - observed);
                    if (std::max(std::max(diff.r, diff.g), std::max(diff.b, diff.a)) <= 1e-6f)
                        continue;
                    if (++failed <= 10)
                        MESSAGE("blend(" << text(s) << ", " << text(d) << ", " << sf.name << ", "
                                         << df.name << ", " << eq.name << "): expected "
                                         << text(expected) << " observed " << text(observed));
                }
    MESSAGE("blend(): " << failed << " of " << tested << " calls wrong");
    CHECK(tested == 10 * 10 * 5 * 20);
    CHECK(failed == 0);
}

TEST_CASE("framebuffer_ops: back_to_front() orders by distance, ties as listed") {
    using Order = std::vector<int>;
    const glm::vec3 o(0.0f);
    // The sheet's panes: far, middle, near.
    std::vector<glm::vec3> centres;
    for (const Pane& p : panes()) centres.push_back(p.centre);
    CHECK(back_to_front(centres, kSortingEye) == Order{2, 1, 0});
    // Distance, not depth along z: (3, 0, -1) is nearer in z but farther away.
    CHECK(back_to_front({{0, 0, -2}, {3, 0, -1}}, o) == Order{1, 0});
    // Equal distances keep the listed order.
    CHECK(back_to_front({{1, 0, 0}, {0, 1, 0}, {0, 0, 1}}, o) == Order{0, 1, 2});
    CHECK(back_to_front({{0, 0, -1}, {2, 0, 0}, {0, -1, 0}, {0, 0, 3}}, o) == Order{3, 1, 0, 2});
    CHECK(back_to_front({}, o).empty());
    // The eye elsewhere: distances 1, 3, 2 and 3 from (1, 2, 3).
    CHECK(back_to_front4({1, 2, 3}, {1, 2, 4}, {4, 2, 3}, {1, 0, 3}, {1, 2, 0}) ==
          Order{1, 3, 2, 0});
}
