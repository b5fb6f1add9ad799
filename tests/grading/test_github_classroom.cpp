// GitHub Classroom's results.json (docs/contract.md, GitHub Classroom's
// results.json), written by `course grade --format github-classroom` for runs
// built by hand, against the shape GitHub Classroom's autograding reporter
// reads: every field and its type, the tests' scores adding up to course's
// points as the reporter adds them, "pass" only at full marks, and a large
// run within one environment variable. The workflow is tested in
// test_github_classroom_workflow.cpp.
#include <cmath>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "grading/report/by_checkpoint.hpp"
#include "grading/report/github_classroom_results.hpp"
#include "grading/report/reports.hpp"
#include "tests/grading/report_fixture.hpp"
#include "tests/support/test_support.hpp"

namespace {

using grading::GradeRun;
using grading::LabResult;
using nlohmann::json;
namespace fs = std::filesystem;
using report_fixture::check;
using report_fixture::crashed_transforms;
using report_fixture::kCrash;
using report_fixture::test_named;

// Linux's most bytes in one environment string (MAX_ARG_STRLEN), "NAME=" and
// its end included: the workflow hands each results.json to the reporter in one.
constexpr size_t kEnvironmentString = 128 * 1024;

// The reporter's shape, field by field: the run's version, status, max_score
// and tests; each test's name, status, score, message, test_code, filename
// and line_no, of these types, and nothing else.
void check_shape(const json& j) {
    REQUIRE(j.is_object());
    std::set<std::string> keys;
    for (const auto& [key, value] : j.items()) keys.insert(key);
    CHECK(keys == std::set<std::string>{"version", "status", "max_score", "tests"});
    CHECK(j["version"].is_number_integer());
    CHECK(j["version"] == 1);
    REQUIRE(j["status"].is_string());
    CHECK(std::set<std::string>{"pass", "fail", "error"}.count(j["status"]) == 1);
    CHECK(j["max_score"].is_number());
    REQUIRE(j["tests"].is_array());
    for (const json& t : j["tests"]) {
        INFO(t.dump());
        std::set<std::string> test_keys;
        for (const auto& [key, value] : t.items()) test_keys.insert(key);
        CHECK(test_keys == std::set<std::string>{"name", "status", "score", "message", "test_code",
                                                 "filename", "line_no"});
        CHECK(t["name"].is_string());
        REQUIRE(t["status"].is_string());
        CHECK(std::set<std::string>{"pass", "fail", "error"}.count(t["status"]) == 1);
        CHECK(t["score"].is_number());
        CHECK(t["score"].get<double>() >= 0.0);
        CHECK(t["message"].is_string());
        CHECK(t["test_code"].is_string());
        CHECK(t["filename"] == "");
        // The reporter prints " - line N" after the name unless line_no is 0.
        CHECK(t["line_no"].is_number_integer());
        CHECK(t["line_no"] == 0);
    }
}

// The total as the reporter's NotifyClassroom adds it (the points GitHub
// Classroom records): every test's score in order, in doubles, over the runs
// that have a max_score.
double reporter_total(const json& j) {
    double total = 0.0;
    if (j["max_score"].get<double>() == 0.0) return total;
    for (const json& t : j["tests"]) total += t["score"].get<double>();
    return total;
}

// Each checkpoint's test against course's own model of it (by_checkpoint):
// same order and points, "pass" exactly when every check passed, which is
// exactly at full marks.
void check_against_model(const json& j, const GradeRun& run) {
    size_t i = 0;
    for (const LabResult& lab : run.labs)
        for (const grading::CheckpointResult& cp : grading::by_checkpoint(lab)) {
            REQUIRE(i < j["tests"].size());
            const json& t = j["tests"][i++];
            INFO(t.dump());
            CHECK(t["name"] == lab.lab + " / " + cp.checkpoint);
            CHECK(t["score"].get<double>() == doctest::Approx(cp.score).epsilon(1e-12));
            CHECK((t["status"] == "pass") == cp.passed);
            CHECK((t["status"] == "pass") == (cp.score == cp.max_score));
        }
    CHECK(i == j["tests"].size());
    CHECK(j["max_score"].get<double>() == doctest::Approx(run.max_score()));
    CHECK(reporter_total(j) == doctest::Approx(run.score()).epsilon(1e-12));
    CHECK((j["status"] == "pass") == run.passed());
}

// Lab 00: triangle (image 4/4 passed, probe 0/2 failed), spin (unit 0.7/1 and
// 0.1/1 failed, stat 1/1), secret (hidden, unit 3/3 passed), vault (hidden,
// probe 0/1 failed); lab 01 crashed: rotate (image 0/5, stat 0/2). 8.8 of
// 20 points; 1 of 5 checkpoints passed.
GradeRun fixture_run() {
    LabResult pipeline;
    pipeline.lab = "00_pipeline";
    pipeline.checks = {
        check("00_pipeline", "triangle", "image", "image vs reference", 4, 4, true,
              "Observed: 0 of 12 pixels differ"),
        check("00_pipeline", "triangle", "probe", "probe (8, 8) colour", 0, 2, false,
              "Expected: (1, 0, 0)\nObserved: (0, 0, 1) \x1b[31mblue\x01 \xff"),
        check("00_pipeline", "spin", "unit", "unit spin(v)", 0.7, 1, false,
              "Observed: 70 of 100 cases right"),
        check("00_pipeline", "spin", "unit", "unit turn(v)", 0.1, 1, false,
              "Observed: 10 of 100 cases right"),
        check("00_pipeline", "spin", "stat", "draws == 1", 1, 1, true, ""),
        check("00_pipeline", "secret", "unit", "unit secret(v)", 3, 3, true, "", "hidden"),
        check("00_pipeline", "vault", "probe", "probe (1, 1) vault colour", 0, 1, false,
              "Expected: secret-value 42\nObserved: 41", "hidden")};
    GradeRun run;
    run.labs = {pipeline, crashed_transforms()};
    return run;
}

}  // namespace

TEST_CASE("github-classroom results.json: the reporter's fields, a test per checkpoint") {
    const GradeRun run = fixture_run();
    const json j = json::parse(grading::github_classroom_results_json(run));
    INFO(j.dump(2));
    check_shape(j);
    check_against_model(j, run);
    CHECK(j["max_score"] == 20);
    CHECK(reporter_total(j) == doctest::Approx(8.8));
    REQUIRE(j["tests"].size() == 5);

    // A failed checkpoint: its first failed check and why, as plain clean
    // text; the command that shows all its checks under its name.
    const json& triangle = test_named(j, "00_pipeline / triangle");
    CHECK(triangle["status"] == "fail");
    CHECK(triangle["score"] == 4);
    CHECK(triangle["message"] == "probe (8, 8) colour: Observed: (0, 0, 1) blue \xEF\xBF\xBD");
    CHECK(triangle["test_code"] == "scripts/grade.sh 00_pipeline");
    // Partial points count, and the checkpoint still fails.
    const json& spin = test_named(j, "00_pipeline / spin");
    CHECK(spin["status"] == "fail");
    CHECK(spin["score"].get<double>() == doctest::Approx(1.8));
    // A passed checkpoint has nothing to say: the reporter prints its name.
    const json& secret = test_named(j, "00_pipeline / secret");
    CHECK(secret["status"] == "pass");
    CHECK(secret["message"] == "");
    CHECK(secret["test_code"] == "");
    // A hidden checkpoint that failed says so, and nothing of its checks.
    const json& vault = test_named(j, "00_pipeline / vault");
    CHECK(vault["status"] == "fail");
    fw::test::check_mentions(vault["message"], {"Hidden checkpoint"});
    for (const char* secret_text : {"vault colour", "secret-value", "41"})
        CHECK(vault.dump().find(secret_text) == std::string::npos);
    // A lab whose child crashed: an error, which the reporter prints with
    // its message, and so is the run.
    const json& rotate = test_named(j, "01_transforms / rotate");
    CHECK(rotate["status"] == "error");
    fw::test::check_mentions(rotate["message"], {"lab 01_transforms: " + kCrash,
                                                 "image vs reference", "the lab wrote no image"});
    CHECK(j["status"] == "error");
}

TEST_CASE("github-classroom results.json: pass only at full marks") {
    GradeRun run;
    LabResult lab;
    lab.lab = "00_pipeline";
    lab.checks = {check("00_pipeline", "triangle", "image", "image vs reference", 4, 4, true, ""),
                  check("00_pipeline", "spin", "unit", "unit spin(v)", 1, 1, true, "")};
    run.labs = {lab};
    json j = json::parse(grading::github_classroom_results_json(run));
    check_shape(j);
    check_against_model(j, run);
    CHECK(j["status"] == "pass");
    for (const json& t : j["tests"]) CHECK(t["status"] == "pass");

    // One case of a hundred wrong: 0.99 of the point, a failed test and run.
    run.labs[0].checks[1] =
        check("00_pipeline", "spin", "unit", "unit spin(v)", 0.99, 1, false, "Observed: 99/100");
    j = json::parse(grading::github_classroom_results_json(run));
    check_shape(j);
    check_against_model(j, run);
    CHECK(j["status"] == "fail");
    CHECK(test_named(j, "00_pipeline / spin")["status"] == "fail");
    CHECK(test_named(j, "00_pipeline / triangle")["status"] == "pass");
}

TEST_CASE("github-classroom results.json: tenths add up to course's total as the reporter adds") {
    // 30 checkpoints of 0.1 and 0.2 points: doubles that do not add exactly.
    GradeRun run;
    LabResult lab;
    lab.lab = "01_transforms";
    for (int i = 0; i < 30; ++i)
        lab.checks.push_back(check("01_transforms", "c" + std::to_string(i), "unit", "unit f(v)",
                                   i % 2 ? 0.1 : 0.2, 0.3, false, "Observed: some cases wrong"));
    run.labs = {lab};
    const json j = json::parse(grading::github_classroom_results_json(run));
    check_shape(j);
    check_against_model(j, run);
    CHECK(run.score() == doctest::Approx(4.5));
    CHECK(std::fabs(reporter_total(j) - run.score()) < 1e-9);
}

TEST_CASE("github-classroom results.json: course grade --format writes it beside the reports") {
    const std::string dir = fw::test::out_dir() + "/written";
    fs::remove_all(dir);
    const GradeRun run = fixture_run();
    grading::write_reports(run, dir, {grading::ResultsFormat::GitHubClassroom, ""});
    CHECK(fw::test::read_text(dir + "/results.json") ==
          grading::github_classroom_results_json(run));
    for (const char* file : {"summary.txt", "junit.xml", "index.html"})
        CHECK_MESSAGE(fs::exists(dir + "/" + file), file);
    // --results puts it elsewhere, making its folder.
    const std::string elsewhere = dir + "/elsewhere/results.json";
    grading::write_reports(run, dir, {grading::ResultsFormat::GitHubClassroom, elsewhere});
    check_shape(json::parse(fw::test::read_text(elsewhere)));
    fw::test::remove_when_passed(dir);
}

TEST_CASE("github-classroom results.json: within one environment variable however large") {
    // Every lab of the course at once, each checkpoint failed with a long
    // Observed line: its base64 still fits one environment string.
    GradeRun run;
    for (int l = 0; l < 11; ++l) {
        LabResult lab;
        lab.lab = std::to_string(l) + "_lab";
        for (int c = 0; c < 20; ++c)
            lab.checks.push_back(check(lab.lab, "checkpoint_" + std::to_string(c), "probe",
                                       "probe (256, 256) colour", 0, 1, false,
                                       "Observed: " + std::string(5000, 'x') + "\n"));
        run.labs.push_back(lab);
    }
    const std::string text = grading::github_classroom_results_json(run);
    INFO("bytes: " << text.size());
    CHECK(text.size() <= grading::kGitHubClassroomLimit);
    CHECK((text.size() + 2) / 3 * 4 + std::string("LAB10_RESULTS=").size() + 1 <
          kEnvironmentString);
    const json j = json::parse(text);
    check_shape(j);
    check_against_model(j, run);
    const std::string message = j["tests"][0]["message"];
    fw::test::check_mentions(message, {"probe (256, 256) colour", "more bytes cut here"});
}
