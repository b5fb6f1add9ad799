// Lab 1 `transforms`: the student's matrices against GLM's transform helpers,
// on edge cases and on 1000 random inputs each (fixed seeds).
#include <cmath>
#include <fstream>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "framework/lab.hpp"
#include "tests/support/test_support.hpp"
#include "transforms_glm.hpp"
#include "transforms_math.hpp"

using namespace transforms_test;

namespace {

constexpr unsigned kSeed = 20240917;  // fixed: a failure replays
constexpr int kRandomInputs = 1000;
const float kEdgeAngles[] = {0, 90, -90, 180, -180, 270, 360, -360, 45, 30, 720};

std::string source_text(const std::string& relative) {
    std::ifstream in(fw::test::source_dir() + "/" + relative);
    REQUIRE_MESSAGE(in, "cannot read " << relative);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

}  // namespace

TEST_CASE("transforms: translate and scale equal glm::translate and glm::scale") {
    using transforms::scale;
    using transforms::translate;
    std::vector<glm::vec3> inputs = {{0, 0, 0},   {1, -2, 3},   {-0.5f, 0.25f, 10}, {1, 1, 1},
                                     {-1, 2, -3}, {0, 0, 0.5f}, {1e-6f, 0, 0},      {-3, -3, -3}};
    std::mt19937 rng(kSeed);
    std::uniform_real_distribution<float> u(-10, 10);
    for (int i = 0; i < kRandomInputs; ++i) inputs.push_back({u(rng), u(rng), u(rng)});
    int failures = 0;
    for (const glm::vec3& v : inputs) {
        failures += !same_matrix(glm::translate(kIdentity, v), translate(v), "translate");
        failures += !same_matrix(glm::scale(kIdentity, v), scale(v), "scale");
    }
    CHECK(failures == 0);
    // What they do to a point (w = 1) and a direction (w = 0).
    CHECK(translate({1, 2, 3}) * glm::vec4(1, 1, 1, 1) == glm::vec4(2, 3, 4, 1));
    CHECK(translate({1, 2, 3}) * glm::vec4(1, 1, 1, 0) == glm::vec4(1, 1, 1, 0));
    CHECK(scale({2, -1, 0.5f}) * glm::vec4(1, 1, 1, 1) == glm::vec4(2, -1, 0.5f, 1));
}

TEST_CASE("transforms: rotateX, rotateY and rotateZ equal glm::rotate about the axes") {
    std::vector<float> angles(std::begin(kEdgeAngles), std::end(kEdgeAngles));
    std::mt19937 rng(kSeed + 1);
    std::uniform_real_distribution<float> u(-720, 720);
    for (int i = 0; i < kRandomInputs; ++i) angles.push_back(u(rng));
    int failures = 0;
    for (float a : angles) {
        CAPTURE(a);
        failures += !same_matrix(glm_rotate(a, {1, 0, 0}), transforms::rotateX(a), "rotateX");
        failures += !same_matrix(glm_rotate(a, {0, 1, 0}), transforms::rotateY(a), "rotateY");
        failures += !same_matrix(glm_rotate(a, {0, 0, 1}), transforms::rotateZ(a), "rotateZ");
    }
    CHECK(failures == 0);
    // Counter-clockwise seen from the axis' positive end: x -> y about z,
    // y -> z about x, z -> x about y.
    const glm::vec4 x(1, 0, 0, 0), y(0, 1, 0, 0), z(0, 0, 1, 0);
    CHECK(glm::length(transforms::rotateZ(90) * x - y) < 1e-6f);
    CHECK(glm::length(transforms::rotateX(90) * y - z) < 1e-6f);
    CHECK(glm::length(transforms::rotateY(90) * z - x) < 1e-6f);
}

TEST_CASE("transforms: rotate (Rodrigues) equals glm::rotate for any non-zero axis") {
    using transforms::rotate;
    std::vector<std::pair<float, glm::vec3>> inputs;
    const glm::vec3 axes[] = {{1, 0, 0},  {0, 1, 0}, {0, 0, 1},         {0, 0, 5},
                              {1, 1, 0},  {1, 2, 3}, {-2, 0.5f, 1},     {0.1f, -0.2f, 0.3f},
                              {0, 0, -1}, {1, 1, 1}, {1e-3f, 0, 1e-3f}, {-7, 8, -9}};
    for (float a : kEdgeAngles)
        for (const glm::vec3& axis : axes) inputs.push_back({a, axis});
    std::mt19937 rng(kSeed + 2);
    std::uniform_real_distribution<float> angle(-720, 720), u(-10, 10);
    for (int i = 0; i < kRandomInputs; ++i)
        inputs.push_back({angle(rng), {u(rng), u(rng), u(rng)}});
    int failures = 0;
    for (const auto& [a, axis] : inputs) {
        CAPTURE(a);
        CAPTURE(axis.x);
        CAPTURE(axis.y);
        CAPTURE(axis.z);
        const glm::mat4 r = rotate(a, axis);
        failures += !same_matrix(glm_rotate(a, axis), r, "rotate");
        // The axis stays put; the opposite axis turns the other way.
        failures += glm::length(glm::vec3(r * glm::vec4(axis, 0)) - axis) >
                    1e-5f * std::fmax(1.0f, glm::length(axis));
        failures += !same_matrix(rotate(-a, axis), rotate(a, -axis), "rotate(-a, axis)");
    }
    CHECK(failures == 0);
    for (float a : kEdgeAngles) {
        CAPTURE(a);
        CHECK(same_matrix(transforms::rotateX(a), rotate(a, {2, 0, 0}), "rotate about x"));
        CHECK(same_matrix(transforms::rotateY(a), rotate(a, {0, 3, 0}), "rotate about y"));
        CHECK(same_matrix(transforms::rotateZ(a), rotate(a, {0, 0, 0.5f}), "rotate about z"));
        // README: a zero axis names no direction and gives the identity.
        CHECK(same_matrix(kIdentity, rotate(a, {0, 0, 0}), "rotate about a zero axis", 0.0f));
    }
}

TEST_CASE("transforms: compose multiplies the named matrices left to right") {
    std::mt19937 rng(kSeed + 3);
    std::uniform_real_distribution<float> u(-3, 3);
    auto random_matrix = [&] {
        glm::mat4 m;
        for (int c = 0; c < 4; ++c) m[c] = {u(rng), u(rng), u(rng), u(rng)};
        return m;
    };
    for (int i = 0; i < 100; ++i) {
        const glm::mat4 T = random_matrix(), R = random_matrix(), S = random_matrix();
        const std::pair<const char*, glm::mat4> products[] = {
            {"trs", T * R * S}, {"tsr", T * S * R}, {"rts", R * T * S},
            {"rst", R * S * T}, {"str", S * T * R}, {"srt", S * R * T}};
        for (const auto& [order, expected] : products) {
            CAPTURE(order);
            CHECK(same_matrix(expected, transforms::compose(order, T, R, S), "compose", 1e-5f));
        }
    }
    for (const char* bad : {"", "tr", "trss", "ttt", "TRS", "xyz"}) {
        CAPTURE(bad);
        const auto compose_bad = [&] { transforms::compose(bad, kIdentity, kIdentity, kIdentity); };
        fw::test::check_mentions(fw::test::thrown<fw::UsageError>(compose_bad),
                                 {"'" + std::string(bad) + "'", "trs", "srt"});
    }
}

TEST_CASE("transforms: the unit function compose is the sheet's M for every order") {
    std::vector<std::vector<float>> inputs = {{0, 0, 0, 1, 1},
                                              {1, 0.5f, 90, 2, 1},
                                              {0.75f, 0.25f, 90, 1.5f, 1},
                                              {-0.5f, 0.75f, 45, -1, 0.5f},
                                              {0, 0, 360, 0.5f, 0.5f},
                                              {2, -2, -360, -3, 3}};
    std::mt19937 rng(kSeed + 4);
    std::uniform_real_distribution<float> t(-2, 2), a(-360, 360), s(-3, 3);
    for (int i = 0; i < kRandomInputs; ++i)
        inputs.push_back({t(rng), t(rng), a(rng), s(rng), s(rng)});
    int failures = 0;
    for (const std::vector<float>& v : inputs)
        for (const fw::Choice<transforms::Order>& o : transforms::kOrders)
            failures +=
                !same_matrix(glm_model(v[0], v[1], v[2], v[3], v[4], o.name),
                             transforms::model_matrix(v[0], v[1], v[2], v[3], v[4], o.value),
                             std::string("compose, order ") + o.name);
    CHECK(failures == 0);
    // Through the lab's unit-function table, as the grader calls it.
    const fw::RegisteredLab& lab = fw::test::this_lab();
    for (const fw::UnitFunction& f : lab.info.functions) {
        if (f.name != "compose") continue;
        const nlohmann::json out = f.call(nlohmann::json::array({1, 0.5, 90, 2, 1, "srt"}));
        CHECK(same_matrix(glm_model(1, 0.5f, 90, 2, 1, "srt"), fw::from_json_value<glm::mat4>(out),
                          "compose via JSON"));
        // An order is passed by its name: an index, or a name not in the
        // list, is refused with the names.
        for (const nlohmann::json& bad : {nlohmann::json(5), nlohmann::json("rrs")}) {
            const auto bad_order = [&] { f.call(nlohmann::json::array({0, 0, 0, 1, 1, bad})); };
            fw::test::check_mentions(fw::test::thrown<fw::Error>(bad_order),
                                     {bad.dump(), "trs", "srt"});
        }
    }
}

TEST_CASE("transforms: the student file builds its matrices without GLM's transform helpers") {
    const std::string source = source_text("labs/01_transforms/transforms_math.cpp");
    for (const char* banned : {"matrix_transform", "gtx/transform", "glm::translate", "glm::scale",
                               "glm::rotate", "glm::ortho", "glm::eulerAngle"}) {
        INFO("labs/01_transforms/transforms_math.cpp mentions " << banned);
        CHECK(source.find(banned) == std::string::npos);
    }
}
