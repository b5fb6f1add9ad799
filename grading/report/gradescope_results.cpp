// results.json in Gradescope's autograder format: a test per checkpoint,
// with small pictures of what failed within kResultsLimit.
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/error.hpp"
#include "grading/report/by_checkpoint.hpp"
#include "grading/report/report_text.hpp"

namespace grading {

const char* name_of(HiddenAs hidden_as) {
    switch (hidden_as) {
        case HiddenAs::AfterPublished:
            return "after_published";
        case HiddenAs::Hidden:
            return "hidden";
        case HiddenAs::AfterDueDate:
            break;
    }
    return "after_due_date";
}

namespace report {

namespace {

std::string html_pre(const std::string& text) { return "<pre>" + escape_markup(text) + "</pre>"; }

// A checkpoint's output on Gradescope (html): its pictures when it failed,
// then each check, failures first, with Expected and Observed.
std::string checkpoint_html(const LabResult& lab, const CheckpointResult& cp,
                            Thumbnails& thumbnails) {
    std::string h;
    if (!lab.status.ok())
        h += "<p><strong>" + escape_markup("lab " + lab.lab + ": " + lab.status.text()) +
             "</strong></p>\n";
    bool left_out = false;
    const std::vector<Thumbnails::Picture> pictures = thumbnails.for_checkpoint(cp, &left_out);
    if (!pictures.empty()) {
        h += "<table><tr>";
        for (const Thumbnails::Picture& p : pictures)
            h += "<td><img src=\"" + p.uri + "\" alt=\"" + p.label + "\" title=\"" + p.label +
                 "\"></td>";
        h += "</tr><tr>";
        for (const Thumbnails::Picture& p : pictures) h += "<td>" + p.label + "</td>";
        h += "</tr></table>\n";
    } else if (left_out) {
        h += "<p>(No pictures here: results.json stays under 1 MB, and earlier checkpoints "
             "took its room for pictures. index.html, from course grade, shows them all.)</p>\n";
    }
    for (const CheckResult* c : cp.checks) {
        h += "<p><strong>" + std::string(c->passed ? "PASS" : "FAIL") + "</strong> " +
             escape_markup(c->title) + " (" + points(c->score) + " / " + points(c->max_score) +
             " points)</p>\n";
        if (!c->output.empty()) h += html_pre(c->output) + "\n";
    }
    return h;
}

// The top-level output: the per-lab table, and why a lab did not finish.
std::string overview_html(const GradeRun& run) {
    size_t total = check_count(run), passed = 0;
    std::string rows;
    for (const LabResult& lab : run.labs) {
        passed += passed_count(lab);
        rows += "<tr><td>" + escape_markup(lab.lab) + "</td><td>" + points(lab.score()) + " / " +
                points(lab.max_score()) + "</td><td>" + std::to_string(passed_count(lab)) + " / " +
                std::to_string(lab.checks.size()) + "</td><td>" +
                escape_markup(first_line(lab.status.text())) + "</td></tr>\n";
    }
    std::string h = "<p><strong>" + points(run.score()) + " / " + points(run.max_score()) +
                    " points</strong>; " + std::to_string(passed) + " of " + std::to_string(total) +
                    " checks passed.</p>\n" + sandbox_html(run.sandbox);
    if (!run.labs.empty())
        h += "<table><tr><th>lab</th><th>score</th><th>checks passed</th><th>status</th></tr>\n" +
             rows + "</table>\n";
    for (const LabResult& lab : run.labs)
        if (!lab.status.ok())
            h += "<p><strong>" + escape_markup(lab.lab + ": " + lab.status.text()) +
                 "</strong></p>\n" + html_pre(lab.log.empty() ? "(no output)" : lab.log) + "\n";
    return h;
}

std::string results_json(const GradeRun& run, Thumbnails& thumbnails, HiddenAs hidden_as) {
    nlohmann::ordered_json tests = nlohmann::ordered_json::array();
    nlohmann::ordered_json labs = nlohmann::ordered_json::array();
    for (size_t li = 0; li < run.labs.size(); ++li) {
        const LabResult& lab = run.labs[li];
        const std::vector<CheckpointResult> checkpoints = by_checkpoint(lab);
        for (size_t ci = 0; ci < checkpoints.size(); ++ci) {
            const CheckpointResult& cp = checkpoints[ci];
            nlohmann::ordered_json checks = nlohmann::ordered_json::array();
            for (const CheckResult* c : cp.checks)
                checks.push_back({{"title", clean_text(c->title)},
                                  {"kind", name_of(c->kind)},
                                  {"passed", c->passed},
                                  {"score", c->score},
                                  {"max_score", c->max_score}});
            nlohmann::ordered_json test;
            test["name"] = clean_text(lab.lab + " / " + cp.checkpoint);
            test["number"] = lab_number(lab, li) + "." + std::to_string(ci + 1);
            test["score"] = cp.score;
            test["max_score"] = cp.max_score;
            test["status"] = cp.passed ? "passed" : "failed";
            test["output"] = checkpoint_html(lab, cp, thumbnails);
            test["output_format"] = "html";
            // Gradescope's visible, or for a hidden checkpoint `hidden_as`.
            test["visibility"] =
                cp.visibility == Visibility::Hidden ? name_of(hidden_as) : "visible";
            test["extra_data"] = {{"lab", clean_text(lab.lab)},
                                  {"checkpoint", clean_text(cp.checkpoint)},
                                  {"checks", checks}};
            tests.push_back(test);
        }
        labs.push_back({{"lab", clean_text(lab.lab)},
                        {"status", clean_text(lab.status.text())},
                        {"score", lab.score()},
                        {"max_score", lab.max_score()},
                        {"seconds", std::round(lab.seconds * 1000.0) / 1000.0}});
    }
    nlohmann::ordered_json results;
    // Gradescope's specification has no top-level max_score: the total
    // possible is the sum of the tests', and extra_data says it.
    results["score"] = run.score();
    results["execution_time"] = std::round(run.seconds * 1000.0) / 1000.0;
    results["output"] = overview_html(run);
    results["output_format"] = "html";
    nlohmann::ordered_json sandbox = nlohmann::ordered_json::array();
    for (const SandboxLayer& layer : run.sandbox)
        sandbox.push_back({{"layer", clean_text(layer.name)},
                           {"active", layer.active},
                           {"detail", clean_text(layer.detail)}});
    results["extra_data"] = {{"max_score", run.max_score()},
                             {"backend", clean_text(run.backend)},
                             {"sandbox", sandbox},
                             {"labs", labs}};
    results["tests"] = tests;
    // Compact: indentation took a fifth of the file, room the pictures need
    // when every lab fails (a student's starting copy).
    return results.dump() + "\n";
}

}  // namespace

std::string gradescope_results_json(const GradeRun& run, const std::string& out_dir,
                                    HiddenAs hidden_as) {
    // Pictures, checkpoint by checkpoint in order, in what the text leaves of the limit.
    Thumbnails thumbnails(out_dir, 0);
    return within_limit(kResultsLimit, thumbnails,
                        [&] { return results_json(run, thumbnails, hidden_as); });
}

}  // namespace report
}  // namespace grading
