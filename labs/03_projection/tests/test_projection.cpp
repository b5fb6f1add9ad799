// Lab 3 `projection`, rendered. Every expectation is computed here from the
// sheet's numbers (docs/labs.md, labs/03_projection/README.md) with closed forms
// or GLM, never read from a reference image or from the lab's own code.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/gtc/matrix_transform.hpp>
#include <string>
#include <utility>
#include <vector>

#include "framework/checkpoints.hpp"
#include "framework/lab.hpp"
#include "framework/render.hpp"
#include "tests/support/test_support.hpp"

namespace {

constexpr int kSize = 512;
const glm::vec3 kBlack{0, 0, 0};

// The sheet's cards: centre (u d t, 0, -d), half-size 0.15 d t, t = tan 30.
const float kT = std::tan(glm::radians(30.0f));
constexpr float kU[5] = {-0.8f, -0.4f, 0.0f, 0.4f, 0.8f};
constexpr float kD[5] = {2, 4, 8, 16, 32};
const glm::vec3 kCardColors[5] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 0}, {1, 0, 1}};
// scene=zfight: red (front) and blue (0.002 behind) 16 x 16 quads centred at
// (0, 0, -20), leaning back by 30 degrees about x.
const glm::vec3 kZRed{0.9f, 0.2f, 0.2f}, kZBlue{0.2f, 0.2f, 0.9f};

using fw::test::Settings;

struct Projection : fw::test::LabUnderTest {
    Projection() : LabUnderTest() {}
};

// The camera the sheet defines for these parameters, from GLM.
glm::mat4 clip_from_world(const fw::ParamValues& p, int w, int h) {
    const float aspect = float(w) / float(h), n = p.number("near"), f = p.number("far");
    const glm::vec3 eye(p.number("eye_x"), p.number("eye_y"), p.number("eye_z"));
    const glm::vec3 target(p.number("target_x"), p.number("target_y"), p.number("target_z"));
    const float s = p.number("ortho_size");
    const glm::mat4 P = p.text("mode") == "orthographic"
                            ? glm::ortho(-s * aspect, s * aspect, -s, s, n, f)
                            : glm::perspective(glm::radians(p.number("fov")), aspect, n, f);
    return P * glm::lookAt(eye, target, glm::vec3(0, 1, 0));
}

// Ray casting, independent of the rasterizer: the card (0..4) that the ray
// through window point (x, y) meets first between the near and far planes,
// or -1. The ray runs from the point's unprojection at NDC depth -1 to +1.
int card_hit(const glm::mat4& world_from_clip, float ndc_x, float ndc_y) {
    const glm::vec4 a = world_from_clip * glm::vec4(ndc_x, ndc_y, -1, 1);
    const glm::vec4 b = world_from_clip * glm::vec4(ndc_x, ndc_y, 1, 1);
    const glm::vec3 from = glm::vec3(a) / a.w, dir = glm::vec3(b) / b.w - from;
    int best = -1;
    float best_s = 2.0f;
    for (int i = 0; i < 5; ++i) {
        if (dir.z == 0.0f) continue;
        const float s = (-kD[i] - from.z) / dir.z;  // the card's plane z = -d
        if (s < 0.0f || s > 1.0f || s >= best_s) continue;
        const glm::vec3 q = from + s * dir;
        const float half = 0.15f * kD[i] * kT;
        if (std::fabs(q.x - kU[i] * kD[i] * kT) <= half && std::fabs(q.y) <= half) {
            best = i;
            best_s = s;
        }
    }
    return best;
}

// Compares the image with the ray caster at every pixel whose 3 x 3
// neighbourhood the caster agrees on (edges pass between pixel centres, so
// pixels next to an edge are left out). Returns the pixels compared.
long check_against_rays(const fw::Image& img, const fw::ParamValues& p) {
    const int w = img.width, h = img.height;
    const glm::mat4 inv = glm::inverse(clip_from_world(p, w, h));
    std::vector<int> hit(size_t(w) * size_t(h));
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            hit[size_t(y) * w + x] = card_hit(inv, (x + 0.5f) / w * 2 - 1, (y + 0.5f) / h * 2 - 1);
    long compared = 0, wrong = 0;
    for (int y = 1; y + 1 < h; ++y)
        for (int x = 1; x + 1 < w; ++x) {
            const int c = hit[size_t(y) * w + x];
            bool uniform = true;
            for (int dy = -1; dy <= 1; ++dy)
                for (int dx = -1; dx <= 1; ++dx) uniform &= hit[size_t(y + dy) * w + x + dx] == c;
            if (!uniform) continue;
            ++compared;
            const glm::vec3 expected = c < 0 ? kBlack : kCardColors[c];
            const fw::Rgba8 o = img.at(x, y);
            if (glm::vec3(o.r, o.g, o.b) / 255.0f == expected) continue;
            if (++wrong <= 5) CHECK(fw::test::probe_rgb(img, x, y, expected));
        }
    CHECK_MESSAGE(wrong == 0, wrong << " of " << compared << " pixels differ from the ray caster");
    return compared;
}

long count_color(const fw::Image& img, glm::vec3 color, int x0, int y0, int x1, int y1) {
    long n = 0;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) {
            const fw::Rgba8 o = img.at(x, y);
            n += glm::all(glm::lessThanEqual(glm::abs(glm::vec3(o.r, o.g, o.b) / 255.0f - color),
                                             glm::vec3(1.5f / 255.0f)));
        }
    return n;
}

// Window depth of a point at distance z in front of the eye, glDepthRange(0, 1).
double perspective_depth(double n, double f, double z) { return f / (f - n) * (1.0 - n / z); }
double orthographic_depth(double n, double f, double z) { return (z - n) / (f - n); }

// The window pixel holding NDC coordinate v of a frame `size` pixels wide.
int pixel(double v, int size) { return int(std::floor((v + 1.0) * 0.5 * size)); }

}  // namespace

TEST_CASE("projection: cards: each covers the NDC square tan 30 / tan(fov / 2) gives") {
    Projection lab;
    struct View {
        float fov;
        int w, h;
    };
    for (const View v : {View{60, 512, 512}, View{40, 512, 512}, View{90, 512, 512},
                         View{120, 512, 512}, View{60, 640, 400}}) {
        CAPTURE(v.fov);
        CAPTURE(v.w);
        CAPTURE(v.h);
        fw::RenderOutput out = lab.render({{"fov", std::to_string(v.fov)}}, v.w, v.h);
        const float aspect = float(v.w) / float(v.h), k = kT / std::tan(glm::radians(v.fov) / 2);
        int seen = 0;
        for (int i = 0; i < 5; ++i) {
            CAPTURE(i);
            // NDC x = (u d t) / (a d tan(fov / 2)) = u k / a, half-size 0.15 k
            // (over a in x): the distance d cancels.
            const float cx = kU[i] * k / aspect, hx = 0.15f * k / aspect, hy = 0.15f * k;
            const float x0 = (cx - hx + 1) / 2 * v.w, x1 = (cx + hx + 1) / 2 * v.w;
            const float y0 = (1 - hy) / 2 * v.h, y1 = (1 + hy) / 2 * v.h;
            if (x0 < 2 || x1 > v.w - 2) continue;  // not wholly in the frame
            ++seen;
            const glm::vec3 c = kCardColors[i];
            const int xm = int((x0 + x1) / 2), ym = v.h / 2;
            CHECK(fw::test::probe_rgb(out.color, xm, ym, c));
            // First and last pixel centres inside each edge, and the first outside.
            CHECK(fw::test::probe_rgb(out.color, int(x0) + 1, ym, c));
            CHECK(fw::test::probe_rgb(out.color, int(x1) - 1, ym, c));
            CHECK(fw::test::probe_rgb(out.color, xm, int(y0) + 1, c));
            CHECK(fw::test::probe_rgb(out.color, xm, int(y1) - 1, c));
            CHECK(fw::test::probe_rgb(out.color, int(x0) - 1, ym, kBlack));
            CHECK(fw::test::probe_rgb(out.color, int(x1) + 1, ym, kBlack));
            CHECK(fw::test::probe_rgb(out.color, xm, int(y0) - 1, kBlack));
            CHECK(fw::test::probe_rgb(out.color, xm, int(y1) + 1, kBlack));
            // Its area in pixels, within one pixel all round.
            const long area = count_color(out.color, c, 0, 0, v.w, v.h);
            const double expected = double(x1 - x0) * double(y1 - y0);
            CHECK(std::fabs(area - expected) <= 2.0 * double(x1 - x0 + y1 - y0) + 4);
        }
        CHECK(seen >= 3);
    }
}

TEST_CASE("projection: every pixel agrees with a ray caster, for cameras and projections") {
    Projection lab;
    const std::vector<Settings> cases = {
        {},
        {{"fov", "90"}},
        {{"mode", "orthographic"}},  // no foreshortening: red in front of green
        {{"mode", "orthographic"}, {"ortho_size", "6"}},
        {{"eye_x", "2"}, {"eye_y", "1"}, {"eye_z", "3"}, {"target_z", "-8"}},
        {{"eye_z", "-40"}, {"target_z", "0"}, {"far", "60"}},  // from behind
        {{"near", "3"}},  // the near plane cuts the red card (d = 2) away
        {{"far", "10"}},  // the far plane cuts yellow (16) and magenta (32)
        {{"eye_x", "-6"}, {"target_x", "3"}, {"target_z", "-12"}, {"fov", "75"}},
    };
    for (const Settings& s : cases) {
        std::string what;
        for (const auto& [k, v] : s) what += k + "=" + v + " ";
        CAPTURE(what);
        fw::RenderOutput out = lab.render(s);
        CHECK(check_against_rays(out.color, lab.params(s)) > kSize * kSize / 2);
    }
    fw::RenderOutput wide = lab.render({{"mode", "orthographic"}}, 640, 360);
    CHECK(check_against_rays(wide.color, lab.params({{"mode", "orthographic"}})) > 640 * 180);
}

TEST_CASE("projection: cards: the depth buffer holds f (1 - n / d) / (f - n) at each card") {
    Projection lab;
    struct Case {
        double n, f;
        bool ortho;
    };
    // n = 1, f = 31: the yellow card (d = 16) lies halfway between near and
    // far, at window depth f / (f + n) = 31 / 32, not 1/2; magenta (d = 32)
    // is beyond far.
    for (const Case c : {Case{1, 50, false}, Case{1, 31, false}, Case{0.5, 100, false},
                         Case{0.001, 50, false}, Case{3, 50, false}, Case{1, 50, true}}) {
        CAPTURE(c.n);
        CAPTURE(c.f);
        CAPTURE(c.ortho);
        Settings s = {{"near", std::to_string(c.n)}, {"far", std::to_string(c.f)}};
        // Orthographic, ortho_size 20: every card centre in view (x = u d t / s).
        if (c.ortho) s.insert(s.end(), {{"mode", "orthographic"}, {"ortho_size", "20"}});
        fw::RenderOutput out = lab.render(s);
        const glm::mat4 inv = glm::inverse(clip_from_world(lab.params(s), kSize, kSize));
        for (int i = 0; i < 5; ++i) {
            CAPTURE(i);
            const int x = pixel(c.ortho ? kU[i] * kD[i] * kT / 20.0 : kU[i], kSize);
            // The card the ray through that pixel meets first (another, in
            // front of it, in orthographic; none where near or far clip it).
            const int hit = card_hit(inv, (x + 0.5f) / kSize * 2 - 1, 1.0f / kSize);
            CAPTURE(hit);
            const double depth = hit < 0   ? 1.0
                                 : c.ortho ? orthographic_depth(c.n, c.f, kD[hit])
                                           : perspective_depth(c.n, c.f, kD[hit]);
            CHECK(fw::test::probe_depth(out.depth, x, kSize / 2, float(depth), 1e-5f));
        }
        CHECK(fw::test::probe_depth(out.depth, 10, 10, 1.0f, 0.0f));
    }
    CHECK(perspective_depth(1, 31, 16) == doctest::Approx(31.0 / 32.0));
}

TEST_CASE("projection: lab render --depth-out writes the same depths as a PFM") {
    const std::string pfm = fw::test::out_dir() + "/cards.pfm";
    const std::string cmd = fw::test::bin_dir() + "/lab render projection --backend " +
                            fw::test::context_info().backend + " -o " + fw::test::out_dir() +
                            "/cards.png --depth-out " + pfm;
    const fw::test::CommandResult r = fw::test::run_command(cmd);
    INFO(cmd << "\n" << r.output);
    REQUIRE(r.exit_code == 0);
    const fw::DepthImage depth = fw::read_pfm(pfm);
    REQUIRE(depth.width == kSize);
    REQUIRE(depth.height == kSize);
    for (int i = 0; i < 5; ++i)
        CHECK(fw::test::probe_depth(depth, pixel(kU[i], kSize), kSize / 2,
                                    float(perspective_depth(1, 50, kD[i])), 1e-5f));
}

TEST_CASE("projection: show=depth draws (z - n) / (f - n) as grey") {
    Projection lab;
    for (const std::string mode : {"perspective", "orthographic"}) {
        CAPTURE(mode);
        const Settings s = {{"show", "depth"},
                            {"mode", mode},
                            {"ortho_size", "20"},
                            {"near", "1.5"},
                            {"far", "40"}};
        fw::RenderOutput out = lab.render(s);
        const glm::mat4 inv = glm::inverse(clip_from_world(lab.params(s), kSize, kSize));
        const bool ortho = mode == "orthographic";
        int cards = 0;
        for (int i = 0; i < 5; ++i) {
            CAPTURE(i);
            const int x = pixel(ortho ? kU[i] * kD[i] * kT / 20.0 : kU[i], kSize);
            const int hit = card_hit(inv, (x + 0.5f) / kSize * 2 - 1, 1.0f / kSize);
            REQUIRE(hit >= 0);
            cards += hit == i;
            const float grey = float((kD[hit] - 1.5) / (40 - 1.5));
            CHECK(fw::test::probe_rgb(out.color, x, kSize / 2, glm::vec3(grey), 1.5f / 255.0f));
        }
        CHECK(cards >= 4);
        CHECK(fw::test::probe_rgb(out.color, 10, 10, kBlack));
    }
}

TEST_CASE("projection: zfight: near = 1 shows only red, near = 0.001 lets blue through") {
    Projection lab;
    // The quads' corners, projected with GLM: the inner rectangle between
    // the top edge, the bottom edge and the narrower (top) half-width.
    const glm::mat4 model = glm::rotate(glm::translate(glm::mat4(1), {0, 0, -20}),
                                        glm::radians(-30.0f), glm::vec3(1, 0, 0));
    const glm::mat4 clip = clip_from_world(lab.params({}), kSize, kSize) * model;
    auto ndc = [&](float x, float y) {
        const glm::vec4 c = clip * glm::vec4(x, y, 0, 1);
        return glm::vec2(c) / c.w;
    };
    const glm::vec2 top_right = ndc(8, 8), bottom_left = ndc(-8, -8);
    const int x0 = pixel(-top_right.x, kSize) + 2, x1 = pixel(top_right.x, kSize) - 2;
    const int y0 = pixel(bottom_left.y, kSize) + 2, y1 = pixel(top_right.y, kSize) - 2;
    REQUIRE(x1 - x0 > 100);
    REQUIRE(y1 - y0 > 100);
    const long region = long(x1 - x0) * (y1 - y0);

    fw::RenderOutput far_near = lab.render({{"scene", "zfight"}, {"near", "1"}});
    CHECK(count_color(far_near.color, kZRed, x0, y0, x1, y1) == region);
    CHECK(count_color(far_near.color, kZBlue, 0, 0, kSize, kSize) == 0);
    CHECK(fw::test::probe_rgb(far_near.color, kSize / 2, kSize - 10, kBlack));

    // The depth at a pixel: where its ray meets red's plane, through the
    // point (0, 0, -20) with normal (0, sin 30, cos 30).
    const glm::vec3 normal(0, std::sin(glm::radians(30.0f)), std::cos(glm::radians(30.0f)));
    for (const glm::ivec2 at : {glm::ivec2(256, 256), glm::ivec2(200, 150), glm::ivec2(300, 300)}) {
        const float tx = ((at.x + 0.5f) / kSize * 2 - 1) * kT,
                    ty = ((at.y + 0.5f) / kSize * 2 - 1) * kT;
        const glm::vec3 ray(tx, ty, -1);
        const double z = -20.0 * normal.z / glm::dot(ray, normal);  // distance along -z
        CHECK(fw::test::probe_depth(far_near.depth, at.x, at.y, float(perspective_depth(1, 50, z)),
                                    1e-5f));
    }

    fw::RenderOutput tiny_near = lab.render({{"scene", "zfight"}, {"near", "0.001"}});
    const long blue = count_color(tiny_near.color, kZBlue, x0, y0, x1, y1);
    const long red = count_color(tiny_near.color, kZRed, x0, y0, x1, y1);
    MESSAGE("near 0.001: " << blue << " blue and " << red << " red of " << region << " pixels");
    CHECK(blue + red == region);
    CHECK(blue > region / 4);
}

TEST_CASE("projection: lab_stats report each centre through the student's matrices and viewport") {
    Projection lab;
    fw::RenderOutput out = lab.render({}, 640, 400);
    const nlohmann::json& centres = out.stats.at("lab_stats").at("centres");
    INFO(centres.dump());
    REQUIRE(centres.size() == 5);
    for (int i = 0; i < 5; ++i) {
        CAPTURE(i);
        // The default camera: NDC (u / a, 0), w_clip = d.
        const nlohmann::json& window = centres[size_t(i)].at("window");
        CHECK(window[0].get<double>() ==
              doctest::Approx((kU[i] / 1.6 + 1) / 2 * 640).epsilon(1e-5));
        CHECK(window[1].get<double>() == doctest::Approx(200).epsilon(1e-5));
        CHECK(window[2].get<double>() ==
              doctest::Approx(perspective_depth(1, 50, kD[i])).epsilon(1e-5));
        CHECK(centres[size_t(i)].at("clip")[3].get<double>() == doctest::Approx(kD[i]));
    }
}

TEST_CASE("projection: parameters that make no camera are refused with their names") {
    Projection lab;
    auto refused = [&](const Settings& s) {
        return fw::test::thrown<fw::UsageError>([&] { lab.render(s); });
    };
    fw::test::check_mentions(refused({{"near", "5"}, {"far", "5"}}),
                             {"far (5)", "near (5)", "must exceed"});
    fw::test::check_mentions(refused({{"near", "2"}, {"far", "1.5"}}), {"far (1.5)", "near (2)"});
    fw::test::check_mentions(refused({{"target_z", "0"}}), {"eye", "target", "move"});
    fw::test::check_mentions(refused({{"eye_y", "3"}, {"target_z", "0"}}),
                             {"parallel", "up (0, 1, 0)", "eye_x"});
    // The command line reports it and exits 2.
    const fw::test::CommandResult r = fw::test::run_command(
        fw::test::bin_dir() + "/lab render projection --set far=0.5 --backend " +
        fw::test::context_info().backend + " -o " + fw::test::out_dir() + "/x.png");
    CHECK(r.exit_code == 2);
    fw::test::check_mentions(r.output, {"far (0.5)", "near (1)"});
}

TEST_CASE(
    "projection: checkpoints.json: its probes, depths and unit inputs hold for the solution") {
    Projection lab;
    int depth_probes = 0, units = 0;
    std::vector<std::string> scenes;
    fw::test::for_each_checkpoint(
        lab.lab, lab.renderer, 5,
        [&](const fw::Checkpoint& cp, const fw::ParamValues& params, const fw::RenderOutput& out) {
            scenes.push_back(params.text("scene"));
            fw::test::check_probes_and_stats(cp.checks, out);
            for (const nlohmann::json& check : cp.checks) {
                CAPTURE(check.dump());
                if (check["kind"] == "probe" && check.contains("depth")) {
                    ++depth_probes;
                } else if (check["kind"] == "unit") {
                    // The function exists and takes every edge case; `course`
                    // compares the results with its reference.
                    ++units;
                    const auto& fns = lab.lab.info.functions;
                    auto f = std::find_if(fns.begin(), fns.end(), [&](const fw::UnitFunction& u) {
                        return u.name == check["function"].get<std::string>();
                    });
                    REQUIRE(f != fns.end());
                    for (const nlohmann::json& args : check.at("edge"))
                        CHECK_NOTHROW(f->call(args));
                }
            }
        });
    CHECK(depth_probes >= 5);
    CHECK(units >= 5);
    for (const char* scene : {"cards", "zfight"})
        CHECK(std::count(scenes.begin(), scenes.end(), scene) >= 2);
}
