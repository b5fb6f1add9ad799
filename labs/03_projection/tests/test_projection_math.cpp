// Lab 3 `projection` without rendering: the declaration, the window's mouse
// controls, and the student functions, each against GLM (glm::lookAt,
// glm::perspective in radians, glm::ortho, glm::perspectiveRH_ZO,
// glm::project) on edge cases and on 1000 random inputs from a fixed seed,
// plus the lecture's own cases computed in closed form.
#include <cmath>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "camera_math.hpp"
#include "framework/lab.hpp"
#include "tests/support/test_support.hpp"

namespace {

constexpr int kRandomCases = 1000;
constexpr unsigned kSeed = 20240303;

// |observed - expected| <= tol * max(1, |expected|) for every entry, as the
// grader compares; logs Expected/Observed for the first entry that is not.
template <class T, int N>
bool close(const T& observed, const T& expected, float tol, const std::string& what) {
    const float* o = &observed[0][0];
    const float* e = &expected[0][0];
    for (int i = 0; i < N; ++i) {
        if (std::fabs(o[i] - e[i]) <= tol * std::fmax(1.0f, std::fabs(e[i]))) continue;
        MESSAGE(what << ": entry " << i << " expected " << e[i] << " observed " << o[i]);
        return false;
    }
    return true;
}
bool close(const glm::mat4& o, const glm::mat4& e, float tol, const std::string& what) {
    return close<glm::mat4, 16>(o, e, tol, what);
}
bool close(glm::vec3 o, glm::vec3 e, float tol, const std::string& what) {
    const glm::mat3 om(o, glm::vec3(0), glm::vec3(0)), em(e, glm::vec3(0), glm::vec3(0));
    return close<glm::mat3, 9>(om, em, tol, what);
}

std::string text(glm::vec3 v) {
    char buf[96];
    std::snprintf(buf, sizeof buf, "(%g, %g, %g)", v.x, v.y, v.z);
    return buf;
}

// Perspective arguments in the lab's domain: far always beyond near.
struct Frustum {
    float fov, aspect, n, f;
};
Frustum random_frustum(std::mt19937& rng) {
    std::uniform_real_distribution<float> fov(10, 150), aspect(0.25f, 4), n(0.0001f, 10);
    std::uniform_real_distribution<float> extra(0.01f, 1000);
    const float near = n(rng);
    return {fov(rng), aspect(rng), near, near + extra(rng)};
}
const Frustum kEdgeFrustums[] = {
    {60, 1, 1, 50},          // the lab's defaults
    {90, 1, 0.1f, 100},      // cot(45 deg) = 1
    {10, 4, 0.0001f, 1000},  // narrow, wide, the smallest near
    {150, 0.25f, 9, 10},     // wide, tall, a thin slab
    {60, 1.5f, 0.001f, 50},  // the z-fighting near plane
};

// The NDC depth z_clip / w_clip of the eye-space point (0, 0, z, 1).
float ndc_depth(const glm::mat4& P, float z) {
    const glm::vec4 clip = P * glm::vec4(0, 0, z, 1);
    return clip.z / clip.w;
}

}  // namespace

TEST_CASE("projection: the declaration has the sheet's parameters and defaults") {
    const fw::RegisteredLab& lab = fw::test::this_lab();
    const fw::ParamValues p = fw::default_params(lab);
    CHECK(p.text("scene") == "cards");
    CHECK(p.text("show") == "color");
    CHECK(p.text("mode") == "perspective");
    CHECK(p.number("fov") == 60);
    CHECK(p.number("near") == 1);
    CHECK(p.number("far") == 50);
    CHECK(p.number("ortho_size") == 2);
    for (const char* name : {"eye_x", "eye_y", "eye_z", "target_x", "target_y"})
        CHECK(p.number(name) == 0);
    CHECK(p.number("target_z") == -1);
    for (const fw::Param& param : lab.info.params) {
        INFO("parameter " << param.name);
        CHECK(!param.help_text.empty());
        CHECK(param.shortcut != 0);
        if (param.name == "fov") CHECK((param.min == 10 && param.max == 150));
        if (param.name == "near") CHECK((param.min == doctest::Approx(0.0001) && param.max == 10));
    }
    std::vector<std::string> functions;
    for (const fw::UnitFunction& f : lab.info.functions) functions.push_back(f.name);
    CHECK(functions == std::vector<std::string>{"lookAt", "perspective", "orthographic",
                                                "perspective01", "viewport"});
}

TEST_CASE("projection: dragging orbits the eye about the target, the wheel zooms") {
    const fw::RegisteredLab& reg = fw::test::this_lab();
    std::unique_ptr<fw::Lab> lab = reg.create();
    fw::ParamValues p = fw::default_params(reg);
    p.set("eye_z", "4");
    p.set("target_z", "0");
    auto eye = [&] { return glm::vec3(p.number("eye_x"), p.number("eye_y"), p.number("eye_z")); };
    // Right: the scene turns right, so the eye goes left (-x), still 4 away.
    CHECK(lab->on_drag(p, fw::Frame{}, 50, 0));
    CHECK(eye().x < -1.0f);
    CHECK(glm::length(eye()) == doctest::Approx(4.0f).epsilon(1e-5));
    CHECK(eye().y == doctest::Approx(0.0f));
    // Far down: the eye rises, but stops short of straight above the target.
    CHECK(lab->on_drag(p, fw::Frame{}, 0, -10000));
    CHECK(glm::length(eye()) == doctest::Approx(4.0f).epsilon(1e-5));
    CHECK(eye().y > 3.9f);
    CHECK(lab->validate(p).empty());
    // The wheel: 5 degrees a step, within [10, 150].
    CHECK(lab->on_scroll(p, fw::Frame{}, 2));
    CHECK(p.number("fov") == 50);
    lab->on_scroll(p, fw::Frame{}, 100);
    CHECK(p.number("fov") == 10);
    lab->on_scroll(p, fw::Frame{}, -100);
    CHECK(p.number("fov") == 150);
}

TEST_CASE("projection math: lookAt agrees with glm::lookAt") {
    const glm::vec3 up(0, 1, 0);
    struct Case {
        glm::vec3 eye, target, up;
    };
    const Case edges[] = {
        {{0, 0, 0}, {0, 0, -1}, up},            // the lab's default: the identity
        {{0, 0, 5}, {0, 0, 0}, up},             // a translation only
        {{0, 0, 0}, {1, 0, 0}, up},             // looking down +x
        {{0, 0, 0}, {0, 0, 1}, up},             // looking back, down +z
        {{3, 2, 1}, {-1, 0.5f, -8}, up},        // anywhere
        {{1, 1, 1}, {0, 0, 0}, {0, 0, 1}},      // another up
        {{0, 0, 0}, {0, -1, -1e-3f}, up},       // nearly straight down
        {{0, 0, 0}, {0, 0, -1}, {0, 5, 0}},     // up need not be unit length
        {{0, 0, 0}, {0, 0, -1}, {0.3f, 1, 0}},  // nor perpendicular to the view
    };
    for (const Case& c : edges) {
        const std::string what =
            "lookAt(" + text(c.eye) + ", " + text(c.target) + ", " + text(c.up) + ")";
        CHECK(close(projection::lookAt(c.eye, c.target, c.up), glm::lookAt(c.eye, c.target, c.up),
                    1e-5f, what));
    }
    CHECK(close(projection::lookAt({0, 0, 0}, {0, 0, -1}, up), glm::mat4(1.0f), 1e-6f,
                "the default camera"));

    std::mt19937 rng(kSeed);
    std::uniform_real_distribution<float> coord(-10, 10);
    auto random_vec = [&] { return glm::vec3(coord(rng), coord(rng), coord(rng)); };
    int failures = 0;
    for (int i = 0; i < kRandomCases; ++i) {
        const glm::vec3 eye = random_vec(), target = random_vec(), u = random_vec();
        const std::string what = "case " + std::to_string(i) + ": lookAt(" + text(eye) + ", " +
                                 text(target) + ", " + text(u) + ")";
        failures +=
            !close(projection::lookAt(eye, target, u), glm::lookAt(eye, target, u), 1e-4f, what);
    }
    CHECK_MESSAGE(failures == 0, failures << " of " << kRandomCases << " random cases differ");
}

TEST_CASE("projection math: lookAt sends the eye to the origin and the target onto -z") {
    std::mt19937 rng(kSeed + 1);
    std::uniform_real_distribution<float> coord(-10, 10);
    auto random_vec = [&] { return glm::vec3(coord(rng), coord(rng), coord(rng)); };
    int failures = 0;
    for (int i = 0; i < kRandomCases; ++i) {
        const glm::vec3 eye = random_vec(), target = random_vec();
        const glm::mat4 V = projection::lookAt(eye, target, {0, 1, 0});
        const float distance = glm::length(target - eye);
        const std::string what =
            "case " + std::to_string(i) + ": eye " + text(eye) + ", target " + text(target);
        // Expected: eye -> (0, 0, 0), target -> (0, 0, -|target - eye|),
        // and a point above the eye stays in the upper half (y > 0).
        bool pass = close(glm::vec3(V * glm::vec4(eye, 1)), glm::vec3(0), 1e-4f, what + ", eye");
        pass = close(glm::vec3(V * glm::vec4(target, 1)), glm::vec3(0, 0, -distance), 1e-4f,
                     what + ", target") &&
               pass;
        pass = (V * glm::vec4(eye + glm::vec3(0, 1, 0), 1)).y >= 0.0f && pass;
        // The rotation part is orthonormal: V^T V = I on the upper 3 x 3.
        const glm::mat3 R(V);
        pass = close(glm::mat4(glm::transpose(R) * R), glm::mat4(1.0f), 1e-5f, what + ", R^T R") &&
               pass;
        failures += !pass;
    }
    CHECK_MESSAGE(failures == 0, failures << " of " << kRandomCases << " random cases fail");
}

TEST_CASE("projection math: perspective agrees with glm::perspective (radians)") {
    for (const Frustum& c : kEdgeFrustums) {
        CAPTURE(c.fov);
        CAPTURE(c.aspect);
        CAPTURE(c.n);
        CAPTURE(c.f);
        CHECK(close(projection::perspective(c.fov, c.aspect, c.n, c.f),
                    glm::perspective(glm::radians(c.fov), c.aspect, c.n, c.f), 1e-5f,
                    "perspective"));
        CHECK(close(projection::perspective01(c.fov, c.aspect, c.n, c.f),
                    glm::perspectiveRH_ZO(glm::radians(c.fov), c.aspect, c.n, c.f), 1e-5f,
                    "perspective01"));
    }
    std::mt19937 rng(kSeed + 2);
    int failures = 0;
    for (int i = 0; i < kRandomCases; ++i) {
        const Frustum c = random_frustum(rng);
        char what[160];
        std::snprintf(what, sizeof what, "case %d: (fov %g, aspect %g, near %g, far %g)", i, c.fov,
                      c.aspect, c.n, c.f);
        failures += !close(projection::perspective(c.fov, c.aspect, c.n, c.f),
                           glm::perspective(glm::radians(c.fov), c.aspect, c.n, c.f), 1e-5f,
                           std::string("perspective ") + what);
        failures += !close(projection::perspective01(c.fov, c.aspect, c.n, c.f),
                           glm::perspectiveRH_ZO(glm::radians(c.fov), c.aspect, c.n, c.f), 1e-5f,
                           std::string("perspective01 ") + what);
    }
    CHECK_MESSAGE(failures == 0, failures << " random results differ");
}

TEST_CASE("projection math: the lecture's depths: near -> -1, far -> +1, and the halfway point") {
    for (const Frustum& c : kEdgeFrustums) {
        CAPTURE(c.n);
        CAPTURE(c.f);
        const glm::mat4 P = projection::perspective(c.fov, c.aspect, c.n, c.f);
        const glm::mat4 P01 = projection::perspective01(c.fov, c.aspect, c.n, c.f);
        // (0, 0, -near, 1) -> NDC depth -1 ([0, 1] variant: 0); (0, 0, -far, 1)
        // -> +1 (1). The point halfway, z = -(n + f) / 2, lands at
        // (f - n) / (f + n) (variant: f / (f + n)), close to the far end.
        const float half = -(c.n + c.f) / 2;
        CHECK(ndc_depth(P, -c.n) == doctest::Approx(-1.0).epsilon(1e-6));
        CHECK(ndc_depth(P, -c.f) == doctest::Approx(1.0).epsilon(1e-6));
        CHECK(ndc_depth(P, half) == doctest::Approx((c.f - c.n) / (c.f + c.n)).epsilon(1e-5));
        CHECK(ndc_depth(P01, -c.n) == doctest::Approx(0.0).epsilon(1e-6));
        CHECK(ndc_depth(P01, -c.f) == doctest::Approx(1.0).epsilon(1e-6));
        CHECK(ndc_depth(P01, half) == doctest::Approx(c.f / (c.f + c.n)).epsilon(1e-5));
        // The top of the view at distance 1 reaches y = 1, the right edge x = 1.
        const float t = std::tan(glm::radians(c.fov) / 2);
        const glm::vec4 corner = P * glm::vec4(t * c.aspect, t, -1, 1);
        CHECK(corner.x / corner.w == doctest::Approx(1.0).epsilon(1e-5));
        CHECK(corner.y / corner.w == doctest::Approx(1.0).epsilon(1e-5));
    }
    // The sheet's defaults, near 1 and far 50: halfway (z = -25.5) is at
    // NDC 49/51 = 0.96, window depth 50/51 = 0.98.
    const glm::mat4 P = projection::perspective(60, 1, 1, 50);
    CHECK(ndc_depth(P, -25.5f) == doctest::Approx(49.0 / 51.0).epsilon(1e-6));
}

TEST_CASE("projection math: orthographic agrees with glm::ortho") {
    struct Box {
        float l, r, b, t, n, f;
    };
    const Box edges[] = {
        {-1, 1, -1, 1, -1, 1},        // the NDC cube itself (near -1: z = +1 is the near face)
        {-2, 2, -2, 2, 1, 50},        // the lab's orthographic default, square frame
        {-1, 3, -0.5f, 2, 0.1f, 10},  // off centre
        {-10, -5, 5, 10, -5, 5},      // the whole box to one side, near behind the eye
        {-0.1f, 0.1f, -0.1f, 0.1f, 0.0001f, 1000},
    };
    for (const Box& c : edges) {
        CAPTURE(c.l);
        CAPTURE(c.r);
        CAPTURE(c.n);
        CAPTURE(c.f);
        const glm::mat4 O = projection::orthographic(c.l, c.r, c.b, c.t, c.n, c.f);
        CHECK(close(O, glm::ortho(c.l, c.r, c.b, c.t, c.n, c.f), 1e-5f, "orthographic"));
        // Its corners: (l, b, -n) -> (-1, -1, -1) and (r, t, -f) -> (1, 1, 1).
        CHECK(close(glm::vec3(O * glm::vec4(c.l, c.b, -c.n, 1)), glm::vec3(-1), 1e-5f,
                    "near corner"));
        CHECK(
            close(glm::vec3(O * glm::vec4(c.r, c.t, -c.f, 1)), glm::vec3(1), 1e-5f, "far corner"));
    }
    std::mt19937 rng(kSeed + 3);
    std::uniform_real_distribution<float> lo(-10, -0.1f), hi(0.1f, 10), n(-5, 5), depth(1, 100);
    int failures = 0;
    for (int i = 0; i < kRandomCases; ++i) {
        const Box c{lo(rng), hi(rng), lo(rng), hi(rng), n(rng), 0};
        const float f = c.n + depth(rng);
        failures +=
            !close(projection::orthographic(c.l, c.r, c.b, c.t, c.n, f),
                   glm::ortho(c.l, c.r, c.b, c.t, c.n, f), 1e-5f, "case " + std::to_string(i));
    }
    CHECK_MESSAGE(failures == 0, failures << " of " << kRandomCases << " random cases differ");
}

TEST_CASE("projection math: viewport agrees with glm::project and glDepthRange(0, 1)") {
    struct Case {
        glm::vec3 ndc;
        int width, height;
        glm::vec3 window;  // by hand from the GL spec's x_w = (w / 2) x_d + w / 2, ...
    };
    const Case edges[] = {
        {{-1, -1, -1}, 512, 512, {0, 0, 0}},
        {{1, 1, 1}, 512, 512, {512, 512, 1}},
        {{0, 0, 0}, 512, 512, {256, 256, 0.5f}},
        {{0.5f, -0.5f, 0.25f}, 640, 480, {480, 120, 0.625f}},
        {{-1, 1, 0}, 1, 1, {0, 1, 0.5f}},
        {{2, -3, 3}, 100, 50, {150, -50, 2}},  // outside NDC: the same straight line
    };
    for (const Case& c : edges) {
        CAPTURE(c.width);
        CAPTURE(c.height);
        CHECK(close(projection::viewport(c.ndc, c.width, c.height), c.window, 1e-6f,
                    "viewport" + text(c.ndc)));
    }
    std::mt19937 rng(kSeed + 4);
    std::uniform_real_distribution<float> ndc(-1.5f, 1.5f);
    std::uniform_int_distribution<int> size(1, 4096);
    int failures = 0;
    for (int i = 0; i < kRandomCases; ++i) {
        const glm::vec3 p(ndc(rng), ndc(rng), ndc(rng));
        const int w = size(rng), h = size(rng);
        // glm::project with identity matrices is exactly the viewport mapping.
        const glm::vec3 expected =
            glm::project(p, glm::mat4(1.0f), glm::mat4(1.0f), glm::vec4(0, 0, w, h));
        failures += !close(projection::viewport(p, w, h), expected, 1e-5f,
                           "case " + std::to_string(i) + ": " + text(p));
    }
    CHECK_MESSAGE(failures == 0, failures << " of " << kRandomCases << " random cases differ");
}
