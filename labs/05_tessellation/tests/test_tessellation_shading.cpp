// Lab 5 `tessellation`: the shaded surfaces, pixel by pixel: the flag's
// normals from its partial derivatives and the lit spheres. Every expectation
// is computed here from the sheet's numbers (labs/05_tessellation/README.md),
// never read from a reference image or from the lab's own code.
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <optional>
#include <string>

#include "tessellation_test.hpp"
#include "tests/support/test_support.hpp"

using namespace tessellation_test;

namespace {

// The flag as README.md defines it: r(u, v) = (u W, v H, sin(K pi u + phase) D),
// W = 2, H = 1.2, seen through lookAt((-0.2, 1.3, 2.6), (1, 0.6, 0), (0, 1, 0))
// and perspective(45 deg, 1, 0.1, 100).
struct Flag {
    float D = 0.15f, K = 2.0f, phase_degrees = 0.0f;
    static constexpr float W = 2.0f, H = 1.2f;

    float z_at(float u) const { return std::sin(K * kPi * u + glm::radians(phase_degrees)) * D; }
    glm::vec3 normal_at(float u) const {
        const float a = K * kPi * u + glm::radians(phase_degrees);
        return glm::normalize(
            glm::cross(glm::vec3(W, 0.0f, K * kPi * D * std::cos(a)), glm::vec3(0.0f, H, 0.0f)));
    }
    // Where the ray through pixel (x, y)'s centre first meets the flag, as
    // (u, v); nullopt if it misses. The flag is a height field over the
    // plane z = 0, so march along the ray until z - z_at(u) changes sign.
    std::optional<glm::vec2> hit(int x, int y) const {
        const glm::mat4 view_projection =
            glm::perspective(glm::radians(45.0f), 1.0f, 0.1f, 100.0f) *
            glm::lookAt(glm::vec3(-0.2f, 1.3f, 2.6f), glm::vec3(1.0f, 0.6f, 0.0f),
                        glm::vec3(0.0f, 1.0f, 0.0f));
        const glm::mat4 inverse = glm::inverse(view_projection);
        const glm::vec2 ndc = ndc_of(x, y);
        const glm::vec4 a = inverse * glm::vec4(ndc, -1.0f, 1.0f);
        const glm::vec4 b = inverse * glm::vec4(ndc, 1.0f, 1.0f);
        const glm::vec3 origin = glm::vec3(a) / a.w;
        const glm::vec3 dir = glm::normalize(glm::vec3(b) / b.w - origin);
        auto g = [&](float t) {
            const glm::vec3 p = origin + t * dir;
            return p.z - z_at(p.x / W);
        };
        // Only the slab |z| <= D can hold the surface; the ray runs towards -z.
        const float enter = (D - origin.z) / dir.z, leave = (-D - origin.z) / dir.z;
        constexpr float kStep = 1e-3f;
        // g at the step's start: the last step's end, computed once.
        float g_start = g(enter - kStep);
        for (float t = enter - kStep; t < leave + kStep; t += kStep) {
            // A root in [t, t + kStep]: the ray passes through the surface,
            // from the front or (beside the flag, or from behind) the back.
            const bool above = g_start > 0.0f;
            g_start = g(t + kStep);
            if (above == (g_start > 0.0f)) continue;
            float lo = t, hi = t + kStep;
            for (int i = 0; i < 30; ++i) {
                const float mid = 0.5f * (lo + hi);
                ((g(mid) > 0.0f) == above ? lo : hi) = mid;
            }
            const glm::vec3 p = origin + hi * dir;
            const glm::vec2 uv(p.x / W, p.y / H);
            if (uv.x >= 0.0f && uv.x <= 1.0f && uv.y >= 0.0f && uv.y <= 1.0f) return uv;
            // The ray crossed the wave's extension beside the flag: go on.
        }
        return std::nullopt;
    }
};

}  // namespace

TEST_CASE("tessellation: flag: normals from the partial derivatives, pixel by pixel") {
    Tessellation lab;
    struct Case {
        Flag flag;
        const char* D;
        const char* K;
        const char* phase;
    };
    const Case cases[] = {{{0.15f, 2.0f, 0.0f}, "0.15", "2", "0"},
                          {{0.3f, 3.0f, 90.0f}, "0.3", "3", "90"}};
    for (const Case& c : cases) {
        CAPTURE(c.K);
        const fw::RenderOutput out = lab.render({{"scene", "flag"},
                                                 {"show", "normals"},
                                                 {"wireframe", "false"},
                                                 {"inner", "64"},
                                                 {"outer", "64"},
                                                 {"D", c.D},
                                                 {"K", c.K},
                                                 {"phase", c.phase}});
        std::vector<std::optional<glm::vec2>> hits;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) hits.push_back(c.flag.hit(x, y));
        auto hit = [&](int x, int y) { return hits[static_cast<std::size_t>(y * kSize + x)]; };
        long compared = 0, bad = 0, coverage_wrong = 0;
        for (int y = 1; y < kSize - 1; ++y)
            for (int x = 1; x < kSize - 1; ++x) {
                const std::optional<glm::vec2> uv = hit(x, y);
                const bool inside = uv && glm::all(glm::greaterThan(*uv, glm::vec2(0.01f))) &&
                                    glm::all(glm::lessThan(*uv, glm::vec2(0.99f)));
                // Covered although neither this pixel nor a neighbour sees the flag.
                if (!uv)
                    coverage_wrong += covered(out, x, y) && !hit(x + 1, y) && !hit(x - 1, y) &&
                                      !hit(x, y + 1) && !hit(x, y - 1);
                if (!inside) continue;
                coverage_wrong += !covered(out, x, y);
                ++compared;
                const glm::vec3 expected = 0.5f * c.flag.normal_at(uv->x) + 0.5f;
                const glm::vec3 observed = rgb(out.color, x, y);
                if (near(observed, expected, 3.0f / 255.0f)) continue;
                if (++bad <= 5)
                    MESSAGE("pixel (" << x << ", " << y << ") u " << uv->x << ": expected ("
                                      << expected.x << ", " << expected.y << ", " << expected.z
                                      << ") observed (" << observed.x << ", " << observed.y << ", "
                                      << observed.z << ")");
            }
        INFO(compared << " pixels compared, " << bad << " differ, " << coverage_wrong
                      << " covered where the flag is not or the reverse");
        CHECK(compared > 20000);
        CHECK(bad == 0);
        CHECK(coverage_wrong == 0);
    }
}

TEST_CASE("tessellation: lit spheres: Lambert as lab 4 where the ray meets the unit sphere") {
    Tessellation lab;
    // The ray through a pixel centre meets the unit sphere at the normal N;
    // the colour is 0.8 max(N . L, 0). Fine levels shade within 0.02 of it.
    const glm::mat4 inverse =
        glm::inverse(glm::perspective(glm::radians(45.0f), 1.0f, 0.1f, 100.0f) *
                     glm::lookAt(glm::vec3(0, 0, 4), glm::vec3(0.0f), glm::vec3(0, 1, 0)));
    auto expected = [&](int x, int y) {
        const glm::vec4 far = inverse * glm::vec4(ndc_of(x, y), 1.0f, 1.0f);
        const glm::vec3 eye(0, 0, 4), d = glm::normalize(glm::vec3(far) / far.w - eye);
        const float b = glm::dot(eye, d), c = glm::dot(eye, eye) - 1.0f;
        const glm::vec3 n = eye + (-b - std::sqrt(b * b - c)) * d;
        return glm::vec3(0.8f * std::max(glm::dot(n, kLight), 0.0f));
    };
    for (const std::string scene : {"sphere", "param_sphere"}) {
        CAPTURE(scene);
        const fw::RenderOutput out = lab.render(
            {{"scene", scene}, {"inner", "32"}, {"outer", "32"}, {"wireframe", "false"}});
        for (const glm::ivec2 at :
             {glm::ivec2(256, 256), glm::ivec2(340, 340), glm::ivec2(200, 300),
              glm::ivec2(300, 180), glm::ivec2(160, 170)})
            CHECK(fw::test::probe_rgb(out.color, at.x, at.y, expected(at.x, at.y), 0.02f));
        CHECK(fw::test::probe_rgb(out.color, 20, 20, kBlack));
    }
}
