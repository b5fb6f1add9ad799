#include "grading/class/class_page.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "framework/text.hpp"
#include "grading/class/class_findings.hpp"
#include "grading/class/class_page_parts.hpp"
#include "grading/report/report_text.hpp"

namespace grading::cls {

namespace fs = std::filesystem;
using report::escape_markup;
using report::points;

namespace {

// What the page adds to index.html's styles.
const char* const kClassStyle = R"(
section.part { margin: 1.5em 0; }
section.part > h2 { margin-bottom: 0.4em; }
table.labs caption { text-align: left; font-weight: 600; padding: 0.3em 0; }
table.labs th, table.labs td { vertical-align: top; }
table.labs pre { margin: 0; }
svg.histogram { max-width: 100%; height: auto; background: #fff; border: 1px solid #ddd; }
img.frame { width: 128px; image-rendering: pixelated; border: 1px solid #ccc; display: block; }
nav ul { margin: 0.3em 0; }
)";

std::string duration(double seconds) {
    const long s = std::lround(seconds);
    return s >= 60 ? std::to_string(s / 60) + " min " + std::to_string(s % 60) + " s"
                   : points(seconds) + " s";
}

// The run in a paragraph: submissions, students, labs and the grading time.
std::string summary_html(const std::vector<ClassRow>& rows,
                         const std::vector<std::pair<std::string, std::string>>& labs,
                         double seconds) {
    double students = 0;
    size_t fresh = 0;
    const ClassRow* slowest = nullptr;
    for (const ClassRow& r : rows) {
        students += students_of(r);
        fresh += r.graded_any();
        if (!slowest || r.seconds > slowest->seconds) slowest = &r;
    }
    std::vector<std::string> ids;
    for (const auto& [id, dir] : labs) ids.push_back(id);
    std::string h = "<p>" + std::to_string(rows.size()) +
                    (rows.size() == 1 ? " submission" : " submissions") + " (" + points(students) +
                    (students == 1 ? " student" : " students") + "), " +
                    (labs.size() == 1 ? "lab " : "labs ") + escape_markup(fw::join(ids, ", ")) +
                    ". Grading took " + duration(seconds) + ": " + std::to_string(fresh) +
                    " graded in this run, " + std::to_string(rows.size() - fresh) +
                    " unchanged since an earlier run";
    if (slowest && slowest->graded_any())
        h += "; the slowest, " + escape_markup(slowest->submission.key) + ", took " +
             duration(slowest->seconds);
    return h + ".</p>\n";
}

std::string nav_html() {
    return "<nav aria-label=\"Parts of this page\"><ul>\n"
           "<li><a href=\"#scores\">Scores</a></li>\n"
           "<li><a href=\"#checkpoints\">Checkpoints, the most failed first</a></li>\n"
           "<li><a href=\"#mistakes\">Named mistakes</a></li>\n"
           "<li><a href=\"#attention\">Submissions to look at</a></li>\n"
           "</ul></nav>\n";
}

// A lab's scores, one a student, rounded as grades.csv writes them.
std::vector<double> lab_scores(const std::vector<ClassRow>& rows, const std::string& lab,
                               double& max) {
    std::vector<double> scores;
    max = 0;
    for (const ClassRow& r : rows) {
        const auto g = r.labs.find(lab);
        if (g == r.labs.end()) continue;
        max = std::max(max, g->second.max_score);
        const double s = std::round(g->second.score * 100) / 100;
        for (int i = 0; i < int(students_of(r)); ++i) scores.push_back(s);
    }
    return scores;
}

std::string scores_html(const std::vector<ClassRow>& rows,
                        const std::vector<std::pair<std::string, std::string>>& labs) {
    std::ostringstream h;
    h << "<section class=\"part\" id=\"scores\">\n<h2>Scores</h2>\n";
    for (size_t i = 0; i < labs.size(); ++i) {
        const std::string& lab = labs[i].first;
        double max = 0;
        std::vector<double> scores = lab_scores(rows, lab, max);
        h << "<h3>" << escape_markup(lab) << "</h3>\n";
        if (scores.empty() || max <= 0) {
            h << "<p>No scores for this lab.</p>\n";
            continue;
        }
        std::sort(scores.begin(), scores.end());
        double sum = 0;
        for (double s : scores) sum += s;
        const size_t n = scores.size();
        const double median = n % 2 ? scores[n / 2] : (scores[n / 2 - 1] + scores[n / 2]) / 2;
        h << "<p>" << n << (n == 1 ? " student" : " students") << " of " << points(max)
          << " points: mean " << points(sum / double(n)) << ", median " << points(median)
          << ", lowest " << points(scores.front()) << ", highest " << points(scores.back())
          << ".</p>\n"
          << histogram_html(histogram(scores, max), lab, "hist-" + std::to_string(i));
    }
    h << "</section>\n";
    return h.str();
}

std::string rates_html(const ClassFindings& f,
                       const std::vector<std::pair<std::string, std::string>>& labs) {
    std::ostringstream h;
    h << "<section class=\"part\" id=\"checkpoints\">\n<h2>Checkpoints, the most failed "
         "first</h2>\n<p>Per lab, the students whose lab ran (built and graded, whether or not it "
         "finished) who passed or failed each checkpoint, the highest failure rate first.</p>\n";
    for (const auto& [lab, dir] : labs) {
        h << "<h3>" << escape_markup(lab) << "</h3>\n";
        const auto found = f.rates.find(lab);
        if (found == f.rates.end() || found->second.empty()) {
            h << "<p>No report of this lab to count from.</p>\n";
            continue;
        }
        h << "<table class=\"labs\">\n<caption>Checkpoints of " << escape_markup(lab) << " ("
          << points(f.rated.at(lab)) << " students)</caption>\n"
          << "<tr><th scope=\"col\">checkpoint</th><th scope=\"col\">failed</th><th "
             "scope=\"col\">passed</th><th scope=\"col\">failure rate</th></tr>\n";
        for (const CheckpointRate& r : found->second) {
            const double all = r.passed + r.failed;
            h << "<tr><th scope=\"row\">" << escape_markup(r.checkpoint)
              << (r.hidden ? "<span class=\"tag\">hidden</span>" : "") << "</th><td class=\"num\">"
              << points(r.failed) << "</td><td class=\"num\">" << points(r.passed)
              << "</td><td class=\"num\">"
              << (all > 0 ? std::to_string(std::lround(100 * r.failed / all)) + "%" : "-")
              << "</td></tr>\n";
        }
        h << "</table>\n";
    }
    h << "</section>\n";
    return h.str();
}

}  // namespace

void write_class_page(const fs::path& out, const std::vector<ClassRow>& rows,
                      const std::vector<std::pair<std::string, std::string>>& labs,
                      double seconds) {
    const ClassFindings findings = read_findings(out, rows, labs);
    std::ostringstream h;
    h << "<!DOCTYPE html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n"
      << "<title>Class report: " << rows.size()
      << (rows.size() == 1 ? " submission" : " submissions") << "</title>\n<style>"
      << report::report_style() << kClassStyle << "</style>\n</head>\n<body>\n<main>\n"
      << "<h1>Class report</h1>\n"
      << summary_html(rows, labs, seconds) << nav_html() << scores_html(rows, labs)
      << rates_html(findings, labs) << mistakes_html(out, rows, findings)
      << attention_html(rows, labs) << "</main>\n</body>\n</html>\n";
    const fs::path file = out / "class.html", partial = out / "class.html.part";
    report::write_text_file(partial.string(), h.str());
    fs::rename(partial, file);
}

}  // namespace grading::cls
