// PrairieLearn's results.json (docs/contract.md, PrairieLearn's results.json),
// from the per-checkpoint model Gradescope's results.json is written from
// (by_checkpoint.hpp). PrairieLearn shows every test to the student and has
// no per-test visibility, so a hidden checkpoint is listed with its name and
// points (the score tells them anyway) and nothing of its checks.
#include "grading/report/prairielearn_results.hpp"

#include <algorithm>
#include <limits>
#include <nlohmann/json.hpp>

#include "framework/error.hpp"
#include "grading/report/by_checkpoint.hpp"
#include "grading/report/report_text.hpp"
#include "grading/report/reports.hpp"

namespace grading {

namespace {

using nlohmann::ordered_json;

constexpr const char* kHidden =
    "Hidden checkpoint: its checks, and why it failed, are not shown to students.";

// `text`, cleaned, and cut to about `cap` bytes with a line saying so.
std::string capped(const std::string& text, size_t cap) {
    return report::cut_text(text, cap, "results.json must stay under 1 MB");
}

bool hidden(const CheckpointResult& cp) { return cp.visibility == Visibility::Hidden; }

// The checks of a checkpoint by title, as its description.
std::string check_titles(const CheckpointResult& cp) {
    std::string text;
    for (const CheckResult* c : cp.checks) text += (text.empty() ? "" : "; ") + c->title;
    return "Checks: " + text;
}

// One test: the checkpoint's points; when visible, what failed first (the
// message), every check with Expected and Observed (the output) and, when it
// failed, its pictures as long as the budget lasts.
ordered_json checkpoint_test(const LabResult& lab, const CheckpointResult& cp,
                             Thumbnails& thumbnails, size_t cap) {
    std::string description = "Hidden checkpoint", message = kHidden, output;
    ordered_json images = ordered_json::array();
    if (!hidden(cp)) {
        description = check_titles(cp);
        message = checkpoint_failure(lab, cp);
        output = checkpoint_text(lab, cp);
        bool left_out = false;
        for (const Thumbnails::Picture& p : thumbnails.for_checkpoint(cp, &left_out))
            images.push_back({{"label", p.label}, {"url", p.uri}});
        if (left_out)
            output +=
                "(No pictures here: results.json must stay under 1 MB, and the checkpoints "
                "above took its room for pictures.)\n";
    }
    ordered_json test;
    test["name"] = report::clean_text(lab.lab + " / " + cp.checkpoint);
    test["description"] = capped(description, cap);
    test["points"] = cp.score;
    test["max_points"] = cp.max_score;
    test["message"] = capped(message, cap);
    test["output"] = capped(output, cap);
    test["images"] = images;
    return test;
}

// The lab table and the total.
std::string overview(const GradeRun& run, size_t passed, size_t checkpoints) {
    return lab_table(run) + "\nTotal: " + report::points(run.score()) + "/" +
           report::points(run.max_score()) + " points, " + std::to_string(passed) + " of " +
           std::to_string(checkpoints) + " checkpoints passed.\n";
}

// Why a lab's child did not finish normally, with the end of its log.
std::string lab_logs(const GradeRun& run) {
    std::string text;
    for (const LabResult& lab : run.labs)
        if (!lab.status.ok())
            text += (text.empty() ? "" : "\n") + lab.lab + ": " + lab.status.text() + "\n" +
                    (lab.log.empty() ? "(no output)\n" : lab.log + "\n");
    return text;
}

std::string results_json(const GradeRun& run, Thumbnails& thumbnails, size_t cap) {
    ordered_json tests = ordered_json::array();
    size_t passed = 0;
    for (const LabResult& lab : run.labs)
        for (const CheckpointResult& cp : by_checkpoint(lab)) {
            passed += cp.passed ? 1 : 0;
            tests.push_back(checkpoint_test(lab, cp, thumbnails, cap));
        }
    const double max = run.max_score();
    ordered_json results;
    results["gradable"] = true;
    results["score"] = max > 0 ? std::clamp(run.score() / max, 0.0, 1.0) : 0.0;
    results["message"] = capped(overview(run, passed, tests.size()), cap);
    // Only what did not finish normally: the sandbox's layers are in the
    // grading job's log (summary.txt), not in what the student reads.
    results["output"] = capped(lab_logs(run), cap);
    results["tests"] = tests;
    return results.dump(2) + "\n";
}

}  // namespace

std::string prairielearn_results_json(const GradeRun& run, const std::string& out_dir) {
    // Text that alone would break the limit (a child's error repeated in every
    // check, say) is cut: each text field to its share of half the limit.
    size_t cap = std::numeric_limits<size_t>::max();
    Thumbnails thumbnails(out_dir, 0);
    if (results_json(run, thumbnails, cap).size() > kResultsLimit) {
        size_t fields = 2;
        for (const LabResult& lab : run.labs) fields += 3 * by_checkpoint(lab).size();
        cap = kResultsLimit / (2 * fields);
    }
    return within_limit(kResultsLimit, thumbnails,
                        [&] { return results_json(run, thumbnails, cap); });
}

std::string prairielearn_not_gradable_json(const std::string& reason, const std::string& log) {
    const size_t cap = kResultsLimit / 4;
    ordered_json results;
    results["gradable"] = false;
    results["score"] = 0.0;
    results["message"] = capped(
        reason + "\nThis submission was not graded: it counts neither points nor an attempt.\n",
        cap);
    results["output"] = capped(log, cap);
    results["format_errors"] = ordered_json::array({capped(reason, cap)});
    results["tests"] = ordered_json::array();
    return results.dump(2) + "\n";
}

}  // namespace grading
