// The report of a failing unit check (docs/contract.md, Checks): values in
// math layout, whole, and the usual mistakes named. Every mistake is made
// here on purpose, with GLM in this file, against the labs' real references
// (course_units), and must be recognised by its stable ID; correct values,
// unrelated wrong values and cases where the mistake changes nothing must
// name none. No child runs: judge_unit() reads a units.json built here.
#include <algorithm>
#include <cmath>
#include <functional>
#include <glm/glm.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <limits>
#include <nlohmann/json.hpp>
#include <random>
#include <set>
#include <string>
#include <vector>

#include "framework/json_glm.hpp"
#include "framework/names.hpp"
#include "grading/diagnosis/starting_code.hpp"
#include "grading/judge/judge_source.hpp"
#include "grading/judge/judge_unit.hpp"
#include "grading/units/mistakes.hpp"
#include "grading/units/reference.hpp"
#include "tests/support/test_support.hpp"

namespace {

using grading::ReferenceUnit;
using grading::UnitFailure;
using nlohmann::json;

const glm::mat4 kI(1.0f);

// Plain pointers, not strings: a reference returned from a call that took
// class temporaries is what GCC's -Wdangling-reference warns about.
const ReferenceUnit& reference(const char* lab, const char* function) {
    return grading::find_reference(lab, function);
}

glm::mat4 mat(const json& j) { return fw::from_json_value<glm::mat4>(j); }
json js(const glm::mat4& m) { return fw::to_json_value(m); }
float num(const json& j) { return j.get<float>(); }
glm::vec3 vec(const json& j) { return fw::from_json_value<glm::vec3>(j); }

// A student's function, given the arguments and course's expected result.
using Student = std::function<json(const json& args, const json& expected)>;

// `count` random argument lists of `ref` (a fixed seed), the failing ones.
std::vector<UnitFailure> failures(const ReferenceUnit& ref, double tolerance, const Student& f,
                                  int count = 60) {
    std::mt19937 rng(20240611);
    std::vector<UnitFailure> out;
    for (int i = 0; i < count; ++i) {
        const json args = grading::random_arguments(ref, rng);
        const json expected = ref.function.call(args);
        json observed = f(args, expected);
        if (!grading::results_match(expected, observed, tolerance, nullptr))
            out.push_back({args, expected, std::move(observed)});
    }
    return out;
}

std::set<std::string> ids(const ReferenceUnit& ref, const std::vector<UnitFailure>& cases,
                          double tolerance) {
    std::set<std::string> out;
    for (const grading::Explanation& e :
         grading::recognise_mistakes(ref, cases, tolerance).mistakes)
        out.insert(std::string(grading::mistake_id(e.mistake)));
    return out;
}

// The mistakes named for `f` on random arguments of lab.function.
std::set<std::string> named(const std::string& lab, const std::string& function, double tolerance,
                            const Student& f) {
    const ReferenceUnit& ref = reference(lab.c_str(), function.c_str());
    const std::vector<UnitFailure> cases = failures(ref, tolerance, f);
    REQUIRE_MESSAGE(cases.size() > 40, "the deliberate mistake must fail most cases");
    return ids(ref, cases, tolerance);
}

using Ids = std::set<std::string>;

// The fraction of the failing cases that explain_failure() explains.
double explained(const ReferenceUnit& ref, double tolerance, const Student& f) {
    const std::vector<UnitFailure> cases = failures(ref, tolerance, f, 400);
    REQUIRE(!cases.empty());
    size_t n = 0;
    for (const UnitFailure& c : cases)
        n += grading::explain_failure(ref, c, tolerance).empty() ? 0 : 1;
    return double(n) / double(cases.size());
}

glm::mat4 rotate_deg(float degrees, glm::vec3 axis) {
    return glm::rotate(kI, glm::radians(degrees), axis);
}

// lab 1's compose with the factors in `order` ("trs", ...) multiplied left to
// right, or right to left.
glm::mat4 compose(const json& a, bool reversed, float angle_sign = 1.0f) {
    const glm::mat4 T = glm::translate(kI, {num(a[0]), num(a[1]), 0.0f});
    const glm::mat4 R = rotate_deg(angle_sign * num(a[2]), {0, 0, 1});
    const glm::mat4 S = glm::scale(kI, {num(a[3]), num(a[4]), 1.0f});
    glm::mat4 M = kI;
    for (char c : a[5].get<std::string>()) {
        const glm::mat4& F = c == 't' ? T : c == 'r' ? R : S;
        M = reversed ? F * M : M * F;
    }
    return M;
}

// The last column's top three entries moved into the bottom row.
json bottom_row(const json& expected) {
    glm::mat4 m = mat(expected);
    for (int r = 0; r < 3; ++r) {
        m[r][3] = m[3][r];
        m[3][r] = 0.0f;
    }
    return js(m);
}

// lab 3's view matrix with rows u, v, w from unnormalised directions.
json unnormalised_view(const json& a) {
    const glm::vec3 eye = vec(a[0]), w = eye - vec(a[1]), u = glm::cross(vec(a[2]), w),
                    v = glm::cross(w, u);
    glm::mat4 m(1.0f);
    for (int c = 0; c < 3; ++c) {
        m[c][0] = u[c];
        m[c][1] = v[c];
        m[c][2] = w[c];
    }
    m[3] = glm::vec4(-glm::dot(u, eye), -glm::dot(v, eye), -glm::dot(w, eye), 1.0f);
    return js(m);
}

// Rodrigues' formula with the axis as given.
json unnormalised_rotation(const json& a) {
    const float t = glm::radians(num(a[0]));
    const glm::vec3 k = vec(a[1]);
    const float c = std::cos(t), s = std::sin(t);
    glm::mat3 m(c);
    for (int col = 0; col < 3; ++col)
        for (int row = 0; row < 3; ++row) m[col][row] += (1.0f - c) * k[row] * k[col];
    m[1][0] -= s * k.z;
    m[0][1] += s * k.z;
    m[2][0] += s * k.y;
    m[0][2] -= s * k.y;
    m[2][1] -= s * k.x;
    m[1][2] += s * k.x;
    return js(glm::mat4(m));
}

// lab 2's arm with J = T * S instead of S * T, and everything below it built
// on that J, as the student's code would.
json arm_with_reversed_j(const json& a, const json& expected) {
    const glm::mat4 S = mat(expected[0]);
    const glm::mat4 J = glm::translate(kI, {2.0f, 0.0f, 0.0f}) * S;
    const glm::mat4 H = J * rotate_deg(num(a[1]), {0, 0, 1});
    const float grip = num(a[2]);
    return json::array(
        {js(S), js(J), js(H),
         js(H * glm::translate(kI, {1.0f, 0.1f, 0.0f}) * rotate_deg(grip, {0, 0, 1})),
         js(H * glm::translate(kI, {1.0f, -0.1f, 0.0f}) * rotate_deg(-grip, {0, 0, 1}))});
}

glm::vec3 unit_direction(glm::vec3 v) { return glm::normalize(v); }
bool any_direction(glm::vec3) { return true; }

enum class Side { Left, Right };
constexpr fw::Choice<Side> kSides[] = {{Side::Left, "left"}, {Side::Right, "right"}};
float side_sign(Side s) { return s == Side::Left ? -1.0f : 1.0f; }

std::string judge(const std::string& lab, const std::string& function, double tolerance,
                  const std::vector<json>& edge, const Student& f, int random = 20,
                  bool* passed = nullptr, grading::CheckResult* result = nullptr,
                  const std::string& starting = "") {
    const ReferenceUnit& ref = reference(lab.c_str(), function.c_str());
    grading::UnitPlan plan{"cp", 0, {}};
    for (const json& args : edge)
        plan.cases.push_back({"u" + std::to_string(plan.cases.size()), args, true});
    std::mt19937 rng(7);
    for (int i = 0; i < random; ++i)
        plan.cases.push_back(
            {"u" + std::to_string(plan.cases.size()), grading::random_arguments(ref, rng), false});
    json units = json::object();
    for (const grading::UnitCase& c : plan.cases)
        units[c.id] = {{"result", f(c.args, ref.function.call(c.args))}};
    grading::LabData data;
    data.id = lab;
    grading::CheckResult r;
    r.max_score = 4;
    grading::UnitCheck check;
    check.function = function;
    check.tolerance = tolerance;
    grading::judge_unit(data, check, plan, 42, &units, "", r, starting);
    if (passed) *passed = r.passed;
    if (result) *result = r;
    return r.output;
}

size_t count(const std::string& text, const std::string& needle) {
    size_t n = 0;
    for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1))
        ++n;
    return n;
}

}  // namespace

template <>
struct fw::ChoicesOf<Side> {
    static constexpr const auto& list = kSides;
};

TEST_CASE("mistake IDs are the stable names the reports print") {
    using grading::Mistake;
    CHECK(grading::mistake_id(Mistake::Transpose) == "transpose");
    CHECK(grading::mistake_id(Mistake::Inverse) == "inverse");
    CHECK(grading::mistake_id(Mistake::ReversedProduct) == "reversed-product");
    CHECK(grading::mistake_id(Mistake::RadiansForDegrees) == "radians-for-degrees");
    CHECK(grading::mistake_id(Mistake::DegreesForRadians) == "degrees-for-radians");
    CHECK(grading::mistake_id(Mistake::FlippedAngle) == "flipped-angle");
    CHECK(grading::mistake_id(Mistake::TranslationInBottomRow) == "translation-in-bottom-row");
    CHECK(grading::mistake_id(Mistake::NotNormalised) == "not-normalised");
    CHECK(grading::mistake_id(Mistake::FlippedAxis) == "flipped-axis");
    CHECK(grading::mistake_id(Mistake::LastColumnForDiagonal) == "last-column-for-diagonal");
    CHECK(grading::mistake_id(Mistake::LengthSquared) == "length-squared");
    CHECK(grading::mistake_id(Mistake::OffByOne) == "off-by-one");
    CHECK(grading::mistake_id(Mistake::PerspectiveDepth) == "perspective-depth");
}

TEST_CASE("each mistake is recognised against the labs' references") {
    SUBCASE("transpose: compose typed in rows") {
        CHECK(named("transforms", "compose", 1e-5, [](const json&, const json& e) {
                  return js(glm::transpose(mat(e)));
              }) == Ids{"transpose"});
    }
    SUBCASE("inverse: the camera's placement instead of the view matrix") {
        CHECK(named("projection", "lookAt", 1e-4, [](const json&, const json& e) {
                  return js(glm::inverse(mat(e)));
              }) == Ids{"inverse"});
    }
    SUBCASE("reversed-product: compose right to left") {
        CHECK(named("transforms", "compose", 1e-5, [](const json& a, const json&) {
                  return js(compose(a, true));
              }) == Ids{"reversed-product"});
    }
    SUBCASE("reversed-product: lab 2's J = T S, named as J") {
        const ReferenceUnit& ref = reference("robot-arm", "arm_matrices");
        const auto cases = failures(ref, 1e-5, arm_with_reversed_j);
        REQUIRE(cases.size() > 40);
        const grading::Recognised r = grading::recognise_mistakes(ref, cases, 1e-5);
        REQUIRE(r.mistakes.size() == 1);
        CHECK(r.mistakes[0].mistake == grading::Mistake::ReversedProduct);
        CHECK(r.mistakes[0].element == 1);
        const std::string line = grading::likely_mistake(ref, r.mistakes[0]);
        CHECK(line.rfind("Likely mistake (reversed-product): your J (matrix [1] of the list) is ",
                         0) == 0);
    }
    SUBCASE("degrees-for-radians: the angle in degrees given to cos and sin") {
        const Student rotate_x = [](const json& a, const json&) {
            return js(glm::rotate(kI, num(a[0]), {1, 0, 0}));
        };
        const Student perspective = [](const json& a, const json&) {
            return js(glm::perspective(num(a[0]), num(a[1]), num(a[2]), num(a[3])));
        };
        CHECK(named("transforms", "rotateX", 1e-5, rotate_x) == Ids{"degrees-for-radians"});
        CHECK(named("projection", "perspective", 1e-5, perspective) == Ids{"degrees-for-radians"});
        // Every case, though an angle of up to 720 degrees read as radians
        // is only as close as one float step of 41253 degrees.
        CHECK(explained(reference("transforms", "rotateX"), 1e-5, rotate_x) == 1.0);
        CHECK(explained(reference("projection", "perspective"), 1e-5, perspective) == 1.0);
    }
    SUBCASE("radians-for-degrees: converted twice") {
        CHECK(named("transforms", "rotateY", 1e-5, [](const json& a, const json&) {
                  return js(glm::rotate(kI, glm::radians(glm::radians(num(a[0]))), {0, 1, 0}));
              }) == Ids{"radians-for-degrees"});
        CHECK(named("transforms", "compose", 1e-5, [](const json& a, const json&) {
                  json b = a;
                  b[2] = glm::radians(num(a[2]));
                  return js(compose(b, false));
              }) == Ids{"radians-for-degrees"});
    }
    SUBCASE("flipped-angle: compose turning the other way") {
        CHECK(named("transforms", "compose", 1e-5, [](const json& a, const json&) {
                  return js(compose(a, false, -1.0f));
              }) == Ids{"flipped-angle"});
    }
    SUBCASE("a rotation's transpose is its inverse and its opposite angle: all three, said so") {
        const ReferenceUnit& ref = reference("transforms", "rotateZ");
        const auto cases = failures(ref, 1e-5, [](const json& a, const json&) {
            return js(rotate_deg(-num(a[0]), {0, 0, 1}));
        });
        CHECK(ids(ref, cases, 1e-5) == Ids{"transpose", "inverse", "flipped-angle"});
        CHECK(grading::recognise_mistakes(ref, cases, 1e-5).coincide);
    }
    SUBCASE("translation-in-bottom-row: lookAt's translation as a row") {
        CHECK(named("projection", "lookAt", 1e-4, [](const json&, const json& e) {
                  return bottom_row(e);
              }) == Ids{"translation-in-bottom-row"});
    }
    SUBCASE("not-normalised: rotate's axis and lookAt's basis") {
        CHECK(named("transforms", "rotate", 1e-5, [](const json& a, const json&) {
                  return unnormalised_rotation(a);
              }) == Ids{"not-normalised"});
        CHECK(named("projection", "lookAt", 1e-4, [](const json& a, const json&) {
                  return unnormalised_view(a);
              }) == Ids{"not-normalised"});
    }
    SUBCASE("flipped-axis: lookAt's w pointing at the target") {
        const ReferenceUnit& ref = reference("projection", "lookAt");
        const auto cases = failures(ref, 1e-4, [](const json& a, const json&) {
            // w = target - eye: u = up x w turns too, v = w x u does not.
            const glm::vec3 eye = vec(a[0]), target = vec(a[1]), up = vec(a[2]);
            const glm::vec3 w = glm::normalize(target - eye);
            const glm::vec3 u = glm::normalize(glm::cross(up, w)), v = glm::cross(w, u);
            glm::mat4 m(1.0f);
            for (int c = 0; c < 3; ++c) m[c][0] = u[c], m[c][1] = v[c], m[c][2] = w[c];
            m[3][0] = -glm::dot(u, eye), m[3][1] = -glm::dot(v, eye), m[3][2] = -glm::dot(w, eye);
            return js(m);
        });
        REQUIRE(cases.size() > 40);
        const grading::Recognised r = grading::recognise_mistakes(ref, cases, 1e-4);
        REQUIRE(r.mistakes.size() == 1);
        CHECK(r.mistakes[0].mistake == grading::Mistake::FlippedAxis);
        const std::string line = grading::likely_mistake(ref, r.mistakes[0]);
        CHECK(line.rfind("Likely mistake (flipped-axis): your matrix is the expected one with rows "
                         "1 and 3 negated",
                         0) == 0);
    }
    SUBCASE("last-column-for-diagonal: scale typed as a translation") {
        CHECK(named("transforms", "scale", 1e-5, [](const json& a, const json&) {
                  return js(glm::translate(kI, vec(a[0])));
              }) == Ids{"last-column-for-diagonal"});
    }
    SUBCASE("length-squared: rotate's axis divided by dot(axis, axis)") {
        CHECK(named("transforms", "rotate", 1e-5, [](const json& a, const json&) {
                  const glm::vec3 axis = vec(a[1]);
                  json b = a;
                  const glm::vec3 shorter = axis / glm::dot(axis, axis);
                  b[1] = json::array({shorter.x, shorter.y, shorter.z});
                  return unnormalised_rotation(b);
              }) == Ids{"length-squared"});
    }
    SUBCASE("off-by-one: a level of detail counted from 1") {
        const auto plus_one = [](const json&, const json& e) {
            return json(e.get<double>() + 1.0);
        };
        CHECK(named("texture-mapping", "level_of_detail", 1e-4, plus_one) == Ids{"off-by-one"});
        const auto minus_one = [](const json&, const json& e) {
            return json(e.get<double>() - 1.0);
        };
        CHECK(named("texture-mapping", "level_of_detail", 1e-4, minus_one) == Ids{"off-by-one"});
        const auto doubled = [](const json&, const json& e) { return json(2.0 * e.get<double>()); };
        CHECK(named("texture-mapping", "level_of_detail", 1e-4, doubled).empty());
    }
    SUBCASE("not-normalised: a vector result of another length in the right direction") {
        const ReferenceUnit ref =
            grading::make_reference("direction", &unit_direction, {grading::vec(3, -10, 10)});
        const auto cases = failures(ref, 1e-5, [](const json& a, const json&) { return a[0]; });
        REQUIRE(cases.size() > 40);
        CHECK(ids(ref, cases, 1e-5) == Ids{"not-normalised"});
        const std::string line = grading::likely_mistake(ref, {grading::Mistake::NotNormalised});
        CHECK(line.rfind("Likely mistake (not-normalised): your vector points the right way", 0) ==
              0);
    }
}

TEST_CASE("correct and unrelated wrong values name nothing") {
    const std::vector<std::pair<std::string, std::string>> functions = {
        {"transforms", "translate"}, {"transforms", "scale"},       {"transforms", "rotateZ"},
        {"transforms", "rotate"},    {"transforms", "compose"},     {"robot-arm", "arm_matrices"},
        {"projection", "lookAt"},    {"projection", "perspective"}, {"projection", "orthographic"},
        {"projection", "viewport"},  {"pipeline", "expand_quad"}};
    for (const auto& [lab, function] : functions) {
        CAPTURE(function);
        const ReferenceUnit& ref = reference(lab.c_str(), function.c_str());
        std::mt19937 rng(3);
        for (int i = 0; i < 20; ++i) {
            const json args = grading::random_arguments(ref, rng);
            const json expected = ref.function.call(args);
            // Correct: nothing to explain.
            CHECK(grading::explain_failure(ref, {args, expected, expected}, 1e-5).empty());
            // Every number off by 0.25 (the student version's kind of wrong).
            json off = expected;
            std::function<void(json&)> shift = [&](json& v) {
                if (v.is_array())
                    for (json& x : v) shift(x);
                else if (v.is_number())
                    v = v.get<double>() + 0.25;
            };
            shift(off);
            CHECK(grading::explain_failure(ref, {args, expected, off}, 1e-5).empty());
            // Every number zero.
            json zero = expected;
            std::function<void(json&)> clear = [&](json& v) {
                if (v.is_array())
                    for (json& x : v) clear(x);
                else if (v.is_number())
                    v = 0.0;
            };
            clear(zero);
            CHECK(grading::explain_failure(ref, {args, expected, zero}, 1e-5).empty());
        }
    }
    // The identity for every matrix (what the student version returns).
    CHECK(named("transforms", "compose", 1e-5, [](const json&, const json&) {
              return js(kI);
          }).empty());
    CHECK(named("projection", "lookAt", 1e-4, [](const json&, const json&) {
              return js(kI);
          }).empty());
    // Not a value of the reference's form at all: nothing, and no exception.
    const ReferenceUnit& ref = reference("transforms", "rotateZ");
    CHECK(grading::explain_failure(
              ref, {json::array({90}), ref.function.call(json::array({90})), "a string"}, 1e-5)
              .empty());
}

TEST_CASE("a result 1 off names off-by-one only where the reference words it, in its own words") {
    // Lab 7's back_to_front() sorting the centres by z instead of by their
    // distance to the eye: an order whose first wrong index is often 1 off
    // the expected one, which says nothing of counting.
    const auto by_z = [](const json& a, const json&) {
        std::vector<int> order = {0, 1, 2, 3};
        std::stable_sort(order.begin(), order.end(),
                         [&](int i, int j) { return num(a[1 + i][2]) < num(a[1 + j][2]); });
        return json(order);
    };
    const std::string sorted = judge("framebuffer-ops", "back_to_front", 1e-4, {}, by_z, 200);
    REQUIRE(sorted.find("cases passed") != std::string::npos);
    CHECK_MESSAGE(sorted.find("Likely mistake") == std::string::npos, sorted);
    CHECK_MESSAGE(sorted.find("mipmap") == std::string::npos, sorted);
    CHECK(named("framebuffer-ops", "back_to_front", 1e-4, by_z).empty());
    // Every index 1 more, and lab 9's std140 offset 1 more: no words for
    // them, so nothing named either.
    CHECK(named("framebuffer-ops", "back_to_front", 1e-4, [](const json&, const json& e) {
              json out = e;
              for (json& i : out) i = i.get<int>() + 1;
              return out;
          }).empty());
    CHECK(named("buffers", "std140_place", 1e-4, [](const json&, const json& e) {
              json out = e;
              out[0] = out[0].get<double>() + 1.0;
              return out;
          }).empty());
    // Lab 8's level of detail: named, in words about its levels.
    const ReferenceUnit& lod = reference("texture-mapping", "level_of_detail");
    const std::string line = grading::likely_mistake(lod, {grading::Mistake::OffByOne});
    CHECK(line.rfind("Likely mistake (off-by-one): your result is the expected number plus or "
                     "minus 1: a mipmap level counted from 1",
                     0) == 0);
}

TEST_CASE("a mistake that explains only a minority of the failing cases is not named") {
    const ReferenceUnit& ref = reference("transforms", "compose");
    int i = 0;
    const auto some = [&i](int every) {
        return [&i, every](const json&, const json& e) {
            const glm::mat4 m = mat(e);
            return js(i++ % every == 0 ? glm::transpose(m) : m * 2.0f);
        };
    };
    CHECK(ids(ref, failures(ref, 1e-5, some(3)), 1e-5).empty());  // a third
    i = 0;
    const auto most = [&i](const json&, const json& e) {
        const glm::mat4 m = mat(e);
        return js(i++ % 3 != 0 ? glm::transpose(m) : m * 2.0f);
    };
    CHECK(ids(ref, failures(ref, 1e-5, most), 1e-5) == Ids{"transpose"});  // two thirds
}

TEST_CASE("an alternative that equals the expected value explains nothing") {
    // rotateZ(a) for a tiny a: turning the other way, transposing and
    // inverting all give a matrix within the tolerance of the expected one.
    // An observed value just beyond the tolerance on the other side matches
    // those alternatives but must not be called any of them.
    const double tol = 1e-5;
    const float a = glm::degrees(4.5e-6f);  // 2 sin(a) = 0.9 tol
    const ReferenceUnit& ref = reference("transforms", "rotateZ");
    const json args = json::array({a});
    const json expected = ref.function.call(args);
    glm::mat4 m = mat(expected);
    m[1][0] += 1.8e-5f;  // row 0, column 1: -sin a + 1.8 tol, near sin a
    m[0][1] -= 1.8e-5f;
    const json observed = js(m);
    REQUIRE_FALSE(grading::results_match(expected, observed, tol, nullptr));
    REQUIRE(grading::results_match(js(glm::transpose(mat(expected))), observed, tol, nullptr));
    CHECK(grading::explain_failure(ref, {args, expected, observed}, tol).empty());

    // A symmetric matrix is its own transpose; an angle of 0 negated is 0.
    const ReferenceUnit& scale = reference("transforms", "scale");
    const json s = scale.function.call(json::array({json::array({2, 3, 4})}));
    glm::mat4 wrong = mat(s);
    wrong[0][0] = 5.0f;
    CHECK(
        grading::explain_failure(scale, {json::array({json::array({2, 3, 4})}), s, js(wrong)}, tol)
            .empty());
    const json zero = ref.function.call(json::array({0}));
    CHECK(
        grading::explain_failure(ref, {json::array({0}), zero, js(mat(zero) * 3.0f)}, tol).empty());
}

TEST_CASE("matrices print in rows, columns aligned, numbers without needless decimals") {
    // Rows as on paper:
    //   1   2    3   4
    //   0  -1  0.5   0
    //   0   0    1  10
    //   0   0    0   1
    const json m = json::array({json::array({1, 0, 0, 0}), json::array({2, -1, 0, 0}),
                                json::array({3, 0.5, 1, 0}), json::array({4, 0, 10, 1})});
    CHECK(grading::matrix_rows(m, 5) ==
          std::vector<std::string>{"[ 1   2    3   4 ]", "[ 0  -1  0.5   0 ]", "[ 0   0    1  10 ]",
                                   "[ 0   0    0   1 ]"});
    CHECK(grading::vector_text(json::array({1.5, -2, 0}), 5) == "(1.5, -2, 0)");
    CHECK(grading::unit_decimals(1e-4) == 5);
    CHECK(grading::unit_decimals(1e-5) == 6);
    CHECK(grading::unit_number(0.70710678, 5) == "0.70711");
    CHECK(grading::unit_number(-4.37e-8, 5) == "0");
    CHECK(grading::unit_number(2.5, 6) == "2.5");
    CHECK(grading::matrix_rows(json::array({json::array({1, 2}), "x"}), 5).empty());

    const ReferenceUnit& ref = reference("transforms", "translate");
    const json args = json::array({json::array({1, -2, 3})});
    const json expected = ref.function.call(args);
    const json observed = js(glm::transpose(mat(expected)));
    CHECK(grading::unit_case_text(
              ref, args, true, expected, &observed,
              "first difference: " + grading::unit_difference(ref, expected, observed, 1e-5),
              1e-5) ==
          "  translate(vec3(1, -2, 3)) [edge case]\n"
          "    expected (rows):    observed (rows):\n"
          "    [ 1  0  0   1 ]     [ 1   0  0  0 ]\n"
          "    [ 0  1  0  -2 ]     [ 0   1  0  0 ]\n"
          "    [ 0  0  1   3 ]     [ 0   0  1  0 ]\n"
          "    [ 0  0  0   1 ]     [ 1  -2  3  1 ]\n"
          "    first difference: row 3, column 0 (GLM m[0][3]): expected 0, got 1\n");
}

TEST_CASE("a failing unit check's output: the counts, the mistake once, the rows note once") {
    bool passed = true;
    const std::string out = judge(
        "transforms", "translate", 1e-5, {json::array({json::array({1, -2, 3})})},
        [](const json&, const json& e) { return js(glm::transpose(mat(e))); }, 20, &passed);
    MESSAGE(out);
    CHECK_FALSE(passed);
    CHECK(out.rfind("seed 42 (COURSE_SEED=42 repeats these cases): 20 random and 1 edge cases; "
                    "tolerance 1e-05 (relative where |expected| > 1)\n"
                    "Expected: every case equal to course's reference\n"
                    "Observed: 0 of 21 cases passed\n"
                    "Likely mistake (transpose): your matrix is the transpose of the expected "
                    "one",
                    0) == 0);
    CHECK(count(out, "Likely mistake (transpose): ") == 1);
    CHECK(count(out, "Likely mistake (translation-in-bottom-row): ") == 1);
    CHECK(count(out, "Likely mistake (") == 2);
    CHECK(count(out, grading::kMatrixRowsNote) == 1);
    CHECK(count(out, "expected (rows):") == 3);  // three cases shown, of 21
    CHECK(out.find("  translate(vec3(1, -2, 3)) [edge case]\n") != std::string::npos);

    const std::string good = judge(
        "transforms", "rotateZ", 1e-5, {json::array({90})},
        [](const json&, const json& e) { return e; }, 20, &passed);
    CHECK(passed);
    CHECK(good.find("Observed: 21 of 21 cases passed") != std::string::npos);
    CHECK(good.find("Likely mistake") == std::string::npos);
    CHECK(good.find("First failures") == std::string::npos);

    // Wrong in an unrelated way: failures shown, no mistake named.
    const std::string other = judge(
        "transforms", "rotateZ", 1e-5, {json::array({90})},
        [](const json&, const json& e) { return js(mat(e) * 2.0f); }, 20, &passed);
    CHECK_FALSE(passed);
    CHECK(other.find("First failures") != std::string::npos);
    CHECK(other.find("Likely mistake") == std::string::npos);
}

TEST_CASE("long values are printed whole: every matrix of a list, every vector") {
    bool passed = true;
    // Every matrix of lab 2's five wrong in every entry, with long numbers.
    const auto far = [](const json&, const json& e) {
        json o = e;
        for (json& m : o)
            for (json& column : m)
                for (json& x : column) x = x.get<double>() * 1000.0 + 123.456789;
        return o;
    };
    const std::string out =
        judge("robot-arm", "arm_matrices", 1e-5, {json::array({30, -45, 20})}, far, 2, &passed);
    MESSAGE(out);
    CHECK_FALSE(passed);
    CHECK(out.size() > 2000);
    CHECK(out.find("...") == std::string::npos);
    const ReferenceUnit& arm = reference("robot-arm", "arm_matrices");
    const json args = json::array({30, -45, 20});
    const json observed = far(args, arm.function.call(args));
    const int decimals = grading::unit_decimals(1e-5);
    for (size_t k = 0; k < 5; ++k)
        for (const std::string& row : grading::matrix_rows(observed[k], decimals)) {
            CAPTURE(row);
            CHECK(out.find(row) != std::string::npos);
        }
    for (const std::string name :
         {"[0] S:\n", "[1] J:\n", "[2] H:\n", "[3] upper finger:\n", "[4] lower finger:\n"})
        CHECK(count(out, name) == 3);

    // Only H and the fingers wrong: S and J are said to be as expected.
    const std::string some = judge(
        "robot-arm", "arm_matrices", 1e-5, {json::array({30, -45, 20})},
        [](const json&, const json& e) {
            json o = e;
            for (size_t k = 2; k < 5; ++k) o[k][3][0] = o[k][3][0].get<double>() + 1.0;
            return o;
        },
        0, &passed);
    CHECK(some.find("    [0] S: as expected\n    [1] J: as expected\n    [2] H:\n") !=
          std::string::npos);
    CHECK(some.find("first difference: [2] H, row 0, column 3 (GLM m[3][0])") != std::string::npos);

    // Lab 0's six vertices, each on its own line, the wrong ones marked.
    const std::string quad = judge(
        "pipeline", "expand_quad", 1e-5,
        {json::array({json::array({0, 0, 0}), json::array({1, 0, 0}), json::array({1, 1, 0}),
                      json::array({0, 1, 0})})},
        [](const json&, const json& e) {
            json o = e;
            o[5] = json::array({7, 8, 9});
            return o;
        },
        0, &passed);
    MESSAGE(quad);
    CHECK(quad.find("    expected:        observed:\n"
                    "    [0] (0, 0, 0)    (0, 0, 0)\n"
                    "    [1] (1, 0, 0)    (1, 0, 0)\n"
                    "    [2] (1, 1, 0)    (1, 1, 0)\n"
                    "    [3] (0, 0, 0)    (0, 0, 0)\n"
                    "    [4] (1, 1, 0)    (1, 1, 0)\n"
                    "    [5] (0, 1, 0)    (7, 8, 9)   <- differs\n"
                    "    first difference: [5], component x: expected 0, got 7\n") !=
          std::string::npos);
    CHECK(quad.find(grading::kMatrixRowsNote) == std::string::npos);
}

TEST_CASE("a vector's components are named by what they mean; depth weighted by 1/w is named") {
    // Lab 11's interpolate() returns (r, g, b, depth): the student's depth
    // interpolated like the colour, sum (lambda_i / w_i) z_i / sum lambda_i / w_i.
    const Student depth_by_w = [](const json& a, const json& e) {
        json o = e;
        if (!a[6].get<bool>()) return o;
        double sum = 0.0, norm = 0.0, total = 0.0;
        for (int i = 0; i < 3; ++i) total += a[5][i].get<double>();
        for (int i = 0; i < 3; ++i) {
            const double k = a[5][i].get<double>() / total / a[4][i].get<double>();
            sum += k * a[3][i].get<double>();
            norm += k;
        }
        o[3] = sum / norm;
        return o;
    };
    const json edge = json::array({json::array({1, 0, 0}), json::array({0, 1, 0}),
                                   json::array({0, 0, 1}), json::array({0.2, 0.2, 0.8}),
                                   json::array({1, 4, 1}), json::array({0.25, 0.5, 0.25}), true});
    bool passed = true;
    const std::string out =
        judge("rasterizer", "interpolate", 1e-4, {edge}, depth_by_w, 20, &passed);
    MESSAGE(out);
    CHECK_FALSE(passed);
    CHECK(out.find("first difference: component depth: expected ") != std::string::npos);
    CHECK(out.find("component w") == std::string::npos);
    CHECK(out.find("Likely mistake (perspective-depth): your vector has the depth interpolated "
                   "perspective-correctly") != std::string::npos);
    // Another mistake of the same function, the colour left affine where it
    // should be perspective-correct: it names no perspective-depth.
    const Student colour_affine = [](const json& a, const json& e) {
        if (!a[6].get<bool>()) return e;
        json args = a;
        args[6] = false;
        return reference("rasterizer", "interpolate").function.call(args);
    };
    const std::string other =
        judge("rasterizer", "interpolate", 1e-4, {edge}, colour_affine, 20, &passed);
    CHECK_FALSE(passed);
    CHECK(other.find("perspective-depth") == std::string::npos);
}

TEST_CASE("a part at its starting code is shown its first difference, not the answer") {
    // Lab 12's shadow_matrix() as the starting code returns it: the identity.
    const Student identity = [](const json&, const json&) { return js(glm::mat4(1.0f)); };
    const json light = json::array({1, 1, 0, 0});
    const std::string starting = "shadow_matrix() is still the starting code.";
    const std::string out = judge("shadows", "shadow_matrix", 1e-4, {json::array({light})},
                                  identity, 5, nullptr, nullptr, starting);
    MESSAGE(out);
    CHECK(out.find(starting) != std::string::npos);
    CHECK(out.find("  shadow_matrix(vec4(1, 1, 0, 0)) [edge case]\n"
                   "    first difference: row 0, column 1 (GLM m[1][0]): expected -1, got 0\n") !=
          std::string::npos);
    CHECK(out.find("expected (rows):") == std::string::npos);
    CHECK(out.find(grading::kMatrixRowsNote) == std::string::npos);
    // Past the starting code, the whole expected matrix beside the student's.
    const std::string later = judge("shadows", "shadow_matrix", 1e-4, {json::array({light})},
                                    identity, 5, nullptr, nullptr, "");
    CHECK(later.find("expected (rows):") != std::string::npos);
}

TEST_CASE("a case without a result shows the expected value and why") {
    const ReferenceUnit& ref = reference("transforms", "rotateZ");
    const json args = json::array({90});
    const std::string text = grading::unit_case_text(ref, args, false, ref.function.call(args),
                                                     nullptr, "the function failed: boom", 1e-5);
    CHECK(text ==
          "  rotateZ(90)\n"
          "    expected (rows):    observed (rows):\n"
          "    [ 0  -1  0  0 ]     none\n"
          "    [ 1   0  0  0 ]\n"
          "    [ 0   0  1  0 ]\n"
          "    [ 0   0  0  1 ]\n"
          "    the function failed: boom\n");
    // A malformed result from the child is shown cut, as raw JSON.
    const json huge = std::string(5000, 'x');
    const std::string cut =
        grading::unit_case_text(ref, args, false, ref.function.call(args), &huge, "", 1e-5);
    CHECK(cut.size() < 1000);
    CHECK(cut.find("xxx...") != std::string::npos);
}

TEST_CASE("a reference's extras are checked when it registers") {
    ReferenceUnit names = grading::make_reference(
        "direction", &unit_direction, {grading::vec(3, -1, 1)}, grading::element_names({"a", "b"}));
    CHECK_THROWS_WITH_AS(grading::register_reference("98_extras", std::move(names)),
                         doctest::Contains("names the elements of a result that is not a list"),
                         fw::Error);
    ReferenceUnit alt =
        grading::make_reference("direction", &unit_direction, {grading::vec(3, -1, 1)},
                                grading::reversed_product(&rotate_deg));  // two arguments, a matrix
    CHECK_THROWS_WITH_AS(grading::register_reference("98_extras", std::move(alt)),
                         doctest::Contains("alternative whose arguments or result differ"),
                         fw::Error);
    const ReferenceUnit tol =
        grading::make_reference("direction", &unit_direction, {grading::vec(3, -1, 1)}, 0.5);
    CHECK(tol.tolerance == 0.5);
    CHECK(tol.shape.kind == grading::ValueShape::Kind::Vector);
    CHECK(reference("robot-arm", "arm_matrices").shape.list);
    CHECK(reference("transforms", "rotateZ").domains[0].degrees);
    // An enum argument is drawn from its names, and only a choice fits it.
    ReferenceUnit by_index = grading::make_reference("side", &side_sign, {grading::integer(0, 1)});
    CHECK_THROWS_WITH_AS(grading::register_reference("98_extras", std::move(by_index)),
                         doctest::Contains("argument 1 is an enum and needs grading::choice"),
                         fw::Error);
    ReferenceUnit on_a_number =
        grading::make_reference("direction", &unit_direction, {grading::choice<Side>()});
    CHECK_THROWS_WITH_AS(grading::register_reference("98_extras", std::move(on_a_number)),
                         doctest::Contains("argument 1 is not an enum"), fw::Error);
    std::mt19937 rng(5);
    std::set<std::string> drawn;
    for (int i = 0; i < 200; ++i)
        drawn.insert(grading::random_arguments(reference("transforms", "compose"), rng)[5]);
    CHECK(drawn == std::set<std::string>{"trs", "tsr", "rts", "rst", "str", "srt"});
}

TEST_CASE("a domain on a grid draws its multiples only; a redraw_when() draw is drawn again") {
    // Lab 11's triangles: corners on the 1/16-pixel grid, none degenerate.
    const ReferenceUnit& bary = reference("rasterizer", "barycentric");
    std::mt19937 rng(11);
    std::set<double> xs;
    for (int i = 0; i < 2000; ++i) {
        const json args = grading::random_arguments(bary, rng);
        for (const json& corner : args)
            for (const json& v : corner) {
                const double x = v.get<double>();
                CHECK((x >= 0.0 && x <= 32.0 && x * 16.0 == std::floor(x * 16.0)));
                xs.insert(x);
            }
        const glm::dvec2 a = fw::from_json_value<glm::vec2>(args[0]),
                         b = fw::from_json_value<glm::vec2>(args[1]),
                         c = fw::from_json_value<glm::vec2>(args[2]);
        CHECK((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x) != 0.0);
    }
    CHECK(xs.size() > 400);  // of the 513 multiples in [0, 32]
    // A grid between whose bounds no multiple lies, and a test that always
    // holds, are refused.
    ReferenceUnit empty = grading::make_reference(
        "direction", &unit_direction, {grading::on_grid(grading::vec(3, 0.1, 0.2), 1.0)});
    CHECK_THROWS_WITH_AS(grading::register_reference("98_extras", std::move(empty)),
                         doctest::Contains("on a grid with no point between its bounds"),
                         fw::Error);
    ReferenceUnit always =
        grading::make_reference("direction", &unit_direction, {grading::vec(3, -1, 1)},
                                grading::redraw_when(&any_direction));
    CHECK_THROWS_WITH_AS(grading::random_arguments(always, rng),
                         doctest::Contains("1000 argument lists in a row were drawn again"),
                         fw::Error);
}

TEST_CASE("an aggregate result is a list whose elements the report names by field") {
    const ReferenceUnit& arm = reference("robot-arm", "arm_matrices");
    CHECK(arm.element_names ==
          std::vector<std::string>{"S", "J", "H", "upper finger", "lower finger"});
    CHECK(arm.shape.kind == grading::ValueShape::Kind::Matrix);
    const json args = json::array({30, -45, 20});
    json wrong = arm.function.call(args);
    REQUIRE(wrong.size() == 5);
    wrong[1][3][0] = wrong[1][3][0].get<double>() + 1.0;  // J's translation x
    const std::string text =
        grading::unit_case_text(arm, args, false, arm.function.call(args), &wrong, "", 1e-5);
    CHECK(text.find("J") != std::string::npos);
}

TEST_CASE("a forbidden name is found in code, never in comments or strings") {
    const std::string text =
        "// glm::translate in a comment\n"                                    // 1
        "/* glm::translate\n   in a block */ int x = 1'000;\n"                // 2-3
        "const char* s = \"glm::translate(\\\"\";  char c = '\"';\n"          // 4
        "glm::mat4 a = glm::translate(M, t);\n"                               // 5
        "glm::mat4 b = glm::translateX(M); auto c = my_glm::translate(M);\n"  // 6
        "#include <glm/gtc/matrix_transform.hpp>\n"                           // 7
        "glm::mat4 d = glm::translate (M, t);  // and glm::translate\n";      // 8
    CHECK(grading::lines_using(text, "glm::translate") == std::vector<int>{5, 8});
    CHECK(grading::lines_using(text, "matrix_transform") == std::vector<int>{7});
    CHECK(grading::lines_using(text, "glm::rotate").empty());
    // Line numbers survive the blanking.
    const std::string code = grading::code_only(text);
    CHECK(std::count(code.begin(), code.end(), '\n') == std::count(text.begin(), text.end(), '\n'));
    CHECK(code.find("comment") == std::string::npos);
}

TEST_CASE("a forbidden-name check reads the source only beside a lab that ran") {
    grading::LabData lab;
    lab.root = lab.sources = fw::test::source_dir();
    grading::ForbiddenCheck check;
    check.files = {"labs/01_transforms/transforms_math.cpp"};
    check.names = {"glm::translate"};
    check.rule = "by hand";
    grading::CheckResult ran;
    ran.max_score = 2;
    grading::judge_forbidden(lab, check, grading::LabStatus(), ran);
    CHECK(ran.passed);
    CHECK(ran.score == 2);
    CHECK(ran.title == "source without glm::translate");
    // A submission that does not build keeps nothing for what it leaves out.
    grading::CheckResult broken;
    broken.max_score = 2;
    grading::judge_forbidden(lab, check, grading::LabStatus::failed("it does not build"), broken);
    CHECK_FALSE(broken.passed);
    CHECK(broken.score == 0);
    CHECK(broken.title == "source without glm::translate");
    CHECK(broken.output.find("it does not build") != std::string::npos);
    // A name that is there fails the check and is named with its line.
    check.names = {"glm::mat4", "glm::translate", "glm::scale"};
    grading::CheckResult found;
    found.max_score = 2;
    grading::judge_forbidden(lab, check, grading::LabStatus(), found);
    CHECK_FALSE(found.passed);
    CHECK(found.output.find("transforms_math.cpp:") != std::string::npos);
    CHECK(found.title == "source without glm::mat4 and 2 other names");
}

TEST_CASE("a unit check's points are proportional to its cases passed, rounded down to 0.1") {
    CHECK(grading::unit_points(4, 1008, 1009) == doctest::Approx(3.9));
    CHECK(grading::unit_points(4, 1009, 1009) == 4);
    CHECK(grading::unit_points(4, 0, 1009) == 0);
    CHECK(grading::unit_points(1, 1, 2) == doctest::Approx(0.5));
    CHECK(grading::unit_points(2, 3, 1006) == 0);  // 0.006 points: not a tenth
    CHECK(grading::unit_points(2.5, 999, 1000) == doctest::Approx(2.4));

    // One wrong case of 1009 (the edge case) costs a tenth, not the whole check.
    const json edge = json::array({json::array({1, -2, 3})});
    grading::CheckResult r;
    bool passed = true;
    const std::string out = judge(
        "transforms", "translate", 1e-5, {edge},
        [&](const json& args, const json& e) {
            return args == edge ? js(glm::transpose(mat(e))) : e;
        },
        1008, &passed, &r);
    CHECK_FALSE(passed);
    CHECK_FALSE(r.passed);
    CHECK(r.score == doctest::Approx(3.9));
    CHECK(r.max_score == 4);
    CHECK(out.find("Observed: 1008 of 1009 cases passed") != std::string::npos);
    // What the terminal prints: the mistake named, and the first case in rows.
    CHECK(r.diagnosis.rfind("Likely mistake (transpose): ", 0) == 0);
    CHECK(r.first_case.rfind("  translate(vec3(1, -2, 3)) [edge case]\n", 0) == 0);
    CHECK(r.first_case.find("expected (rows):") != std::string::npos);
}

TEST_CASE("NaN and infinity travel as such and are printed with what they usually mean") {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    const float inf = std::numeric_limits<float>::infinity();
    // The child's encoding: strings, not null; read back as the same values.
    CHECK(fw::to_json_value(nan) == json("NaN"));
    CHECK(fw::to_json_value(inf) == json("Infinity"));
    CHECK(fw::to_json_value(-inf) == json("-Infinity"));
    CHECK(fw::to_json_value(glm::vec3(1, nan, 2)).dump() == "[1.0,\"NaN\",2.0]");
    CHECK(std::isnan(fw::from_json_value<float>(json("NaN"))));
    CHECK(fw::from_json_value<glm::vec2>(json::array({"-Infinity", 1}))[0] == -inf);
    CHECK(fw::to_json_value(glm::mat4(nan)).dump().find("null") == std::string::npos);
    CHECK(grading::unit_number(nan, 5) == "NaN");
    CHECK(grading::unit_number(-inf, 5) == "-Infinity");

    std::string why;
    CHECK_FALSE(grading::results_match(json(0.5), json("NaN"), 1e-5, &why));
    CHECK(why == "expected 0.5, got NaN (a division by a zero length?)");
    CHECK_FALSE(grading::results_match(json(0.5), json("Infinity"), 1e-5, &why));
    CHECK(why == "expected 0.5, got Infinity (a division by zero?)");

    // A function that divides by a zero length: every entry NaN (as the child
    // writes it, through json_glm.hpp), the report says so and never "null".
    grading::CheckResult r;
    const std::string out = judge(
        "transforms", "translate", 1e-5, {json::array({json::array({1, -2, 3})})},
        [&](const json&, const json& e) { return js(mat(e) * nan); }, 5, nullptr, &r);
    MESSAGE(out);
    CHECK(out.find("null") == std::string::npos);
    CHECK(out.find("[ NaN  NaN  NaN  NaN ]") != std::string::npos);
    CHECK(out.find("got NaN (a division by a zero length?)") != std::string::npos);
    CHECK(r.diagnosis.find("Your function returned NaN: a division by a zero length?") !=
          std::string::npos);
    CHECK(r.score == 0);

    const std::string infinite = judge(
        "transforms", "translate", 1e-5, {json::array({json::array({1, -2, 3})})},
        [&](const json&, const json& e) { return js(mat(e) * inf); }, 5, nullptr, &r);
    CHECK(infinite.find("Infinity (a division by zero?)") != std::string::npos);
}
