// Lab 7 `framebuffer-ops`: the declaration and the scenes blend, sorting and
// discard, and the checkpoints. Every expectation is computed here from the
// sheet's numbers (scenes.hpp) with GL's rules for blending and the depth
// test, never read from a reference image or from the lab's own code.
#include <algorithm>
#include <string>
#include <vector>

#include "framebuffer_ops_test.hpp"
#include "framework/checkpoints.hpp"

using namespace framebuffer_ops_test;
using namespace framebuffer_ops;

namespace {

// --- scene=blend -----------------------------------------------------------

const char* const kModes[] = {"none", "over", "additive", "multiply", "premultiplied"};
constexpr float kBlendTol = 2.0f / 255.0f;
// The sheet's quads: A [-0.7, 0.3]^2, B [-0.3, 0.7]^2 (NDC).
const WindowRect kRectA = ndc_rect(-0.7f, -0.7f, 0.3f, 0.3f);
const WindowRect kRectB = ndc_rect(-0.3f, -0.3f, 0.7f, 0.7f);

// What `mode` writes for a fragment of colour src.rgb and alpha src.a over
// `dst`, all with GL_FUNC_ADD.
glm::vec3 blend_mode(const std::string& mode, glm::vec4 src, glm::vec3 dst) {
    const glm::vec3 c(src);
    const float a = src.a;
    // Blending off: the fragment replaces the pixel.
    if (mode == "none") return stored(c);
    // GL_SRC_ALPHA, GL_ONE.
    if (mode == "additive") return stored(a * c + dst);
    // GL_DST_COLOR, GL_ZERO.
    if (mode == "multiply") return stored(c * dst);
    // over: GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA; premultiplied: the colour
    // arrives as a * c, with GL_ONE, GL_ONE_MINUS_SRC_ALPHA: the same sum.
    return stored(a * c + (1.0f - a) * dst);
}

// A pixel of scene blend: the opaque background, then the quads covering it
// in the order drawn.
glm::vec3 blend_pixel(const std::string& mode, bool a_first, bool in_a, bool in_b) {
    glm::vec3 c = stored(glm::vec3(kBlendBackground));
    if (a_first ? in_a : in_b) c = blend_mode(mode, a_first ? kQuadA : kQuadB, c);
    if (a_first ? in_b : in_a) c = blend_mode(mode, a_first ? kQuadB : kQuadA, c);
    return c;
}

// Every pixel more than a pixel away from the quads' edges.
void check_blend_frame(const fw::Image& img, const std::string& mode, bool a_first) {
    PixelTally tally{"blend " + mode + (a_first ? ", A first" : ", B first"), kBlendTol};
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            const float a = kRectA.inside_by(centre(x, y)), b = kRectB.inside_by(centre(x, y));
            if (std::fabs(a) < 1.0f || std::fabs(b) < 1.0f) continue;
            tally.check(x, y, blend_pixel(mode, a_first, a > 0, b > 0), rgb(img, x, y));
        }
    // 512^2 = 262144 pixels, less about 4100 along the edges.
    tally.require(255000);
}

// Pixels whose alpha is not 255: the lab masks alpha writes, so the clear's
// alpha 1 stays everywhere.
long translucent_pixels(const fw::Image& img) {
    long n = 0;
    for (const fw::Rgba8& p : img.pixels) n += p.a != 255;
    MESSAGE("pixels with alpha other than 255: " << n);
    return n;
}

// --- scene=sorting ---------------------------------------------------------

// A pane as the window sees it: its rectangle and its window depth (a pane
// faces the camera, so all its points have one depth).
struct PaneOnScreen {
    WindowRect rect;
    float depth;
    glm::vec4 color;
};

std::vector<PaneOnScreen> panes_on_screen() {
    const glm::mat4 clip = sorting_view_projection();
    std::vector<PaneOnScreen> out;
    for (const Pane& pane : panes()) {
        const float h = pane.half_size;
        const glm::vec3 lo = to_window(clip * glm::vec4(pane.centre + glm::vec3(-h, -h, 0), 1));
        const glm::vec3 hi = to_window(clip * glm::vec4(pane.centre + glm::vec3(h, h, 0), 1));
        out.push_back({{lo.x, lo.y, hi.x, hi.y}, lo.z, pane.color});
    }
    return out;
}

// The order the panes are drawn in: as listed, or back to front, the
// farthest from the eye first, ties in the listed order.
std::vector<int> draw_order(bool sorted) {
    std::vector<int> order{0, 1, 2};
    const std::vector<Pane> list = panes();
    const auto farther = [&](int i, int j) {
        return glm::distance(list[i].centre, kSortingEye) >
               glm::distance(list[j].centre, kSortingEye);
    };
    if (sorted) std::stable_sort(order.begin(), order.end(), farther);
    return order;
}

struct Pixel {
    glm::vec3 color;
    float depth;
};

// GL at point p of scene sorting: the background writes no depth (the depth
// test is off); each pane covering p is blended "over" where it passes
// GL_LESS against the depth buffer, which it updates only with depth writes on.
Pixel sorting_pixel(const std::vector<PaneOnScreen>& panes, bool sorted, bool depth_write,
                    glm::vec2 p) {
    Pixel px{stored(glm::vec3(kBlendBackground)), 1.0f};
    for (int i : draw_order(sorted)) {
        if (panes[i].rect.inside_by(p) <= 0 || !(panes[i].depth < px.depth)) continue;
        px.color = over(panes[i].color, px.color);
        if (depth_write) px.depth = panes[i].depth;
    }
    return px;
}

// The pixel farthest inside the panes whose bits are set in `inside` and
// outside the others.
glm::ivec2 region_pixel(const std::vector<PaneOnScreen>& panes, unsigned inside) {
    glm::ivec2 best(-1);
    float best_margin = -1e9f;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            float margin = 1e9f;
            for (size_t i = 0; i < panes.size(); ++i) {
                const float d = panes[i].rect.inside_by(centre(x, y));
                margin = glm::min(margin, (inside >> i) & 1u ? d : -d);
            }
            if (margin > best_margin) best_margin = margin, best = {x, y};
        }
    MESSAGE("panes " << inside << " (bits: 1 near, 2 middle, 4 far): pixel (" << best.x << ", "
                     << best.y << "), " << best_margin << " px from an edge");
    REQUIRE(best_margin >= 3.0f);
    return best;
}

// --- scene=discard ---------------------------------------------------------

// The sheet's fence, [-0.8, 0.8]^2 at NDC z -0.5, and back quad,
// [-0.6, 0.6]^2 at z 0.5, with their window depths (z + 1) / 2.
const WindowRect kFence = ndc_rect(-0.8f, -0.8f, 0.8f, 0.8f);
const WindowRect kBack = ndc_rect(-0.6f, -0.6f, 0.6f, 0.6f);
constexpr float kFenceDepth = 0.25f, kBackDepth = 0.75f;

// The fence's alpha at window point p: 2 |fract(uv * cells) - 0.5|, clamped.
float fence_alpha(glm::vec2 p) {
    const glm::vec2 uv = (p - glm::vec2(kFence.x0, kFence.y0)) / (kFence.x1 - kFence.x0);
    return glm::clamp(2.0f * glm::length(glm::fract(uv * kFenceCells) - 0.5f), 0.0f, 1.0f);
}

// GL at point p of scene discard, cleared to black and depth 1: the fence,
// "over", where not discarded; then the opaque back quad where it passes
// GL_LESS. A discarded fragment writes neither colour nor depth.
Pixel discard_pixel(glm::vec2 p, bool alpha_test, float cutoff) {
    Pixel px{glm::vec3(0.0f), 1.0f};
    const float a = fence_alpha(p);
    if (kFence.inside_by(p) > 0 && !(alpha_test && a < cutoff))
        px = {over(glm::vec4(kFenceColor, a), px.color), kFenceDepth};
    if (kBack.inside_by(p) > 0 && kBackDepth < px.depth)
        px = {stored(glm::vec3(kBackColor)), kBackDepth};
    return px;
}

}  // namespace

TEST_CASE("framebuffer_ops: the declaration has the sheet's parameters and defaults") {
    const fw::RegisteredLab& lab = fw::test::this_lab();
    const fw::ParamValues p = fw::default_params(lab);
    CHECK(p.text("scene") == "blend");
    CHECK(p.text("mode") == "over");
    CHECK(p.text("first") == "a");
    CHECK(p.flag("depth_write"));
    CHECK_FALSE(p.flag("sorted"));
    CHECK(p.flag("alpha_test"));
    CHECK(p.number("cutoff") == 0.5f);
    CHECK(p.flag("outline"));
    CHECK_FALSE(p.flag("cull"));
    CHECK(p.text("pattern") == "facing");
    CHECK(p.flag("scissor"));
    std::vector<std::string> names;
    for (const fw::Param& param : lab.info.params) {
        INFO("parameter " << param.name);
        names.push_back(param.name);
        CHECK(!param.help_text.empty());
        CHECK(param.shortcut != 0);
    }
    CHECK(names == std::vector<std::string>{"scene", "mode", "first", "depth_write", "sorted",
                                            "alpha_test", "cutoff", "outline", "cull", "pattern",
                                            "scissor"});
}

TEST_CASE("framebuffer_ops: blend: each mode's equation, in both orders, at every pixel") {
    Lab lab;
    for (const std::string mode : kModes)
        for (const bool a_first : {true, false}) {
            CAPTURE(mode);
            CAPTURE(a_first);
            const fw::RenderOutput out =
                lab.render({{"scene", "blend"}, {"mode", mode}, {"first", a_first ? "a" : "b"}});
            const fw::Image& img = out.color;
            // A only, B only, both, neither.
            const std::pair<glm::vec2, glm::bvec2> probes[] = {{{-0.5f, -0.5f}, {true, false}},
                                                               {{0.5f, 0.5f}, {false, true}},
                                                               {{0.0f, 0.0f}, {true, true}},
                                                               {{-0.9f, 0.9f}, {false, false}}};
            bool pass = true;
            for (const auto& [at, in] : probes)
                pass = fw::test::probe_rgb(img, pixel(at.x), pixel(at.y),
                                           blend_pixel(mode, a_first, in.x, in.y), kBlendTol) &&
                       pass;
            CHECK(pass);
            check_blend_frame(img, mode, a_first);
            CHECK(translucent_pixels(img) == 0);
        }
}

TEST_CASE("framebuffer_ops: blend: over depends on the order, additive and multiply do not") {
    Lab lab;
    const int overlap = pixel(0.0f);
    for (const std::string mode : {"over", "premultiplied", "additive", "multiply"}) {
        CAPTURE(mode);
        const bool commutes = mode == "additive" || mode == "multiply";
        const glm::vec3 expected_a = blend_pixel(mode, true, true, true);
        const glm::vec3 expected_b = blend_pixel(mode, false, true, true);
        // The arithmetic itself: a sum and a product commute, "over" does not.
        CHECK((max_difference(expected_a, expected_b) <= 1.0f / 255.0f) == commutes);
        const glm::vec3 a =
            rgb(lab.render({{"scene", "blend"}, {"mode", mode}}).color, overlap, overlap);
        const glm::vec3 b =
            rgb(lab.render({{"scene", "blend"}, {"mode", mode}, {"first", "b"}}).color, overlap,
                overlap);
        MESSAGE("overlap: A first (" << a.r << ", " << a.g << ", " << a.b << "), B first (" << b.r
                                     << ", " << b.g << ", " << b.b << ")");
        if (commutes)
            CHECK(max_difference(a, b) <= 1.0f / 255.0f);
        else
            CHECK(max_difference(a, b) > 0.1f);
    }
}

TEST_CASE("framebuffer_ops: sorting: depth writes and the draw order decide what shows") {
    Lab lab;
    const std::vector<PaneOnScreen> panes = panes_on_screen();
    // Bits: 1 near, 2 middle, 4 far.
    const std::pair<const char*, unsigned> regions[] = {{"near only", 1u},
                                                        {"near and middle", 3u},
                                                        {"all three", 7u},
                                                        {"middle and far", 6u},
                                                        {"far only", 4u}};
    std::vector<glm::ivec2> probes;
    for (const auto& [name, bits] : regions) probes.push_back(region_pixel(panes, bits));
    // The depths the projection gives (0.1 to 100; eye 2.5, 3 and 3.5 away),
    // which the panes write with depth_write=true; with false, all stays 1.
    MESSAGE("window depths: near " << panes[0].depth << ", middle " << panes[1].depth << ", far "
                                   << panes[2].depth);
    CHECK(panes[0].depth < panes[1].depth);
    CHECK(panes[1].depth < panes[2].depth);
    // Where all three overlap, the three ways of drawing differ.
    const glm::vec2 all = centre(probes[2].x, probes[2].y);
    const glm::vec3 written = sorting_pixel(panes, false, true, all).color;
    const glm::vec3 unwritten = sorting_pixel(panes, false, false, all).color;
    const glm::vec3 sorted = sorting_pixel(panes, true, true, all).color;
    CHECK(max_difference(written, unwritten) > 0.05f);
    CHECK(max_difference(written, sorted) > 0.05f);
    CHECK(max_difference(unwritten, sorted) > 0.05f);
    for (const bool depth_write : {true, false})
        for (const bool sort : {false, true}) {
            CAPTURE(depth_write);
            CAPTURE(sort);
            const fw::RenderOutput out =
                lab.render({{"scene", "sorting"},
                            {"depth_write", depth_write ? "true" : "false"},
                            {"sorted", sort ? "true" : "false"}});
            bool pass = true;
            for (size_t r = 0; r < probes.size(); ++r) {
                INFO(regions[r].first);
                const glm::ivec2 q = probes[r];
                const Pixel e = sorting_pixel(panes, sort, depth_write, centre(q.x, q.y));
                pass = fw::test::probe_rgb(out.color, q.x, q.y, e.color, 3.0f / 255.0f) && pass;
                pass = fw::test::probe_depth(out.depth, q.x, q.y, e.depth) && pass;
            }
            CHECK(pass);
            // Every pixel 1.5 pixels or more from a pane's edge, colour and depth.
            PixelTally color{"sorting colour", 3.0f / 255.0f}, depth{"sorting depth", 1e-5f};
            for (int y = 0; y < kSize; ++y)
                for (int x = 0; x < kSize; ++x) {
                    bool edge = false;
                    for (const PaneOnScreen& pane : panes)
                        edge |= std::fabs(pane.rect.inside_by(centre(x, y))) < 1.5f;
                    if (edge) continue;
                    const Pixel e = sorting_pixel(panes, sort, depth_write, centre(x, y));
                    color.check(x, y, e.color, rgb(out.color, x, y));
                    depth.check(x, y, e.depth, out.depth.at(x, y));
                }
            color.require(250000);
            depth.require(250000);
        }
}

TEST_CASE("framebuffer_ops: discard: a discarded fragment writes no colour and no depth") {
    Lab lab;
    const fw::RenderOutput on = lab.render({{"scene", "discard"}});
    const fw::RenderOutput off = lab.render({{"scene", "discard"}, {"alpha_test", "false"}});
    const fw::RenderOutput high = lab.render({{"scene", "discard"}, {"cutoff", "0.7"}});
    const glm::vec3 black(0.0f), back(kBackColor);
    const float tol = 2.0f / 255.0f;
    bool pass = true;
    // The centre of a hole, inside the back quad: alpha about 0.
    MESSAGE("alpha at (204, 204): " << fence_alpha(centre(204, 204)));
    pass = fw::test::probe_rgb(on.color, 204, 204, back, tol) && pass;
    pass = fw::test::probe_depth(on.depth, 204, 204, kBackDepth) && pass;
    pass = fw::test::probe_rgb(off.color, 204, 204, fence_alpha(centre(204, 204)) * kFenceColor,
                               tol) &&
           pass;
    pass = fw::test::probe_depth(off.depth, 204, 204, kFenceDepth) && pass;
    // Where four cells meet: alpha 1.
    MESSAGE("alpha at (256, 256): " << fence_alpha(centre(256, 256)));
    pass = fw::test::probe_rgb(on.color, 256, 256, kFenceColor, tol) && pass;
    pass = fw::test::probe_depth(on.depth, 256, 256, kFenceDepth) && pass;
    // Alpha about 0.6: kept with the cut-off 0.5, discarded with 0.7.
    const float a = fence_alpha(centre(235, 204));
    MESSAGE("alpha at (235, 204): " << a);
    CHECK(std::fabs(a - 0.6f) < 0.01f);
    pass = fw::test::probe_rgb(on.color, 235, 204, a * kFenceColor, tol) && pass;
    pass = fw::test::probe_depth(on.depth, 235, 204, kFenceDepth) && pass;
    pass = fw::test::probe_rgb(high.color, 235, 204, back, tol) && pass;
    pass = fw::test::probe_depth(high.depth, 235, 204, kBackDepth) && pass;
    // Outside the fence nothing is drawn.
    pass = fw::test::probe_rgb(on.color, 20, 20, black, tol) && pass;
    pass = fw::test::probe_depth(on.depth, 20, 20, 1.0f) && pass;
    CHECK(pass);
}

TEST_CASE("framebuffer_ops: discard: every pixel, for several cut-offs and without the test") {
    Lab lab;
    const std::pair<bool, float> cases[] = {
        {true, 0.5f}, {true, 0.7f}, {true, 0.3f}, {false, 0.5f}};
    for (const auto& [alpha_test, cutoff] : cases) {
        CAPTURE(alpha_test);
        CAPTURE(cutoff);
        const fw::RenderOutput out = lab.render({{"scene", "discard"},
                                                 {"alpha_test", alpha_test ? "true" : "false"},
                                                 {"cutoff", std::to_string(cutoff)}});
        PixelTally color{"discard colour", 2.0f / 255.0f}, depth{"discard depth", 1e-6f};
        long discarded = 0;
        for (int y = 0; y < kSize; ++y)
            for (int x = 0; x < kSize; ++x) {
                const glm::vec2 p = centre(x, y);
                // Away from the quads' edges and, with the test, from the cut-off.
                if (std::fabs(kFence.inside_by(p)) < 2.0f || std::fabs(kBack.inside_by(p)) < 2.0f)
                    continue;
                const float a = fence_alpha(p);
                if (alpha_test && std::fabs(a - cutoff) < 0.02f) continue;
                discarded += alpha_test && a < cutoff && kBack.inside_by(p) > 0;
                const Pixel e = discard_pixel(p, alpha_test, cutoff);
                color.check(x, y, e.color, rgb(out.color, x, y));
                depth.check(x, y, e.depth, out.depth.at(x, y));
            }
        MESSAGE("pixels where the back quad shows through a hole: " << discarded);
        CHECK((discarded > 1000) == alpha_test);
        // 262144 pixels, less those near the edges and, with the test, the cut-off.
        color.require(235000);
        depth.require(235000);
    }
}

TEST_CASE("framebuffer_ops: checkpoints.json: its probes and stats hold for the solution") {
    Lab lab;
    std::vector<std::string> scenes;
    fw::test::for_each_checkpoint(
        lab.lab, lab.renderer, 6,
        [&](const fw::Checkpoint& cp, const fw::ParamValues& params, const fw::RenderOutput& out) {
            scenes.push_back(params.text("scene"));
            fw::test::check_probes_and_stats(cp.checks, out);
        });
    for (const char* scene : {"blend", "sorting", "discard", "stencil", "faces", "scissor"}) {
        INFO("scene " << scene);
        CHECK(std::count(scenes.begin(), scenes.end(), scene) >= 1);
    }
}
