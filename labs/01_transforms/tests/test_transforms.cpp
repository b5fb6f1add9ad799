// Lab 1 `transforms`: the rendered scene and the checkpoints. Every pixel
// expectation is computed here from the sheet's numbers (docs/labs.md,
// labs/01_transforms/README.md) with closed forms, never read from a
// reference image or from the lab's own code. The matrices themselves are
// tested in test_transforms_math.cpp.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "framework/checkpoints.hpp"
#include "framework/lab.hpp"
#include "framework/render.hpp"
#include "tests/support/test_support.hpp"
#include "transforms_glm.hpp"

using namespace transforms_test;

namespace {

constexpr int kSize = 512;
const glm::vec3 kBlack{0, 0, 0}, kGrey{0.25f, 0.25f, 0.25f}, kRed{1, 0, 0}, kYellow{1, 1, 0};

// ---- Pixels: the scene in closed form ----------------------------------

struct Setting {
    float tx = 0, ty = 0, angle = 0, sx = 1, sy = 1;
    std::string order = "trs";
};

std::string describe(const Setting& s) {
    std::ostringstream out;
    out << "tx=" << s.tx << " ty=" << s.ty << " angle=" << s.angle << " sx=" << s.sx
        << " sy=" << s.sy << " order=" << s.order;
    return out.str();
}

// One letter of `order` acting on a 2D point: t adds (tx, ty), r turns by
// angle counter-clockwise, s multiplies by (sx, sy); `inverse` undoes it.
glm::vec2 act(char op, glm::vec2 p, const Setting& s, bool inverse) {
    const float sign = inverse ? -1.0f : 1.0f;
    if (op == 't') return p + sign * glm::vec2(s.tx, s.ty);
    if (op == 's') return inverse ? p / glm::vec2(s.sx, s.sy) : p * glm::vec2(s.sx, s.sy);
    const float a = sign * s.angle * 3.14159265358979f / 180.0f;
    return {std::cos(a) * p.x - std::sin(a) * p.y, std::sin(a) * p.x + std::cos(a) * p.y};
}

// p' = M p with M = A B C: C acts first, so walk the letters right to left.
glm::vec2 forward(glm::vec2 p, const Setting& s) {
    for (auto it = s.order.rbegin(); it != s.order.rend(); ++it) p = act(*it, p, s, false);
    return p;
}
// M^-1 = C^-1 B^-1 A^-1: undo A first.
glm::vec2 backward(glm::vec2 p, const Setting& s) {
    for (char op : s.order) p = act(op, p, s, true);
    return p;
}

bool inside(glm::vec2 p, float lo, float hi) {
    return p.x >= lo && p.x <= hi && p.y >= lo && p.y <= hi;
}

// What the sheet puts at world point w: the marker over the red square (both
// moved by M) over the grey reference over black.
glm::vec3 colour_at(const Setting& s, glm::vec2 w) {
    const glm::vec2 object = backward(w, s);
    if (inside(object, 0.25f, 0.5f)) return kYellow;
    if (inside(object, -0.5f, 0.5f)) return kRed;
    if (inside(w, -0.5f, 0.5f)) return kGrey;
    return kBlack;
}

// World x in [-2, 2] -> window (x / 2 + 1) / 2 * 512; and back.
float to_window(float world) { return (world / 2.0f + 1.0f) / 2.0f * kSize; }
int pixel(float world) { return static_cast<int>(std::floor(to_window(world))); }
float to_world(float window) { return window / kSize * 4.0f - 2.0f; }

// The pixel holding world point w; a failure if w is off screen.
bool probe_world(const fw::Image& img, glm::vec2 w, glm::vec3 expected) {
    CAPTURE(w.x);
    CAPTURE(w.y);
    return fw::test::probe_rgb(img, pixel(w.x), pixel(w.y), expected, 0.01f);
}

// Every 4th pixel whose centre is at least 1.5 px from any edge of the
// scene (the same colour 1.5 px away in the four directions) must have the
// colour colour_at() gives. Reports the first few differences.
long mismatches(const fw::Image& img, const Setting& s) {
    long bad = 0, probed = 0;
    for (int y = 2; y < kSize; y += 4)
        for (int x = 2; x < kSize; x += 4) {
            const glm::vec2 c(x + 0.5f, y + 0.5f);
            auto at = [&](glm::vec2 window) {
                return colour_at(s, {to_world(window.x), to_world(window.y)});
            };
            const glm::vec3 want = at(c);
            if (at(c + glm::vec2(1.5f, 0)) != want || at(c - glm::vec2(1.5f, 0)) != want ||
                at(c + glm::vec2(0, 1.5f)) != want || at(c - glm::vec2(0, 1.5f)) != want)
                continue;
            ++probed;
            const fw::Rgba8 p = img.at(x, y);
            const glm::vec3 got(p.r / 255.0f, p.g / 255.0f, p.b / 255.0f);
            const glm::vec3 d = glm::abs(got - want);
            if (d.r > 0.01f || d.g > 0.01f || d.b > 0.01f) {
                if (++bad <= 5)
                    MESSAGE("pixel (" << x << ", " << y << "): expected (" << want.r << ", "
                                      << want.g << ", " << want.b << ") observed (" << got.r << ", "
                                      << got.g << ", " << got.b << ")");
            }
        }
    MESSAGE(bad << " of " << probed << " probed pixels differ");
    CHECK(probed > 10000);
    return bad;
}

struct Transforms {
    const fw::RegisteredLab& lab = fw::test::this_lab();
    fw::LabRenderer renderer{lab, fw::test::context_info()};

    fw::ParamValues params(const Setting& s) const {
        fw::ParamValues p = fw::default_params(lab);
        p.set_json("tx", s.tx);
        p.set_json("ty", s.ty);
        p.set_json("angle", s.angle);
        p.set_json("sx", s.sx);
        p.set_json("sy", s.sy);
        p.set("order", s.order);
        return p;
    }
    fw::RenderOutput render(const Setting& s) { return renderer.render(params(s), kSize, kSize); }
};

Setting setting_of(const fw::ParamValues& p) {
    return {p.number("tx"), p.number("ty"), p.number("angle"),
            p.number("sx"), p.number("sy"), p.text("order")};
}

}  // namespace

TEST_CASE("transforms: the declaration has the sheet's parameters, defaults and functions") {
    const fw::RegisteredLab& lab = fw::test::this_lab();
    const fw::ParamValues p = fw::default_params(lab);
    for (const char* zero : {"tx", "ty", "angle"}) CHECK(p.number(zero) == 0.0f);
    CHECK(p.number("sx") == 1.0f);
    CHECK(p.number("sy") == 1.0f);
    CHECK(p.text("order") == "trs");
    for (const fw::Param& param : lab.info.params) {
        INFO("parameter " << param.name);
        CHECK(!param.help_text.empty());
        CHECK(param.shortcut != 0);
        CHECK(param.shortcut != 'R');
        if (param.name == "tx" || param.name == "ty") CHECK((param.min == -2 && param.max == 2));
        if (param.name == "angle") CHECK((param.min == -360 && param.max == 360));
        if (param.name == "sx" || param.name == "sy") CHECK((param.min == -3 && param.max == 3));
        if (param.name == "order")
            CHECK(param.choices ==
                  std::vector<std::string>{"trs", "tsr", "rts", "rst", "str", "srt"});
    }
    std::vector<std::string> names;
    for (const fw::UnitFunction& f : lab.info.functions) names.push_back(f.name);
    CHECK(names == std::vector<std::string>{"translate", "scale", "rotateX", "rotateY", "rotateZ",
                                            "rotate", "compose"});
}

TEST_CASE("transforms: pixels: marker, body, reference and background where the sheet puts them") {
    Transforms lab;
    std::vector<Setting> settings = {
        {},
        {1, -0.5f, 0, 1, 1, "trs"},
        {0, 0, 90, 1, 1, "trs"},
        {0, 0, 180, 1, 1, "trs"},
        {0, 0, -90, 1, 1, "trs"},
        {0, 0, 360, 0.5f, 0.5f, "trs"},
        {0, 0, 0, -1, 1, "trs"},
        {0, 0, 0, -1, 0.5f, "trs"},
        {0, 0, 30, -1, -1.5f, "srt"},
        {-0.5f, 0.75f, 45, -1, 0.5f, "trs"},
        {1, -1.25f, -30, 0.75f, 1.5f, "trs"},
    };
    // The same T, R and S in all six orders: six different pictures.
    for (const char* order : {"trs", "tsr", "rts", "rst", "str", "srt"})
        settings.push_back({0.75f, 0.25f, 90, 1.5f, 1, order});
    for (const char* order : {"trs", "srt", "rts", "tsr"})
        settings.push_back({1, 0.5f, 90, 2, 1, order});

    for (const Setting& s : settings) {
        INFO(describe(s));
        const fw::RenderOutput out = lab.render(s);
        // The marker's centre and a point of the body far from the marker.
        CHECK(probe_world(out.color, forward({0.375f, 0.375f}, s), kYellow));
        CHECK(probe_world(out.color, forward({-0.25f, -0.25f}, s), kRed));
        // A point of the reference the object leaves uncovered (M^-1 takes
        // it well outside the square), where there is one.
        for (glm::vec2 g :
             {glm::vec2(0, 0), glm::vec2(-0.375f, -0.375f), glm::vec2(0.375f, -0.375f),
              glm::vec2(-0.375f, 0.375f), glm::vec2(0.375f, 0.375f)}) {
            const glm::vec2 q = backward(g, s);
            if (std::fmax(std::fabs(q.x), std::fabs(q.y)) > 0.6f) {
                CHECK(probe_world(out.color, g, kGrey));
                break;
            }
        }
        // A background corner the object does not reach.
        for (glm::vec2 b : {glm::vec2(-1.9f, -1.9f), glm::vec2(1.9f, 1.9f), glm::vec2(-1.9f, 1.9f),
                            glm::vec2(1.9f, -1.9f)})
            if (colour_at(s, b) == kBlack) {
                CHECK(probe_world(out.color, b, kBlack));
                break;
            }
        CHECK(mismatches(out.color, s) == 0);
        // Three squares of two triangles each.
        CHECK(out.stats.at("primitives_generated") == 6);
    }
}

TEST_CASE("transforms: with M = I the object hides the reference; lab_stats report M") {
    Transforms lab;
    const fw::RenderOutput out = lab.render({});
    for (glm::vec2 g : {glm::vec2(0, 0), glm::vec2(-0.45f, -0.45f), glm::vec2(0.45f, -0.45f)})
        CHECK(probe_world(out.color, g, kRed));
    const fw::RenderOutput moved = lab.render({1, 0.5f, 90, 2, 1, "trs"});
    const nlohmann::json& stats = moved.stats.at("lab_stats");
    INFO(stats.dump());
    const glm::mat4 m = glm_model(1, 0.5f, 90, 2, 1, "trs");
    for (int r = 0; r < 4; ++r)
        for (int c = 0; c < 4; ++c)
            CHECK(stats["model_rows"][r][c].get<float>() == doctest::Approx(m[c][r]).epsilon(1e-5));
    CHECK(stats["marker_centre"][0].get<float>() == doctest::Approx(0.625).epsilon(1e-5));
    CHECK(stats["marker_centre"][1].get<float>() == doctest::Approx(1.25).epsilon(1e-5));
}

TEST_CASE("transforms: dragging moves the object by the mouse's distance in world units") {
    Transforms lab;
    fw::ParamValues p = lab.params({});
    lab.renderer.render(p, kSize, kSize);
    // 512 pixels span the 4 world units of [-2, 2].
    CHECK(lab.renderer.lab().on_drag(p, fw::Frame{}, 64, -32));
    CHECK(p.number("tx") == doctest::Approx(0.5));
    CHECK(p.number("ty") == doctest::Approx(-0.25));
    lab.renderer.lab().on_drag(p, fw::Frame{}, 5000, 0);
    CHECK(p.number("tx") == 2.0f);
    CHECK(lab.renderer.lab().on_scroll(p, fw::Frame{}, 2));
    CHECK(p.number("angle") == 30.0f);
}

TEST_CASE("transforms: checkpoints.json: probes agree with the sheet and hold for the solution") {
    Transforms lab;
    int units = 0;
    std::vector<std::string> orders;
    fw::test::for_each_checkpoint(
        lab.lab, lab.renderer, 5,
        [&](const fw::Checkpoint& cp, const fw::ParamValues& params, const fw::RenderOutput& out) {
            const Setting s = setting_of(params);
            orders.push_back(s.order);
            for (const nlohmann::json& check : cp.checks) {
                CAPTURE(check.dump());
                if (check["kind"] == "probe") {
                    const int x = check["at"][0], y = check["at"][1];
                    const glm::vec3 written(check["color"][0].get<float>(),
                                            check["color"][1].get<float>(),
                                            check["color"][2].get<float>());
                    // The file's colour is what the sheet puts at that pixel centre.
                    CHECK(colour_at(s, {to_world(x + 0.5f), to_world(y + 0.5f)}) == written);
                    CHECK(fw::test::probe_rgb(out.color, x, y, written,
                                              check.value("tolerance", 0.01f)));
                } else if (check["kind"] == "stat") {
                    CHECK(check["stat"] == "primitives_generated");
                    CHECK(check["equals"] == 6);
                    CHECK(out.stats.at("primitives_generated") == 6);
                } else if (check["kind"] == "unit") {
                    ++units;
                    const fw::UnitFunction* f = nullptr;
                    for (const fw::UnitFunction& u : lab.lab.info.functions)
                        if (u.name == check["function"].get<std::string>()) f = &u;
                    REQUIRE(f != nullptr);
                    for (const nlohmann::json& args : check["edge"]) {
                        CAPTURE(args.dump());
                        REQUIRE(int(args.size()) == f->arity);
                        CHECK(same_matrix(glm_unit(f->name, args),
                                          fw::from_json_value<glm::mat4>(f->call(args)), f->name,
                                          check.value("tolerance", 1e-5f)));
                    }
                }
            }
        });
    CHECK(units >= 7);
    for (const char* order : {"trs", "tsr", "rts", "rst", "str", "srt"})
        CHECK(std::count(orders.begin(), orders.end(), order) >= 1);
}
