// GitHub Classroom's results.json (github_classroom_results.hpp). The
// reporter reads, of the run, "status" (fail or error fails its step) and
// "max_score" (a run without one adds nothing to the total), and of each
// test "name", "status", "score" (summed into the points Classroom records),
// "message" (printed for an error), "line_no" (printed after the name unless
// 0) and "test_code" (printed under the name when not empty); "version" and
// "filename" are there as the Classroom's own runners write them.
#include "grading/report/github_classroom_results.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "framework/error.hpp"
#include "grading/report/by_checkpoint.hpp"
#include "grading/report/report_text.hpp"

namespace grading {

namespace {

using nlohmann::ordered_json;

// A message longer than this is cut even when the file has room: the
// reporter's log shows it on one line.
constexpr size_t kMessageCap = 500;

const char* status_of(const LabResult& lab, const CheckpointResult& cp) {
    if (cp.passed) return "pass";
    return lab.status.ok() ? "fail" : "error";
}

std::string capped(const std::string& text, size_t cap) {
    return report::cut_text(text, cap, "results.json must stay under 64 KiB");
}

// A failed checkpoint's message: why its lab did not finish, if it did not,
// and its first failed check with the line that says why.
std::string message_of(const LabResult& lab, const CheckpointResult& cp) {
    if (cp.passed) return {};
    if (cp.visibility == Visibility::Hidden)
        return "Hidden checkpoint: its checks, and why it failed, are not shown to students.";
    const std::string failure = checkpoint_failure(lab, cp);
    if (lab.status.ok()) return failure;
    return "lab " + lab.lab + ": " + report::first_line(lab.status.text()) +
           (failure.empty() ? "" : "; " + failure);
}

ordered_json checkpoint_test(const LabResult& lab, const CheckpointResult& cp, size_t cap) {
    ordered_json test;
    test["name"] = capped(lab.lab + " / " + cp.checkpoint, cap);
    test["status"] = status_of(lab, cp);
    test["score"] = cp.score;
    test["message"] = capped(message_of(lab, cp), cap);
    // Under a failed test's name in the reporter's log: how to see its checks.
    test["test_code"] = cp.passed ? "" : capped("scripts/grade.sh " + lab.lab, cap);
    test["filename"] = "";
    test["line_no"] = 0;
    return test;
}

std::string results_json(const GradeRun& run, size_t cap) {
    ordered_json tests = ordered_json::array();
    bool error = false;
    for (const LabResult& lab : run.labs) {
        error = error || !lab.status.ok();
        for (const CheckpointResult& cp : by_checkpoint(lab))
            tests.push_back(checkpoint_test(lab, cp, cap));
    }
    ordered_json results;
    results["version"] = 1;
    results["status"] = run.passed() ? "pass" : error ? "error" : "fail";
    results["max_score"] = run.max_score();
    results["tests"] = tests;
    // Compact: it travels base64-encoded in an environment variable.
    return results.dump() + "\n";
}

}  // namespace

std::string github_classroom_results_json(const GradeRun& run) {
    std::string json = results_json(run, kMessageCap);
    if (json.size() <= kGitHubClassroomLimit) return json;
    // Each test's text to an equal share of half the limit.
    size_t tests = 0;
    for (const LabResult& lab : run.labs) tests += by_checkpoint(lab).size();
    json = results_json(run, kGitHubClassroomLimit / (2 * 3 * std::max<size_t>(tests, 1)));
    if (json.size() > kGitHubClassroomLimit)
        throw fw::Error("GitHub Classroom's results.json of " + std::to_string(tests) +
                        " checkpoints does not fit in " +
                        std::to_string(kGitHubClassroomLimit / 1024) +
                        " KiB; grade fewer labs in one run");
    return json;
}

}  // namespace grading
