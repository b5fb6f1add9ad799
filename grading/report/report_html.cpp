// index.html: the report a person reads. One self-contained file (inline CSS,
// images as data: URIs, no script, nothing fetched) so that it can be mailed,
// archived by CI or opened from a Gradescope download as it is.
//
// At the top: the total, a table of labs (a failed lab's status says why:
// shader error, crash, timeout) and links to every failed checkpoint with
// its cause. Then one section per lab: its score and status (with the
// child's log when it did not finish normally), and a card per checkpoint,
// failed ones first: the rendered, expected and difference images, then its
// checks, Observed beside Expected.
#include <algorithm>
#include <cstdint>
#include <numeric>
#include <sstream>
#include <vector>

#include "grading/report/by_checkpoint.hpp"
#include "grading/report/page_images.hpp"
#include "grading/report/report_text.hpp"

namespace grading::report {

namespace {

const char* const kStyle = R"(
body { font: 15px/1.4 system-ui, sans-serif; margin: 0 auto; max-width: 1400px; padding: 1em 2em;
       color: #222; background: #fafafa; }
h1 { margin: 0.2em 0; }
h2 { margin: 0; font-size: 1.3em; }
h3 { margin: 0 0 0.4em; font-size: 1.05em; font-weight: 600; }
a { color: #1a56a8; }
table.labs { border-collapse: collapse; margin: 0.8em 0; }
table.labs th, table.labs td { padding: 0.25em 0.9em; border-bottom: 1px solid #ddd; text-align: left; }
table.labs td.num { text-align: right; font-variant-numeric: tabular-nums; }
.total { font-size: 1.25em; font-weight: 600; padding: 0.4em 0.8em; border-radius: 6px; display: inline-block; }
.total.pass { background: #dff3e3; } .total.fail { background: #fbe3e1; }
.failed-list li { margin: 0.15em 0; }
section.lab { margin: 1.5em 0; padding: 0.8em 1em; background: #fff; border: 1px solid #ddd;
              border-radius: 8px; }
section.lab.fail { border-color: #e0a8a3; }
section.lab > header { display: flex; gap: 1em; align-items: baseline; flex-wrap: wrap;
                       margin-bottom: 0.6em; }
.status.ok { color: #17692c; } .status.bad { color: #b3261e; font-weight: 600; }
article.check { margin: 0.6em 0; padding: 0.6em 0.8em; border-radius: 6px; border: 1px solid #ddd;
                border-left: 6px solid #237a3b; }
article.check.fail { border-left-color: #c62828; background: #fff6f5; }
.badge { display: inline-block; min-width: 3em; text-align: center; border-radius: 4px;
         padding: 0 0.4em; margin-right: 0.4em; color: #fff; font-size: 0.85em; }
.badge.pass { background: #237a3b; } .badge.fail { background: #c62828; }
.points { float: right; font-variant-numeric: tabular-nums; }
.tag { display: inline-block; font-size: 0.8em; font-weight: normal; color: #555;
       border: 1px solid #bbb; border-radius: 4px; padding: 0 0.35em; margin-left: 0.4em; }
pre { margin: 0.3em 0; padding: 0.5em; background: #f2f2f2; border-radius: 4px;
      white-space: pre-wrap; word-break: break-word; font-size: 0.9em; }
.images { display: flex; gap: 1em; flex-wrap: wrap; margin-top: 0.5em; }
figure { margin: 0; flex: 1 1 300px; max-width: 440px; }
.images.small figure { flex: 0 1 200px; }
.shot { width: 100%; background: #888 no-repeat center / contain; image-rendering: pixelated;
        border: 1px solid #ccc; }
figcaption { font-size: 0.85em; color: #555; text-align: center; }
table.checks { border-collapse: collapse; width: 100%; margin-top: 0.5em; table-layout: fixed; }
table.checks th, table.checks td { text-align: left; vertical-align: top; padding: 0.2em 0.5em;
                                   border-top: 1px solid #e4e4e4; }
table.checks th { font-weight: 600; font-size: 0.9em; color: #555; }
table.checks th:nth-child(1) { width: 3.5em; }
table.checks th:nth-child(2) { width: 20%; }
table.checks tr.fail td:nth-child(4) pre { background: #fde8e6; }
table.checks pre { white-space: pre-wrap; overflow-wrap: anywhere; }
pre.note { background: none; padding: 0; color: #555; }
.visually-hidden { position: absolute; width: 1px; height: 1px; margin: -1px; padding: 0;
                   overflow: hidden; clip: rect(0 0 0 0); white-space: nowrap; border: 0; }
.missing { padding: 2em 0.5em; border: 1px dashed #c62828; color: #b3261e; font-size: 0.9em;
           text-align: center; word-break: break-all; }
)";

std::string card_id(size_t lab, size_t checkpoint) {
    return "cp-" + std::to_string(lab) + "-" + std::to_string(checkpoint);
}

// A check's output in three parts: what comes before "Expected:" (a note
// such as a unit check's seed), the Expected part and the Observed part
// (with what follows it). An output without those words is all observed.
struct OutputParts {
    std::string note, expected, observed;
};
OutputParts split_output(const std::string& output) {
    const size_t e = output.find("Expected:"), o = output.find("Observed:");
    if (e == std::string::npos || o == std::string::npos || o < e) return {"", "", output};
    auto trim = [](std::string t) {
        while (!t.empty() && (t.back() == '\n' || t.back() == ' ')) t.pop_back();
        return t.substr(std::min(t.size(), t.find_first_not_of(' ')));
    };
    return {trim(output.substr(0, e)), trim(output.substr(e + 9, o - e - 9)),
            trim(output.substr(o + 9))};
}

std::string check_row(const LabResult& lab, const CheckResult& c) {
    const char* state = c.passed ? "pass" : "fail";
    const OutputParts parts = split_output(check_output(lab, c));
    std::ostringstream h;
    h << "<tr class=\"" << state << "\"><td><span class=\"badge " << state << "\">"
      << (c.passed ? "PASS" : "FAIL") << "</span></td><td>" << escape_markup(c.title)
      << "<span class=\"tag\">" << name_of(c.kind) << "</span><br><small>" << points(c.score)
      << " / " << points(c.max_score) << " points</small>";
    if (!parts.note.empty()) h << "<pre class=\"note\">" << escape_markup(parts.note) << "</pre>";
    h << "</td><td><pre>" << escape_markup(parts.expected) << "</pre></td><td><pre>"
      << escape_markup(parts.observed) << "</pre></td></tr>\n";
    return h.str();
}

// A checkpoint's card: its pictures first, then its checks, failures first,
// Observed beside Expected.
std::string card_html(const LabResult& lab, const CheckpointResult& cp, const std::string& id,
                      ImageTable& images) {
    std::ostringstream h;
    const char* state = cp.passed ? "pass" : "fail";
    h << "<article class=\"check " << state << "\" id=\"" << id << "\">\n<h3><span class=\"badge "
      << state << "\">" << (cp.passed ? "PASS" : "FAIL") << "</span>"
      << escape_markup(cp.checkpoint);
    if (cp.visibility == Visibility::Hidden) h << "<span class=\"tag\">hidden</span>";
    h << "<span class=\"points\">" << points(cp.score) << " / " << points(cp.max_score)
      << " points</span></h3>\n";
    const bool has_image =
        !cp.expected.empty() || !cp.difference.empty() ||
        std::any_of(cp.checks.begin(), cp.checks.end(),
                    [](const CheckResult* c) { return c->kind == CheckKind::Image; });
    if (has_image)
        h << "<div class=\"images\">" << images.figure("rendered", cp.rendered)
          << images.figure("expected", cp.expected)
          << images.figure("difference", cp.difference,
                           cp.rendered.empty() || cp.expected.empty() || cp.image_failed
                               ? ""
                               : "no pixel differs beyond the tolerance")
          << "</div>\n";
    else if (!cp.rendered.empty())  // probes and stats: the frame they were read from
        h << "<div class=\"images small\">" << images.figure("rendered", cp.rendered) << "</div>\n";
    h << "<table class=\"checks\">\n<tr><th><span "
         "class=\"visually-hidden\">result</span></th><th>check</th><th>Expected</th><th>Observed</"
         "th>"
         "</tr>\n";
    for (const CheckResult* c : cp.checks) h << check_row(lab, *c);
    h << "</table>\n</article>\n";
    return h.str();
}

// The points of a lab's hidden checkpoints (Visibility::Hidden): `course
// release` leaves them out of the student's copy, and Gradescope shows them
// after the due date (`course gradescope --hidden-as`).
double hidden_points(const LabResult& lab) {
    double hidden = 0;
    for (const CheckpointResult& cp : by_checkpoint(lab))
        if (cp.visibility == Visibility::Hidden) hidden += cp.max_score;
    return hidden;
}

std::string lab_html(const LabResult& lab, size_t index, ImageTable& images) {
    const bool ok = lab.status.ok();
    std::ostringstream h;
    h << "<section class=\"lab" << (lab.passed() ? "" : " fail") << "\" id=\"lab-" << index
      << "\">\n<header><h2>" << escape_markup(lab.lab) << "</h2><span>" << points(lab.score())
      << " / " << points(lab.max_score()) << " points"
      << (hidden_points(lab) > 0 ? " (" + points(hidden_points(lab)) + " hidden)" : "")
      << "</span><span class=\"status " << (ok ? "ok" : "bad") << "\">"
      << escape_markup(lab.status.text()) << "</span><span>" << points(lab.seconds)
      << " s</span></header>\n";
    if (!ok)
        h << "<details open><summary>The lab's output (last lines)</summary><pre>"
          << escape_markup(lab.log.empty() ? "(no output)" : lab.log) << "</pre></details>\n";
    const std::vector<CheckpointResult> checkpoints = by_checkpoint(lab);
    if (checkpoints.empty()) h << "<p>This lab has no checks.</p>\n";

    // Failed checkpoints first; otherwise in the order of the checkpoints file.
    std::vector<size_t> order(checkpoints.size());
    std::iota(order.begin(), order.end(), 0);
    std::stable_partition(order.begin(), order.end(),
                          [&](size_t i) { return !checkpoints[i].passed; });
    for (size_t i : order) h << card_html(lab, checkpoints[i], card_id(index, i), images);
    h << "</section>\n";
    return h.str();
}

// A sentence on the hidden points of the run; empty when it has none.
// The state checks a student's copy leaves out (it holds no solution's
// record of the draws), which the autograder judges.
std::string state_left_out_html(const GradeRun& run) {
    const GradeRun::LeftOut state = run.state_left_out();
    if (state.checkpoints == 0) return "";
    return "<p class=\"hidden-points\">On submission the autograder also judges " +
           std::to_string(state.checkpoints) +
           (state.checkpoints == 1 ? " state check (" : " state checks (") + points(state.points) +
           " points) that this copy leaves out: the state of your draws against the solution's "
           "record of them.</p>\n";
}

std::string hidden_html(const GradeRun& run) {
    double hidden = 0, scored = 0;
    size_t checkpoints = 0;
    for (const LabResult& lab : run.labs)
        for (const CheckpointResult& cp : by_checkpoint(lab))
            if (cp.visibility == Visibility::Hidden) {
                ++checkpoints;
                hidden += cp.max_score;
                scored += cp.score;
            }
    if (checkpoints == 0) {
        const GradeRun::LeftOut left_out = run.hidden_left_out();
        if (left_out.checkpoints == 0) return "";
        return "<p class=\"hidden-points\">On submission the autograder adds " +
               std::to_string(left_out.checkpoints) +
               (left_out.checkpoints == 1 ? " hidden checkpoint (" : " hidden checkpoints (") +
               points(left_out.points) + " points) to the " + points(run.max_score()) +
               " points here: they test the same code with other parameters.</p>\n";
    }
    return "<p class=\"hidden-points\">" + points(hidden) + " of the " + points(run.max_score()) +
           " points are hidden (" + std::to_string(checkpoints) +
           (checkpoints == 1 ? " hidden checkpoint" : " hidden checkpoints") + ", " +
           points(scored) +
           " points scored there): students do not see these checkpoints, "
           "and their copy of the course does not grade them.</p>\n";
}

std::string overview_html(const GradeRun& run) {
    std::ostringstream h;
    size_t total = 0, passed = 0;
    std::string failed;
    std::ostringstream rows;
    for (size_t li = 0; li < run.labs.size(); ++li) {
        const LabResult& lab = run.labs[li];
        size_t lab_passed = 0;
        for (const CheckResult& c : lab.checks) lab_passed += c.passed;
        const std::vector<CheckpointResult> checkpoints = by_checkpoint(lab);
        for (size_t ci = 0; ci < checkpoints.size(); ++ci) {
            const CheckpointResult& cp = checkpoints[ci];
            if (cp.passed) continue;
            failed += "<li><a href=\"#" + card_id(li, ci) + "\">" +
                      escape_markup(lab.lab + " / " + cp.checkpoint) +
                      "</a>: " + escape_markup(checkpoint_failure(lab, cp)) + "</li>\n";
        }
        total += lab.checks.size();
        passed += lab_passed;
        const bool ok = lab.status.ok();
        rows << "<tr><td><a href=\"#lab-" << li << "\">" << escape_markup(lab.lab)
             << "</a></td><td class=\"num\">" << points(lab.score()) << " / "
             << points(lab.max_score()) << "</td><td class=\"num\">" << lab_passed << " / "
             << lab.checks.size() << "</td><td class=\"status " << (ok ? "ok" : "bad") << "\">"
             << escape_markup(first_line(lab.status.text())) << "</td><td class=\"num\">"
             << points(lab.seconds) << "</td></tr>\n";
    }
    h << "<p class=\"total " << (run.passed() ? "pass" : "fail") << "\">" << points(run.score())
      << " / " << points(run.max_score()) << " points &middot; " << passed << " of " << total
      << " checks passed &middot; " << run.labs.size() << (run.labs.size() == 1 ? " lab" : " labs")
      << (run.backend.empty() ? "" : " &middot; backend " + escape_markup(run.backend))
      << " &middot; " << points(run.seconds) << " s</p>\n"
      << hidden_html(run) << state_left_out_html(run) << sandbox_html(run.sandbox);
    if (run.labs.empty()) {
        h << "<p>No labs were graded.</p>\n";
        return h.str();
    }
    h << "<table class=\"labs\">\n<tr><th>lab</th><th>score</th><th>checks passed</th>"
         "<th>status</th><th>seconds</th></tr>\n"
      << rows.str() << "</table>\n";
    if (!failed.empty())
        h << "<h2>Failed checkpoints</h2>\n<ul class=\"failed-list\">\n" << failed << "</ul>\n";
    return h.str();
}

}  // namespace

const char* report_style() { return kStyle; }

std::string sandbox_line(const std::vector<SandboxLayer>& layers) {
    std::string line;
    for (const SandboxLayer& layer : layers)
        line += (line.empty() ? "" : "; ") + std::string(layer.active ? "on: " : "off: ") +
                layer.name + " (" + layer.detail + ")";
    return line;
}

std::string sandbox_html(const std::vector<SandboxLayer>& layers) {
    if (layers.empty()) return "";
    size_t active = 0;
    std::string items;
    for (const SandboxLayer& layer : layers) {
        active += layer.active;
        items += "<li>" + std::string(layer.active ? "" : "<em>not used:</em> ") + "<strong>" +
                 escape_markup(layer.name) + "</strong>: " + escape_markup(layer.detail) +
                 "</li>\n";
    }
    return "<details class=\"sandbox\"><summary>Sandbox: " + std::to_string(active) + " of " +
           std::to_string(layers.size()) + " layers active</summary>\n<ul>\n" + items +
           "</ul></details>\n";
}

std::vector<std::string> html_report(const GradeRun& run, const std::string& out_dir) {
    // The body first: it decides which images the <style> block must hold.
    ImageTable images(out_dir);
    size_t uris = 0;
    for (const LabResult& lab : run.labs)
        for (const auto& [relative, image] : lab.page_images) uris += image.uri.size();
    images.reserve(uris);
    std::ostringstream body;
    body << "<main>\n<h1>Grading report</h1>\n" << overview_html(run);
    for (size_t li = 0; li < run.labs.size(); ++li) {
        images.read_ahead(&run.labs[li].page_images);
        body << lab_html(run.labs[li], li, images);
    }
    body << "</main>\n</body>\n</html>\n";
    return {
        "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
        "<title>Grading report: " +
            points(run.score()) + " / " + points(run.max_score()) + "</title>\n<style>" + kStyle,
        images.take_css(), "</style>\n</head>\n<body>\n", body.str()};
}

}  // namespace grading::report
