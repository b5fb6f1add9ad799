// Recorded unit cases (grading/judge/cases.hpp): the visible unit checks of
// labs 1-3 recorded from the compiled references, loaded into a copy of each
// lab under another id (as the student's copy has them, without compiled
// references), planned from the file and judged from it. The report must be
// word for word the one the compiled reference gives: passing, failing, and
// naming the same usual mistakes. No child runs.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <glm/glm.hpp>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "framework/error.hpp"
#include "framework/json_glm.hpp"
#include "grading/judge/cases.hpp"
#include "grading/judge/judge_unit.hpp"
#include "grading/run/repository.hpp"
#include "grading/units/mistakes.hpp"
#include "grading/units/recorded.hpp"
#include "grading/units/reference.hpp"
#include "tests/support/test_support.hpp"

namespace {

using grading::LabData;
using nlohmann::json;
namespace fs = std::filesystem;

constexpr double kPi = 3.14159265358979323846;

LabData source_lab(const std::string& id) {
    LabData lab = grading::select_labs(grading::discover_labs(grading::source_root()), {id}).at(0);
    grading::parse_checks(lab);
    return lab;
}

// A copy of `lab` in folder 9N_recorded_NAME of a fresh root's labs, as the
// release writes it: the visible checkpoints and the lab's cases.json.
LabData recorded_copy(const LabData& lab, const json& cases, int number) {
    const std::string root = fw::test::out_dir() + "/" + lab.dir;
    fs::remove_all(root);
    const std::string dir = std::to_string(number) + "_recorded_" + lab.dir.substr(3);
    json file = json::parse(fw::test::read_text(lab.file.path), nullptr, true, true);
    json visible = json::array();
    for (const json& cp : file["checkpoints"])
        if (cp.value("visibility", "visible") != "hidden") visible.push_back(cp);
    file["checkpoints"] = visible;
    fw::test::write_text(root + "/labs/" + dir + "/checkpoints.json", file.dump(1));
    grading::write_unit_cases(root + "/labs/" + dir + "/grading/cases.json", cases);
    LabData copy = grading::discover_labs(root).at(0);
    grading::parse_checks(copy);
    return copy;
}

// The checkpoints whose cases `recorded` holds.
std::set<std::string> recorded_checkpoints(const json& recorded) {
    std::set<std::string> out;
    for (const json& c : recorded["checks"]) out.insert(c["checkpoint"].get<std::string>());
    return out;
}

TEST_CASE("a student's copy records the visible checkpoints' cases, the autograder's every one") {
    const LabData lab = source_lab("transforms");
    std::set<std::string> visible, hidden;
    for (size_t k = 0; k < lab.file.checkpoints.size(); ++k)
        (lab.visibility[k] == grading::Visibility::Hidden ? hidden : visible)
            .insert(lab.file.checkpoints[k].name);
    REQUIRE(!hidden.empty());
    const std::set<std::string> student =
        recorded_checkpoints(grading::record_unit_cases(lab, 1, 2));
    const std::set<std::string> autograder =
        recorded_checkpoints(grading::record_unit_cases(lab, 1, 2, grading::RecordFor::Autograder));
    CHECK(!student.empty());
    for (const std::string& cp : student) CHECK_MESSAGE(visible.count(cp), cp << " is hidden");
    CHECK(std::any_of(autograder.begin(), autograder.end(),
                      [&](const std::string& cp) { return hidden.count(cp) > 0; }));
}

struct Recorded {
    LabData source, copy;
    grading::LabPlan plan;
};

Recorded record(const std::string& id, int number) {
    Recorded r;
    r.source = source_lab(id);
    const json cases = grading::record_unit_cases(r.source, 7, 50);
    CHECK(cases.dump() == grading::record_unit_cases(r.source, 7, 50).dump());
    r.copy = recorded_copy(r.source, cases, number);
    r.plan = grading::plan_lab(r.copy, 1, grading::PlanFor::Grading);
    const auto size = fs::file_size(grading::unit_cases_path(r.copy));
    MESSAGE("labs/" << r.source.dir << "/grading/cases.json: " << size << " bytes");
    CHECK(size < 1000000);
    return r;
}

// What a student's function returns for `args`; `ref` is the compiled reference.
using Student = std::function<json(const grading::ReferenceUnit& ref, const json& args)>;

const grading::UnitCheck& unit_check(const LabData& lab, const grading::UnitPlan& unit) {
    for (size_t k = 0; k < lab.file.checkpoints.size(); ++k)
        if (lab.file.checkpoints[k].name == unit.checkpoint)
            return lab.checks[k].at(unit.check).as<grading::UnitCheck>();
    throw fw::Error("no checkpoint " + unit.checkpoint);
}

// The first unit check of `function` judged with `f`'s results, from the
// copy's recorded reference; the compiled one must give the same report.
grading::CheckResult judged(const Recorded& r, const std::string& function, const Student& f) {
    const grading::ReferenceUnit& compiled = grading::find_reference(r.source.id, function);
    for (const grading::UnitPlan& unit : r.plan.units) {
        const grading::UnitCheck& check = unit_check(r.copy, unit);
        if (check.function != function) continue;
        REQUIRE(check.recorded);
        json units = json::object();
        for (const grading::UnitCase& c : unit.cases)
            units[c.id] = {{"result", f(compiled, c.args)}};
        grading::CheckResult from_file, from_code;
        from_file.max_score = from_code.max_score = 1;
        grading::judge_unit(r.copy, check, unit, 1, &units, "", from_file);
        grading::judge_unit(r.source, check, unit, 1, &units, "", from_code);
        // Word for word but the first words: where the cases come from.
        const auto after_source = [](const std::string& text) {
            return text.substr(text.find(':'));
        };
        CHECK(from_file.output.rfind("the cases recorded in this copy", 0) == 0);
        CHECK(from_code.output.rfind("seed 1 (COURSE_SEED=1", 0) == 0);
        CHECK(after_source(from_file.output) == after_source(from_code.output));
        return from_file;
    }
    FAIL("no unit check of " << function);
    return {};
}

json correct(const grading::ReferenceUnit& ref, const json& args) {
    return ref.function.call(args);
}

// Every number of `v` plus `d`.
json shifted(const json& v, double d) {
    if (v.is_array()) {
        json out = json::array();
        for (const json& e : v) out.push_back(shifted(e, d));
        return out;
    }
    return v.is_number() ? json(v.get<double>() + d) : v;
}

json wrong(const grading::ReferenceUnit& ref, const json& args) {
    return shifted(ref.function.call(args), 0.01);
}

// The reference with every angle argument times `factor`, or the float
// above that (`step`: as a student's float arithmetic may round it), where
// only the change over one float step lets mistake recognition match.
Student angles_times(double factor, bool step = false) {
    return [factor, step](const grading::ReferenceUnit& ref, const json& args) {
        json changed = args;
        for (size_t i = 0; i < ref.domains.size(); ++i) {
            if (!ref.domains[i].degrees) continue;
            const float x = float(args[i].get<double>() * factor);
            changed[i] = double(step ? std::nextafter(x, 1e30f) : x);
        }
        return ref.function.call(changed);
    };
}

// The reference's first alternative for `mistake`.
Student alternative(grading::Mistake mistake) {
    return [mistake](const grading::ReferenceUnit& ref, const json& args) {
        for (const grading::Alternative& a : ref.alternatives)
            if (a.mistake == mistake) return a.function.call(args);
        throw fw::Error("no such alternative");
    };
}

json transposed(const grading::ReferenceUnit& ref, const json& args) {
    return fw::to_json_value(
        glm::transpose(fw::from_json_value<glm::mat4>(ref.function.call(args))));
}

void check_named(const grading::CheckResult& r, const std::string& id) {
    CHECK_FALSE(r.passed);
    fw::test::check_mentions(r.output, {"Likely mistake (" + id + ")"});
}

}  // namespace

TEST_CASE("lab 1's recorded cases judge as its compiled references do") {
    const Recorded r = record("transforms", 91);
    CHECK(r.copy.id == "recorded-transforms");
    CHECK(grading::find_reference("recorded-transforms", "translate").recorded);
    CHECK_FALSE(grading::find_reference("transforms", "translate").recorded);
    for (const char* f :
         {"translate", "scale", "rotateX", "rotateY", "rotateZ", "rotate", "compose"}) {
        CAPTURE(f);
        CHECK(judged(r, f, correct).passed);
        const grading::CheckResult bad = judged(r, f, wrong);
        CHECK_FALSE(bad.passed);
        CHECK(bad.output.find("Likely mistake") == std::string::npos);
    }
    check_named(judged(r, "translate", transposed), "transpose");
    check_named(judged(r, "compose", alternative(grading::Mistake::ReversedProduct)),
                "reversed-product");
    check_named(judged(r, "rotateZ", angles_times(kPi / 180.0)), "radians-for-degrees");
    check_named(judged(r, "rotateX", angles_times(180.0 / kPi)), "degrees-for-radians");
    check_named(judged(r, "rotate", alternative(grading::Mistake::NotNormalised)),
                "not-normalised");
    check_named(judged(r, "compose", angles_times(-1.0)), "flipped-angle");
}

TEST_CASE("lab 2's recorded cases name its mistakes, an element of the list at a time") {
    const Recorded r = record("robot-arm", 92);
    CHECK(judged(r, "arm_matrices", correct).passed);
    CHECK_FALSE(judged(r, "arm_matrices", wrong).passed);
    check_named(judged(r, "arm_matrices", alternative(grading::Mistake::ReversedProduct)),
                "reversed-product");
    check_named(judged(r, "arm_matrices", angles_times(180.0 / kPi)), "degrees-for-radians");
    check_named(judged(r, "arm_matrices", angles_times(180.0 / kPi, true)), "degrees-for-radians");
    // The change over one float step that lets an angle converted in float
    // match: recorded for every case, as the compiled reference computes it.
    const grading::ReferenceUnit& compiled = grading::find_reference("robot-arm", "arm_matrices");
    const grading::ReferenceUnit& file =
        grading::find_reference("recorded-robot-arm", "arm_matrices");
    REQUIRE(file.float_step);
    for (const json& args : r.copy.checks.at(0).back().as<grading::UnitCheck>().recorded.value()) {
        json changed = args, below = args, above = args;
        for (size_t i = 0; i < args.size(); ++i) {
            const float x = float(args[i].get<double>() * 180.0 / kPi);
            changed[i] = double(x);
            below[i] = double(std::nextafter(x, -1e30f));
            above[i] = double(std::nextafter(x, 1e30f));
        }
        for (int k = 0; k < 5; ++k) {
            const double expected = grading::largest_difference(compiled.function.call(below)[k],
                                                                compiled.function.call(above)[k]);
            const std::optional<double> step = file.float_step(changed, below, above, k);
            REQUIRE(step);
            CHECK(*step == doctest::Approx(expected).epsilon(1e-6));
        }
    }
    check_named(judged(r, "arm_matrices", angles_times(kPi / 180.0)), "radians-for-degrees");
    // Only the fingers wrong: the list's element 3 is the one explained.
    const grading::CheckResult fingers =
        judged(r, "arm_matrices", [](const grading::ReferenceUnit& ref, const json& args) {
            json changed = args;
            changed[2] = -args[2].get<double>();
            json out = ref.function.call(args);
            out[3] = ref.function.call(changed)[3];
            out[4] = ref.function.call(changed)[4];
            return out;
        });
    check_named(fingers, "flipped-angle");
}

TEST_CASE("lab 3's recorded cases judge its camera and projection matrices") {
    const Recorded r = record("projection", 93);
    for (const char* f : {"lookAt", "perspective", "orthographic", "perspective01", "viewport"}) {
        CAPTURE(f);
        CHECK(judged(r, f, correct).passed);
        CHECK_FALSE(judged(r, f, wrong).passed);
    }
    check_named(judged(r, "lookAt", alternative(grading::Mistake::NotNormalised)),
                "not-normalised");
    check_named(judged(r, "perspective", angles_times(180.0 / kPi)), "degrees-for-radians");
    check_named(judged(r, "orthographic", transposed), "transpose");
}

TEST_CASE("a recorded reference knows only its recorded arguments; compiled ones win") {
    const LabData lab = source_lab("transforms");
    const json cases = grading::record_unit_cases(lab, 3, 2);
    const grading::ReferenceUnit ref =
        grading::recorded_reference("translate", cases["functions"]["translate"]);
    const json args = cases["checks"][0]["random"][0];
    CHECK(ref.function.call(args) ==
          grading::find_reference("transforms", "translate").function.call(args));
    const auto call_unrecorded = [&] { ref.function.call(json{{1.5, 2, 3}}); };
    fw::test::check_mentions(fw::test::thrown(call_unrecorded), {"not recorded", "[[1.5,2,3]]"});
    CHECK_FALSE(grading::register_reference(lab.dir, ref));
    CHECK_FALSE(grading::find_reference("transforms", "translate").recorded);
    // A check the file has no cases for is refused when the checks are read.
    json other = cases;
    other["checks"] = json::array();
    const std::string message =
        fw::test::thrown<fw::UsageError>([&] { recorded_copy(lab, other, 94); });
    fw::test::check_mentions(message, {"has no cases for this check", "cases.json"});
}
