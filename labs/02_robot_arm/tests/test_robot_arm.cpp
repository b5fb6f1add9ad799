// Lab 2 `robot-arm`. Every expectation is computed here from the sheet's
// numbers (docs/labs.md, labs/02_robot_arm/README.md), never read from a reference
// image or from the lab's own code. The matrices come from a closed form in
// complex numbers: a rigid motion of the plane is z -> origin + e^(i angle) z.
#include <algorithm>
#include <cmath>
#include <complex>
#include <memory>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "arm.hpp"
#include "framework/checkpoints.hpp"
#include "framework/lab.hpp"
#include "framework/render.hpp"
#include "tests/support/test_support.hpp"

namespace {

using cplx = std::complex<double>;
constexpr int kSize = 512;
constexpr double kDegree = 3.14159265358979323846 / 180.0;
const glm::vec3 kBlack{0, 0, 0}, kArmColor{0.2f, 0.4f, 1.0f}, kHandColor{0.2f, 0.9f, 0.3f};
const glm::vec3 kFingerColor{1.0f, 0.6f, 0.1f}, kBaseColor{0.4f, 0.4f, 0.4f};
const cplx kShoulder{-1.5, -1.5};

struct Pose {
    double shoulder, hand, grip;
};

// A part placed in the world: its points z (designed at the origin) land at
// origin + turn * z, turn = e^(i angle).
struct Placed {
    cplx origin, turn;
};

cplx unit(double degrees) { return std::polar(1.0, degrees * kDegree); }

// Positions in expected_pose()'s list, in ArmMatrices' field order.
constexpr size_t kS = 0, kJ = 1, kH = 2, kUpperFinger = 3, kLowerFinger = 4;

// {S, J, H, upper finger, lower finger} by walking along the arm: the elbow
// is 2 along the arm, the hand's end 1 further along the hand, the fingers
// 0.1 to either side of it (i * turn is the hand's +y).
std::vector<Placed> expected_pose(const Pose& p) {
    const cplx arm = unit(p.shoulder), hand = arm * unit(p.hand);
    const cplx elbow = kShoulder + 2.0 * arm, end = elbow + hand;
    const cplx side = 0.1 * cplx(0, 1) * hand;
    return {{kShoulder, arm},
            {elbow, arm},
            {elbow, hand},
            {end + side, hand * unit(p.grip)},
            {end - side, hand * unit(-p.grip)}};
}

glm::mat4 as_matrix(const Placed& m) {
    const float c = float(m.turn.real()), s = float(m.turn.imag());
    return glm::mat4({c, s, 0, 0}, {-s, c, 0, 0}, {0, 0, 1, 0},
                     {float(m.origin.real()), float(m.origin.imag()), 0, 1});
}

const char* const kMatrixNames[] = {"S", "J", "H", "upper finger", "lower finger"};

// Every element within `tol`; on failure prints Expected/Observed.
bool matrices_match(const robot_arm::ArmMatrices& m, const Pose& p, float tol = 1e-5f) {
    const std::vector<Placed> expected = expected_pose(p);
    const glm::mat4 observed[] = {m.S, m.J, m.H, m.upper_finger, m.lower_finger};
    bool pass = true;
    for (size_t k = 0; k < expected.size(); ++k) {
        const glm::mat4 e = as_matrix(expected[k]), o = observed[k];
        for (int c = 0; c < 4; ++c)
            for (int r = 0; r < 4; ++r) {
                if (std::fabs(o[c][r] - e[c][r]) <= tol * std::max(1.0f, std::fabs(e[c][r])))
                    continue;
                MESSAGE("pose (" << p.shoulder << ", " << p.hand << ", " << p.grip << "), "
                                 << kMatrixNames[k] << "[" << c << "][" << r << "]: expected "
                                 << e[c][r] << " observed " << o[c][r]);
                pass = false;
            }
    }
    return pass;
}

// The sheet's scene, part by part in draw order: base (README: disc of
// radius 0.3 at the shoulder), arm, hand, upper finger, lower finger.
struct Box {
    double x0, x1, y0, y1;
};
const Box kArm{0, 2, -0.2, 0.2}, kHand{0, 1, -0.15, 0.15}, kFinger{0, 0.6, -0.05, 0.05};

// Distance of `w` inside (> 0) or outside (< 0) a placed box, along the
// nearest edge's normal (exact inside; outside, enough to tell the sides).
double inside(const Box& b, const Placed& m, cplx w) {
    const cplx q = (w - m.origin) / m.turn;
    return std::min({q.real() - b.x0, b.x1 - q.real(), q.imag() - b.y0, b.y1 - q.imag()});
}

// The colour the sheet predicts at world point w, or false where w is within
// `margin` of an edge that decides it (a pixel there may go either way).
bool predict(const Pose& p, cplx w, glm::vec3& color, double margin = 0.01) {
    const std::vector<Placed> m = expected_pose(p);
    const std::pair<double, glm::vec3> top_down[] = {
        {inside(kFinger, m[kLowerFinger], w), kFingerColor},
        {inside(kFinger, m[kUpperFinger], w), kFingerColor},
        {inside(kHand, m[kH], w), kHandColor},
        {inside(kArm, m[kS], w), kArmColor},
        {0.3 - std::abs(w - kShoulder), kBaseColor}};
    for (const auto& [depth, c] : top_down) {
        if (std::fabs(depth) <= margin) return false;
        if (depth > 0) {
            color = c;
            return true;
        }
    }
    color = kBlack;
    return true;
}

// World -> window: ((x / 3) + 1) / 2 * 512, the pixel containing it.
int pixel(double world) { return int(std::floor((world / 3.0 + 1.0) / 2.0 * kSize)); }
cplx pixel_centre(int x, int y) {
    return {((x + 0.5) / kSize * 2.0 - 1.0) * 3.0, ((y + 0.5) / kSize * 2.0 - 1.0) * 3.0};
}

struct RobotArm {
    const fw::RegisteredLab& lab = fw::test::this_lab();
    fw::LabRenderer renderer{lab, fw::test::context_info()};

    fw::ParamValues params(const Pose& p) {
        fw::ParamValues v = fw::default_params(lab);
        v.set("shoulder", std::to_string(p.shoulder));
        v.set("hand", std::to_string(p.hand));
        v.set("grip", std::to_string(p.grip));
        return v;
    }
    fw::RenderOutput render(const Pose& p) { return renderer.render(params(p), kSize, kSize); }
};

// Probes world point `local` of part `k` (placed by expected_pose) for
// `color`, unless the pose puts it off the frame; counts the probes made.
bool probe_part(const fw::Image& img, const Pose& p, size_t k, cplx local, glm::vec3 color,
                int& probed) {
    const Placed m = expected_pose(p)[k];
    const cplx w = m.origin + m.turn * local;
    const int x = pixel(w.real()), y = pixel(w.imag());
    if (x < 0 || y < 0 || x >= kSize || y >= kSize) {
        MESSAGE(kMatrixNames[k] << " (" << w.real() << ", " << w.imag() << ") is off the frame");
        return true;
    }
    ++probed;
    return fw::test::probe_rgb(img, x, y, color);
}

// Every pixel whose colour the sheet decides, compared; prints the first few
// differences as Expected/Observed and returns how many differ.
long sweep(const fw::Image& img, const Pose& p) {
    long wrong = 0;
    for (int y = 0; y < kSize; ++y)
        for (int x = 0; x < kSize; ++x) {
            glm::vec3 e;
            if (!predict(p, pixel_centre(x, y), e)) continue;
            const fw::Rgba8 o = img.at(x, y);
            const glm::vec3 observed(o.r / 255.0f, o.g / 255.0f, o.b / 255.0f);
            if (glm::all(glm::lessThanEqual(glm::abs(observed - e), glm::vec3(1.5f / 255.0f))))
                continue;
            if (++wrong <= 5) fw::test::probe_rgb(img, x, y, e);
        }
    return wrong;
}

const Pose kDefault{30, -45, 20};
// The sheet's edge cases: 0, +-90, 180, the ends of every range.
const Pose kEdges[] = {{0, 0, 0},       {90, 0, 0},      {-90, 0, 0},     {180, 0, 0},
                       {-180, 0, 0},    {0, 90, 0},      {0, -90, 0},     {0, 150, 0},
                       {0, -150, 0},    {0, 0, 90},      {0, 0, 45},      {180, 150, 90},
                       {-180, -150, 0}, {180, -150, 90}, {-180, 150, 90}, {90, 90, 45},
                       {-90, -90, 90},  {30, -45, 20},   {45, 135, 10},   {-135, -30, 60}};

}  // namespace

TEST_CASE("robot-arm: the declaration has the sheet's parameters, ranges and defaults") {
    const fw::RegisteredLab& lab = fw::test::this_lab();
    const fw::ParamValues p = fw::default_params(lab);
    CHECK(p.number("shoulder") == 30);
    CHECK(p.number("hand") == -45);
    CHECK(p.number("grip") == 20);
    const std::pair<double, double> ranges[] = {{-180, 180}, {-150, 150}, {0, 90}};
    REQUIRE(lab.info.params.size() == 3);
    for (size_t i = 0; i < 3; ++i) {
        const fw::Param& param = lab.info.params[i];
        INFO("parameter " << param.name);
        CHECK(param.min == ranges[i].first);
        CHECK(param.max == ranges[i].second);
        CHECK(param.unit_text == "deg");
        CHECK(!param.help_text.empty());
        CHECK(param.shortcut != 0);
        CHECK(param.shortcut != 'R');
    }
    REQUIRE(lab.info.functions.size() == 1);
    CHECK(lab.info.functions[0].name == "arm_matrices");
    CHECK(lab.info.functions[0].arity == 3);
}

TEST_CASE("robot-arm: arm_matrices is the closed form on the edge cases") {
    for (const Pose& p : kEdges) {
        CAPTURE(p.shoulder);
        CAPTURE(p.hand);
        CAPTURE(p.grip);
        CHECK(matrices_match(
            robot_arm::arm_matrices(float(p.shoulder), float(p.hand), float(p.grip)), p));
    }
}

TEST_CASE("robot-arm: arm_matrices is the closed form on 1000 random poses") {
    std::mt19937 rng(20240502);
    std::uniform_real_distribution<float> shoulder(-180, 180), hand(-150, 150), grip(0, 90);
    int failed = 0;
    for (int i = 0; i < 1000; ++i) {
        const Pose p{shoulder(rng), hand(rng), grip(rng)};
        failed += !matrices_match(
            robot_arm::arm_matrices(float(p.shoulder), float(p.hand), float(p.grip)), p);
    }
    CHECK(failed == 0);
}

TEST_CASE("robot-arm: the grader's call through JSON returns the same five matrices") {
    const fw::UnitFunction& f = fw::test::this_lab().info.functions.at(0);
    const nlohmann::json result = f.call(nlohmann::json::array({30, -45, 20}));
    CHECK(matrices_match(fw::from_json_value<robot_arm::ArmMatrices>(result), kDefault));
    // In JSON the five matrices are a list in the fields' order.
    REQUIRE(result.is_array());
    CHECK(result.size() == 5);
    CHECK(fw::from_json_value<glm::mat4>(result[kJ]) == robot_arm::arm_matrices(30, -45, 20).J);
    CHECK(!fw::test::thrown([&] { f.call(nlohmann::json::array({30, -45})); }).empty());
}

TEST_CASE("robot-arm: hand, finger tips and arm show their colours at the sheet's poses") {
    RobotArm lab;
    const Pose poses[] = {kDefault,       {180, 150, 90},  {-180, -150, 0},
                          {180, -150, 0}, {-180, 150, 90}, {0, 0, 0},
                          {90, 90, 45},   {30, 150, 90},   {30, -150, 0}};
    int probed = 0;
    for (const Pose& p : poses) {
        CAPTURE(p.shoulder);
        CAPTURE(p.hand);
        CAPTURE(p.grip);
        const fw::Image img = lab.render(p).color;
        // The hand's centre H * (0.5, 0); each finger 0.05 inside its tip,
        // F * (0.55, 0). Both are on top of everything drawn before them.
        CHECK(probe_part(img, p, kH, {0.5, 0}, kHandColor, probed));
        CHECK(probe_part(img, p, kUpperFinger, {0.55, 0}, kFingerColor, probed));
        CHECK(probe_part(img, p, kLowerFinger, {0.55, 0}, kFingerColor, probed));
        // The arm's middle S * (1, 0), where nothing drawn later covers it.
        const Placed s = expected_pose(p)[kS];
        glm::vec3 top;
        if (predict(p, s.origin + s.turn * 1.0, top) && top == kArmColor)
            CHECK(probe_part(img, p, kS, {1, 0}, kArmColor, probed));
        // Background, far from the arm: the corner opposite the shoulder.
        CHECK(fw::test::probe_rgb(img, kSize - 3, kSize - 3, kBlack));
        CHECK(sweep(img, p) == 0);
    }
    // Shoulder +-180 puts the elbow at x = -3.5, and the hand with it, off
    // the frame; every other probe is on it.
    CHECK(probed >= 30);
}

TEST_CASE("robot-arm: every pixel the sheet decides agrees, at 20 random poses") {
    RobotArm lab;
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> shoulder(-180, 180), hand(-150, 150), grip(0, 90);
    for (int i = 0; i < 20; ++i) {
        const Pose p{shoulder(rng), hand(rng), grip(rng)};
        CAPTURE(p.shoulder);
        CAPTURE(p.hand);
        CAPTURE(p.grip);
        CHECK(sweep(lab.render(p).color, p) == 0);
    }
}

TEST_CASE("robot-arm: the stats give the joints where the sheet puts them") {
    RobotArm lab;
    const Pose p{120, -60, 30};
    const nlohmann::json stats = lab.render(p).stats;
    const std::vector<Placed> m = expected_pose(p);
    const std::pair<const char*, cplx> joints[] = {
        {"shoulder", kShoulder},
        {"elbow", m[kJ].origin},
        {"finger_root", m[kH].origin + m[kH].turn},
        {"upper_tip", m[kUpperFinger].origin + 0.6 * m[kUpperFinger].turn},
        {"lower_tip", m[kLowerFinger].origin + 0.6 * m[kLowerFinger].turn}};
    for (const auto& [name, at] : joints) {
        CAPTURE(name);
        const nlohmann::json& v = stats.at("lab_stats").at(name);
        CHECK(v[0].get<double>() == doctest::Approx(at.real()).epsilon(1e-5));
        CHECK(v[1].get<double>() == doctest::Approx(at.imag()).epsilon(1e-5));
    }
    // The base's 32-triangle fan, then two triangles per box (arm, hand, two fingers).
    CHECK(stats.at("primitives_generated") == 32 + 4 * 2);
}

TEST_CASE("robot-arm: dragging turns the shoulder round and the hand up to its limits") {
    const fw::RegisteredLab& lab = fw::test::this_lab();
    std::unique_ptr<fw::Lab> arm = lab.create();
    fw::ParamValues p = fw::default_params(lab);
    CHECK(arm->on_drag(p, fw::Frame{}, 320, 0));  // +160 degrees: 30 + 160 = 190 = -170
    CHECK(p.number("shoulder") == doctest::Approx(-170));
    CHECK(arm->on_drag(p, fw::Frame{}, 0, 600));  // +300 degrees from -45: stops at 150
    CHECK(p.number("hand") == doctest::Approx(150));
    CHECK(arm->on_scroll(p, fw::Frame{}, 100));
    CHECK(p.number("grip") == doctest::Approx(90));
    CHECK(arm->on_scroll(p, fw::Frame{}, -100));
    CHECK(p.number("grip") == doctest::Approx(0));
}

TEST_CASE("robot-arm: checkpoints.json: its probes are the sheet's colours and hold") {
    RobotArm lab;
    int units = 0;
    fw::test::for_each_checkpoint(
        lab.lab, lab.renderer, 5,
        [&](const fw::Checkpoint& cp, const fw::ParamValues& params, const fw::RenderOutput& out) {
            const Pose p{params.number("shoulder"), params.number("hand"), params.number("grip")};
            for (const nlohmann::json& check : cp.checks) {
                CAPTURE(check.dump());
                if (check["kind"] == "probe") {
                    const int x = check["at"][0].get<int>(), y = check["at"][1].get<int>();
                    const nlohmann::json& rgb = check["color"];
                    const glm::vec3 c{rgb[0].get<float>(), rgb[1].get<float>(),
                                      rgb[2].get<float>()};
                    glm::vec3 sheet;
                    REQUIRE(predict(p, pixel_centre(x, y), sheet));
                    CHECK(fw::test::probe_rgb(out.color, x, y, sheet));
                    CHECK(glm::all(glm::lessThanEqual(glm::abs(c - sheet), glm::vec3(1e-4f))));
                } else if (check["kind"] == "stat") {
                    CHECK(out.stats.at(check["stat"].get<std::string>()) == check["equals"]);
                } else if (check["kind"] == "unit") {
                    ++units;
                    CHECK(check["function"] == "arm_matrices");
                    for (const nlohmann::json& args :
                         check.value("edge", nlohmann::json::array())) {
                        CAPTURE(args.dump());
                        REQUIRE(args.size() == 3);
                        const Pose e{args[0].get<double>(), args[1].get<double>(),
                                     args[2].get<double>()};
                        CHECK(matrices_match(robot_arm::arm_matrices(float(e.shoulder),
                                                                     float(e.hand), float(e.grip)),
                                             e));
                    }
                }
            }
        });
    CHECK(units > 0);
}
