// `portable` checks (docs/contract.md, Checks): the check parsed and planned
// (only its checkpoints ask the child for NAME.usage.json), the file read as
// hostile input, and the verdict's words through judge_lab.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/error.hpp"
#include "grading/judge/checks.hpp"
#include "grading/judge/judge_portable.hpp"
#include "tests/grading/judge_support.hpp"
#include "tests/support/test_support.hpp"

namespace {

using nlohmann::json;

// A lab of two checkpoints, "drawn" with `check` and "other" with a probe.
grading::LabData lab_with(const json& check) {
    const json probe = {{"kind", "probe"}, {"at", {0, 0}}, {"color", {0, 0, 0}}, {"points", 1}};
    return judge_test::lab_of("usage", "91_usage",
                              {judge_test::checkpoint("drawn", json::array({check})),
                               judge_test::checkpoint("other", json::array({probe}))});
}

const json kCheck = {{"kind", "portable"}, {"points", 1}};

// The portable check of checkpoint "drawn", judged from `usage` (none: no
// file) and a frame (a 1x1 PAM) when `rendered`.
grading::CheckResult judged(const std::string* usage, bool rendered = true) {
    const grading::LabData lab = lab_with(kCheck);
    const grading::LabPlan plan = grading::plan_lab(lab, 1, grading::PlanFor::Grading);
    judge_test::Outputs::Files files;
    if (usage) files.push_back({"drawn.usage.json", *usage});
    if (rendered)
        files.push_back({"drawn.pam", fw::encode_pam(fw::Image(512, 512, {0, 0, 0, 255}))});
    else
        files.push_back({"drawn.error.txt", "GL error after draw in lab usage\n"});
    const judge_test::Outputs child(files);
    const std::string out = fw::test::out_dir() + "/report";
    std::filesystem::remove_all(out);
    std::filesystem::create_directories(out + "/usage");
    const std::vector<grading::CheckResult> results =
        grading::judge_lab(lab, plan, *child.outputs, out);
    REQUIRE(results.size() == 2);
    return results[0];
}

bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

const std::string kFinding =
    R"({"rule": "memory-barrier", "call": "glDrawArrays", "draw": 41, "detail": "the buffer 'particles', which call 40 (glDispatchCompute) wrote, is read as vertex attributes (location 0) with no glMemoryBarrier(GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT) since", "times": 1})";

}  // namespace

TEST_CASE("a portable check takes no fields and asks the child for the usage of its render only") {
    const grading::LabData lab = lab_with(kCheck);
    CHECK(lab.checks[0][0].kind == grading::CheckKind::Portable);
    CHECK(std::string(grading::name_of(grading::CheckKind::Portable)) == "portable");
    const grading::LabPlan plan = grading::plan_lab(lab, 1, grading::PlanFor::Grading);
    REQUIRE(plan.job["renders"].size() == 2);
    CHECK(plan.job["renders"][0]["usage"] == true);
    CHECK(plan.job["renders"][1]["usage"] == false);
    // Blessing renders for the images alone.
    CHECK(grading::plan_lab(lab, 1, grading::PlanFor::Blessing).job["renders"].empty());
    json typo = kCheck;
    typo["tolerance"] = 1;
    const std::string error = fw::test::thrown<fw::UsageError>([&] { lab_with(typo); });
    CHECK(has(error, "\"tolerance\" is not a field of a portable check"));
}

TEST_CASE("a portable check passes with no finding and names each finding otherwise") {
    const std::string none = "[]";
    const grading::CheckResult pass = judged(&none);
    CHECK(pass.passed);
    CHECK(pass.title == "GL usage a GPU accepts");
    CHECK(has(pass.output, "Observed: none"));

    const std::string two =
        "[" + kFinding +
        R"(, {"rule": "clip-distance", "call": "glDrawElements", "draw": 3, "detail": "GL_CLIP_DISTANCE0 is not enabled", "times": 4}])";
    const grading::CheckResult fail = judged(&two);
    CHECK_FALSE(fail.passed);
    CHECK(fail.score == 0.0);
    CHECK(has(fail.output,
              "Observed: call 41 of the checkpoint (glDrawArrays): the buffer "
              "'particles', which call 40"));
    CHECK(has(fail.output,
              "\ncall 3 of the checkpoint (glDrawElements): GL_CLIP_DISTANCE0 is "
              "not enabled (4 times)"));
    CHECK(fail.diagnosis ==
          "call 3 of the checkpoint (glDrawElements): GL_CLIP_DISTANCE0 is not enabled (4 times)");

    // A render that failed: its findings, or why it has none.
    const std::string one = "[" + kFinding + "]";
    CHECK(has(judged(&one, false).output, "Observed: call 41 of the checkpoint"));
    const grading::CheckResult failed = judged(&none, false);
    CHECK_FALSE(failed.passed);
    CHECK(has(failed.output, "Observed: none up to where the render failed: no image:"));
}

TEST_CASE("a usage file from the child is hostile: each malformation fails the check, named") {
    const grading::CheckResult missing = judged(nullptr);
    CHECK_FALSE(missing.passed);
    CHECK(has(missing.output, "Observed: no record of the GL usage: "));
    const std::vector<std::pair<std::string, std::string>> bad = {
        {"{}", "drawn.usage.json is not a JSON list of findings"},
        {"[1", "drawn.usage.json is not a JSON list of findings"},
        {"[3]", "finding 0 is not an object"},
        {R"([{"rule": 1, "call": "x", "draw": 1, "detail": "d"}])", "\"rule\" must be a string"},
        {R"([{"rule": "r", "call": "x", "draw": "1", "detail": "d"}])",
         "\"draw\" must be an integer"},
        {R"([{"rule": "r", "call": "x", "draw": 1, "detail": "d", "times": 0.5}])",
         "\"times\" must be an integer"},
    };
    for (const auto& [text, why] : bad) {
        INFO(text);
        const grading::CheckResult r = judged(&text);
        CHECK_FALSE(r.passed);
        CHECK(has(r.output, "Observed: no record of the GL usage: "));
        CHECK(has(r.output, why));
    }
    // A detail of any length is cut for the report.
    const std::string long_detail =
        R"([{"rule": "r", "call": "glDrawArrays", "draw": 1, "detail": ")" +
        std::string(5000, 'x') + R"("}])";
    const grading::CheckResult cut = judged(&long_detail);
    CHECK_FALSE(cut.passed);
    CHECK(cut.output.size() < 1500);
    CHECK(has(cut.output, "xxx..."));
    // More than a report shows: the first eight and a count.
    std::string many = "[";
    for (int i = 0; i < 12; ++i) many += (i ? ", " : "") + kFinding;
    many += "]";
    CHECK(has(judged(&many).output, "\nand 4 more"));
}
