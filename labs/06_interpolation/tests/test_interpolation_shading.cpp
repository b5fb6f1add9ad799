// Lab 6 `interpolation`, scene shading: Gouraud, Phong and toon shading of
// the unit sphere. Expectations come from a CPU ray cast of the exact sphere
// and the lecture's model with the sheet's numbers
// (labs/06_interpolation/README.md), never from a reference image or the
// lab's code.
#include <cmath>
#include <string>
#include <vector>

#include "interpolation_test.hpp"

using namespace interpolation_test;

namespace {

const glm::vec3 kKa{0.1f}, kKd{0.8f, 0.3f, 0.2f}, kKs{0.5f};
constexpr float kShine = 32.0f;
const glm::vec3 kDefaultLight{2, 2, 3};

// The lecture's model at the sphere point N (= its normal, radius 1), with
// the sheet's clamping: cosines below 0 count as 0, and no highlight where
// N.L <= 0. La = Le = 1. Unclamped: the framebuffer clamps to [0, 1].
glm::vec3 blinn_phong(glm::vec3 n, glm::vec3 light) {
    const glm::vec3 l = glm::normalize(light - n), v = glm::normalize(kSphereEye - n);
    const float n_dot_l = glm::dot(n, l);
    const float spec =
        n_dot_l > 0 ? std::pow(glm::max(glm::dot(n, glm::normalize(l + v)), 0.0f), kShine) : 0.0f;
    return kKa + kKd * glm::max(n_dot_l, 0.0f) + kKs * spec;
}

// The sphere point that pixel (x, y) sees, if any.
bool sphere_hit(int x, int y, glm::vec3& n) {
    static const glm::mat4 inverse_clip = glm::inverse(sphere_clip());
    const Ray r = window_ray(inverse_clip, {x + 0.5f, y + 0.5f});
    // |o + t d|^2 = 1 with |d| = 1: t^2 + 2 (o.d) t + |o|^2 - 1 = 0.
    const float b = glm::dot(r.origin, r.direction);
    const float disc = b * b - (glm::dot(r.origin, r.origin) - 1.0f);
    if (disc < 0) return false;
    n = r.origin + (-b - std::sqrt(disc)) * r.direction;
    return true;
}

float n_dot_v(glm::vec3 n) { return glm::dot(n, glm::normalize(kSphereEye - n)); }

// The sphere point where N.H is largest, the centre of the highlight: a
// search over the sphere's angles on a 1-degree grid, then refined.
glm::vec3 highlight_point(glm::vec3 light) {
    auto point = [](float theta, float phi) {
        return glm::vec3(std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
                         std::cos(theta));
    };
    auto n_dot_h = [&](glm::vec3 n) {
        return glm::dot(n,
                        glm::normalize(glm::normalize(light - n) + glm::normalize(kSphereEye - n)));
    };
    float best_theta = 0, best_phi = 0, best = -2;
    const float degree = glm::radians(1.0f);
    for (float theta = 0; theta <= glm::pi<float>(); theta += degree)
        for (float phi = 0; phi < glm::two_pi<float>(); phi += degree)
            if (const float f = n_dot_h(point(theta, phi)); f > best)
                best = f, best_theta = theta, best_phi = phi;
    for (float step = degree; step > 1e-6f; step *= 0.5f)
        for (int i = 0; i < 20; ++i)
            for (glm::vec2 d :
                 {glm::vec2(1, 0), glm::vec2(-1, 0), glm::vec2(0, 1), glm::vec2(0, -1)})
                if (const float f = n_dot_h(point(best_theta + step * d.x, best_phi + step * d.y));
                    f > best)
                    best = f, best_theta += step * d.x, best_phi += step * d.y;
    return point(best_theta, best_phi);
}

// The centre of the brightest pixels of `img` by the blue channel, which the
// highlight dominates: 0.5 there against at most 0.2 for the diffuse term.
glm::vec2 brightest(const fw::Image& img) {
    int top = -1;
    glm::vec2 sum(0);
    int count = 0;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            const int b = img.at(x, y).b;
            if (b > top) top = b, sum = glm::vec2(0), count = 0;
            if (b == top) sum += glm::vec2(x + 0.5f, y + 0.5f), ++count;
        }
    return sum / float(count);
}

fw::RenderOutput render_sphere(Lab& lab, const char* shading, glm::vec3 light = kDefaultLight) {
    return lab.render({{"scene", "shading"},
                       {"shading", shading},
                       {"light_x", std::to_string(light.x)},
                       {"light_y", std::to_string(light.y)},
                       {"light_z", std::to_string(light.z)}});
}

}  // namespace

TEST_CASE("interpolation: shading: Phong's highlight is where N.H is largest") {
    Lab lab;
    for (glm::vec3 light : {kDefaultLight, glm::vec3(-2, 2, 3), glm::vec3(1, -3, 2)}) {
        CAPTURE(light.x);
        CAPTURE(light.y);
        CAPTURE(light.z);
        const fw::RenderOutput out = render_sphere(lab, "phong", light);
        const glm::vec2 expected = to_window(sphere_clip() * glm::vec4(highlight_point(light), 1));
        const glm::vec2 observed = brightest(out.color);
        MESSAGE("highlight: expected (" << expected.x << ", " << expected.y << ") observed ("
                                        << observed.x << ", " << observed.y << ")");
        CHECK(glm::distance(expected, observed) <= 3.0f);
    }
}

TEST_CASE("interpolation: shading: Phong is the lecture's model at every pixel") {
    Lab lab;
    const fw::RenderOutput out = render_sphere(lab, "phong");
    // Away from the outline, where the 1280 flat facets of the mesh and the
    // exact sphere part.
    PixelTally tally{"Blinn-Phong at the ray-cast sphere point", 4.0f / 255.0f};
    glm::vec3 n;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x)
            if (sphere_hit(x, y, n) && n_dot_v(n) > 0.3f)
                tally.check(x, y, glm::clamp(blinn_phong(n, kDefaultLight), 0.0f, 1.0f),
                            rgb(out.color, x, y));
    tally.report();
    CHECK(tally.tested > 100000);
    CHECK(tally.failed == 0);
    CHECK(fw::test::probe_rgb(out.color, 10, 10, glm::vec3(0)));
    CHECK(out.stats["primitives_generated"] == 1280);
}

TEST_CASE("interpolation: shading: Gouraud misses the highlight's shape, not the diffuse light") {
    Lab lab;
    const fw::RenderOutput gouraud = render_sphere(lab, "gouraud");
    const fw::RenderOutput phong = render_sphere(lab, "phong");
    const glm::vec2 h = to_window(sphere_clip() * glm::vec4(highlight_point(kDefaultLight), 1));
    float near_highlight = 0.0f;
    for (int y = int(h.y) - 20; y <= int(h.y) + 20; ++y)
        for (int x = int(h.x) - 20; x <= int(h.x) + 20; ++x)
            near_highlight = glm::max(
                near_highlight, max_difference(rgb(gouraud.color, x, y), rgb(phong.color, x, y)));
    MESSAGE(
        "largest Gouraud - Phong difference within 20 pixels of the highlight: " << near_highlight);
    CHECK(near_highlight > 0.05f);
    // Where the highlight is negligible (cos(delta)^32 < 0.001) and away
    // from the terminator (N.L = 0, where max(0, N.L) bends) the colour
    // varies slowly and the per-vertex model interpolates it well.
    PixelTally tally{"Gouraud against Phong without highlight", 3.0f / 255.0f};
    glm::vec3 n;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            if (!sphere_hit(x, y, n) || n_dot_v(n) < 0.3f) continue;
            const glm::vec3 l = glm::normalize(kDefaultLight - n);
            if (std::fabs(glm::dot(n, l)) < 0.2f) continue;
            const float n_dot_h = glm::dot(n, glm::normalize(l + glm::normalize(kSphereEye - n)));
            if (std::pow(glm::max(n_dot_h, 0.0f), kShine) < 1e-3f)
                tally.check(x, y, rgb(phong.color, x, y), rgb(gouraud.color, x, y));
        }
    tally.report();
    CHECK(tally.tested > 50000);
    CHECK(tally.failed == 0);
}

TEST_CASE("interpolation: shading: toon shows black, kd and kd / 2, and nothing else") {
    Lab lab;
    const fw::RenderOutput out = render_sphere(lab, "toon");
    // Distinct colours, 2/255 apart at least.
    std::vector<glm::vec3> colors;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const glm::vec3 c = rgb(out.color, x, y);
            bool known = false;
            for (glm::vec3 k : colors) known |= max_difference(c, k) <= 2.0f / 255.0f;
            if (!known) colors.push_back(c);
        }
    for (glm::vec3 c : colors) MESSAGE("colour (" << c.r << ", " << c.g << ", " << c.b << ")");
    CHECK(colors.size() == 3);
    // Each pixel, where N.V and N.L are clearly on one side of 0.2 and 0.5.
    PixelTally tally{"toon tone", 2.0f / 255.0f};
    glm::vec3 n;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            if (!sphere_hit(x, y, n)) continue;
            const float nv = n_dot_v(n), nl = glm::dot(n, glm::normalize(kDefaultLight - n));
            if (std::fabs(nv - 0.2f) < 0.03f || std::fabs(nl - 0.5f) < 0.03f) continue;
            tally.check(x, y,
                        nv < 0.2f   ? glm::vec3(0)
                        : nl > 0.5f ? kKd
                                    : 0.5f * kKd,
                        rgb(out.color, x, y));
        }
    tally.report();
    CHECK(tally.failed == 0);
    CHECK(fw::test::probe_rgb(out.color, 256, 256, kKd, 2.0f / 255.0f));
}

TEST_CASE("interpolation: shading: subdiv n draws 20 * 4^n triangles from 10 * 4^n + 2 vertices") {
    Lab lab;
    for (int subdiv = 0; subdiv <= 4; ++subdiv) {
        CAPTURE(subdiv);
        const fw::RenderOutput out =
            lab.render({{"scene", "shading"}, {"subdiv", std::to_string(subdiv)}});
        const int power = 1 << (2 * subdiv);
        CHECK(out.stats["primitives_generated"] == 20 * power);
        CHECK(out.stats["lab_stats"]["triangles"] == 20 * power);
        CHECK(out.stats["lab_stats"]["vertices"] == 10 * power + 2);
    }
}

TEST_CASE("interpolation: shading: dragging moves the light in x and y") {
    Lab lab;
    fw::ParamValues p = fw::default_params(lab.lab);
    // scene triangle: no light
    CHECK_FALSE(lab.renderer.lab().on_drag(p, fw::Frame{}, 10, 10));
    p.set("scene", "shading");
    CHECK(lab.renderer.lab().on_drag(p, fw::Frame{}, 50, -25));
    CHECK(p.number("light_x") > 2.0f);
    CHECK(p.number("light_y") < 2.0f);
    CHECK(p.number("light_z") == 3.0f);
    // The light stays within its declared range, [-10, 10].
    CHECK(lab.renderer.lab().on_drag(p, fw::Frame{}, 5000, -5000));
    CHECK(p.number("light_x") == 10.0f);
    CHECK(p.number("light_y") == -10.0f);
}
