// The text reports of a grading run: summary.txt (the score table `course
// grade` also prints), results.json (Gradescope's autograder format, or
// PrairieLearn's from prairielearn.cpp) and junit.xml (for CI dashboards).
// index.html is in report_html.cpp.
#include "grading/reports.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <vector>

#include "framework/error.hpp"
#include "framework/text.hpp"
#include "grading/by_checkpoint.hpp"
#include "grading/prairielearn.hpp"
#include "grading/report_text.hpp"

namespace grading {
namespace report {

namespace {

// The code point of the UTF-8 sequence starting at text[i] and its length in
// bytes; length 0 when the bytes there are not a well-formed sequence
// (overlong forms and UTF-16 surrogates included).
size_t decode_utf8(const std::string& text, size_t i, char32_t& cp) {
    const auto byte = [&](size_t k) { return static_cast<unsigned char>(text[k]); };
    size_t length = 0;
    char32_t smallest = 0;
    if (byte(i) < 0x80) {
        cp = byte(i);
        return 1;
    } else if ((byte(i) & 0xE0) == 0xC0) {
        length = 2, cp = byte(i) & 0x1F, smallest = 0x80;
    } else if ((byte(i) & 0xF0) == 0xE0) {
        length = 3, cp = byte(i) & 0x0F, smallest = 0x800;
    } else if ((byte(i) & 0xF8) == 0xF0) {
        length = 4, cp = byte(i) & 0x07, smallest = 0x10000;
    } else {
        return 0;
    }
    if (i + length > text.size()) return 0;
    for (size_t k = i + 1; k < i + length; ++k) {
        if ((byte(k) & 0xC0) != 0x80) return 0;
        cp = (cp << 6) | (byte(k) & 0x3F);
    }
    if (cp < smallest || cp > 0x10FFFF || (cp >= 0xD800 && cp <= 0xDFFF)) return 0;
    return length;
}

// XML 1.0's Char production, less DEL and the C1 controls, which it
// discourages and which no report wants.
bool allowed_char(char32_t cp) {
    if (cp == 0x9 || cp == 0xA || cp == 0xD) return true;
    if (cp < 0x20 || (cp >= 0x7F && cp <= 0x9F)) return false;
    return cp <= 0xD7FF || (cp >= 0xE000 && cp <= 0xFFFD) || cp >= 0x10000;
}

// summary.txt is plain ASCII: a character outside it prints as '?', a tab
// as a space.
std::string ascii(const std::string& text) {
    std::string out;
    for (unsigned char c : clean_text(text)) {
        if (c == '\t')
            out += ' ';
        else if (c == '\r')
            continue;
        else if (c < 0x80)
            out += static_cast<char>(c);
        else if (c >= 0xC0)
            out += '?';  // first byte of a sequence; the rest are skipped
    }
    return out;
}

std::string fixed(double value, int decimals) {
    char text[64];
    std::snprintf(text, sizeof text, "%.*f", decimals, value);
    return text;
}

size_t passed_count(const LabResult& lab) {
    return static_cast<size_t>(std::count_if(lab.checks.begin(), lab.checks.end(),
                                             [](const CheckResult& c) { return c.passed; }));
}

size_t check_count(const GradeRun& run) {
    size_t n = 0;
    for (const LabResult& lab : run.labs) n += lab.checks.size();
    return n;
}

// Gradescope's visibility values are visible, hidden, after_due_date and
// after_published; a checkpoint is either visible or hidden.
std::string gradescope_visibility(const LabResult& lab, const CheckResult& check) {
    if (check.visibility == "visible" || check.visibility == "hidden") return check.visibility;
    throw fw::Error("check " + lab.lab + "/" + check.checkpoint + " \"" + check.title +
                    "\" has visibility \"" + check.visibility +
                    "\"; a checkpoint's visibility is visible or hidden");
}

std::string html_pre(const std::string& text) { return "<pre>" + escape_markup(text) + "</pre>"; }

// A checkpoint's output on Gradescope (html): its pictures when it failed,
// then each check, failures first, with Expected and Observed.
std::string checkpoint_html(const LabResult& lab, const CheckpointResult& cp,
                            Thumbnails& thumbnails) {
    std::string h;
    if (lab.status != "ok")
        h +=
            "<p><strong>" + escape_markup("lab " + lab.lab + ": " + lab.status) + "</strong></p>\n";
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
                escape_markup(first_line(lab.status)) + "</td></tr>\n";
    }
    std::string h = "<p><strong>" + points(run.score()) + " / " + points(run.max_score()) +
                    " points</strong>; " + std::to_string(passed) + " of " + std::to_string(total) +
                    " checks passed.</p>\n" + sandbox_html(run.sandbox);
    if (!run.labs.empty())
        h += "<table><tr><th>lab</th><th>score</th><th>checks passed</th><th>status</th></tr>\n" +
             rows + "</table>\n";
    for (const LabResult& lab : run.labs)
        if (lab.status != "ok")
            h += "<p><strong>" + escape_markup(lab.lab + ": " + lab.status) + "</strong></p>\n" +
                 html_pre(lab.log.empty() ? "(no output)" : lab.log) + "\n";
    return h;
}

std::string results_json(const GradeRun& run, const std::string& out_dir, size_t picture_budget) {
    nlohmann::ordered_json tests = nlohmann::ordered_json::array();
    Thumbnails thumbnails(out_dir, picture_budget);
    nlohmann::ordered_json labs = nlohmann::ordered_json::array();
    for (size_t li = 0; li < run.labs.size(); ++li) {
        const LabResult& lab = run.labs[li];
        const std::vector<CheckpointResult> checkpoints = by_checkpoint(lab);
        for (size_t ci = 0; ci < checkpoints.size(); ++ci) {
            const CheckpointResult& cp = checkpoints[ci];
            nlohmann::ordered_json checks = nlohmann::ordered_json::array();
            for (const CheckResult* c : cp.checks)
                checks.push_back({{"title", clean_text(c->title)},
                                  {"kind", c->kind},
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
            test["visibility"] = gradescope_visibility(lab, *cp.checks.front());
            test["extra_data"] = {{"lab", clean_text(lab.lab)},
                                  {"checkpoint", clean_text(cp.checkpoint)},
                                  {"checks", checks}};
            tests.push_back(test);
        }
        labs.push_back({{"lab", clean_text(lab.lab)},
                        {"status", clean_text(lab.status)},
                        {"score", lab.score()},
                        {"max_score", lab.max_score()},
                        {"seconds", std::round(lab.seconds * 1000.0) / 1000.0}});
    }
    nlohmann::ordered_json results;
    results["score"] = run.score();
    results["max_score"] = run.max_score();
    results["execution_time"] = std::round(run.seconds * 1000.0) / 1000.0;
    results["output"] = overview_html(run);
    results["output_format"] = "html";
    nlohmann::ordered_json sandbox = nlohmann::ordered_json::array();
    for (const SandboxLayer& layer : run.sandbox)
        sandbox.push_back({{"layer", clean_text(layer.name)},
                           {"active", layer.active},
                           {"detail", clean_text(layer.detail)}});
    results["extra_data"] = {
        {"backend", clean_text(run.backend)}, {"sandbox", sandbox}, {"labs", labs}};
    results["tests"] = tests;
    return results.dump(2) + "\n";
}

// Pictures, checkpoint by checkpoint in order, in what the text leaves of the limit.
std::string results_json(const GradeRun& run, const std::string& out_dir) {
    return within_limit(kResultsLimit,
                        [&](size_t budget) { return results_json(run, out_dir, budget); });
}

// One <testcase> per checkpoint (classname the lab, name the checkpoint),
// its checks' text inside, failures first.
std::string junit_xml(const GradeRun& run) {
    size_t cases = 0, failures = 0;
    std::vector<std::vector<CheckpointResult>> labs;
    for (const LabResult& lab : run.labs) {
        labs.push_back(by_checkpoint(lab));
        cases += labs.back().size();
        for (const CheckpointResult& cp : labs.back()) failures += cp.passed ? 0 : 1;
    }
    std::ostringstream x;
    x << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<testsuites name=\"course grade\" tests=\"" << cases << "\" failures=\"" << failures
      << "\" time=\"" << fixed(run.seconds, 3) << "\">\n";
    for (size_t li = 0; li < run.labs.size(); ++li) {
        const LabResult& lab = run.labs[li];
        const std::string suite = escape_markup(lab.lab);
        size_t lab_failures = 0;
        for (const CheckpointResult& cp : labs[li]) lab_failures += cp.passed ? 0 : 1;
        x << "  <testsuite name=\"" << suite << "\" tests=\"" << labs[li].size() << "\" failures=\""
          << lab_failures << "\" errors=\"0\" skipped=\"0\" time=\"" << fixed(lab.seconds, 3)
          << "\">\n";
        for (const CheckpointResult& cp : labs[li]) {
            x << "    <testcase classname=\"" << suite << "\" name=\""
              << escape_markup(cp.checkpoint) << "\">\n";
            const std::string text = checkpoint_text(lab, cp);
            if (cp.passed) {
                x << "      <system-out>" << escape_markup(text) << "</system-out>\n";
            } else {
                const std::string message = checkpoint_failure(lab, cp);
                std::string kinds;
                for (const CheckResult* c : cp.checks)
                    if (!c->passed && kinds.find(c->kind) == std::string::npos)
                        kinds += (kinds.empty() ? "" : " ") + c->kind;
                x << "      <failure message=\""
                  << escape_markup(message.empty() ? "checkpoint failed" : message) << "\" type=\""
                  << escape_markup(kinds) << "\">" << escape_markup(text) << "</failure>\n";
            }
            x << "    </testcase>\n";
        }
        if (lab.status != "ok")
            x << "    <system-err>" << escape_markup(lab.status + "\n" + lab.log)
              << "</system-err>\n";
        x << "  </testsuite>\n";
    }
    x << "</testsuites>\n";
    return x.str();
}

}  // namespace

std::string clean_text(const std::string& text) {
    std::string out;
    out.reserve(text.size());
    for (size_t i = 0; i < text.size();) {
        char32_t cp = 0;
        size_t length = decode_utf8(text, i, cp);
        if (length == 0) {
            out += "\xEF\xBF\xBD";  // U+FFFD REPLACEMENT CHARACTER
            ++i;
            continue;
        }
        if (cp == 0x1B && i + 1 < text.size() && text[i + 1] == '[') {
            // A terminal colour or cursor sequence (ECMA-48 CSI: ESC [ parameters
            // final byte in @..~), as compilers print to terminals: dropped whole.
            i += 2;
            while (i < text.size() && !(text[i] >= '@' && text[i] <= '~')) ++i;
            i += i < text.size();
            continue;
        }
        if (allowed_char(cp)) out.append(text, i, length);
        i += length;
    }
    return out;
}

std::string escape_markup(const std::string& text) {
    std::string out;
    for (char c : clean_text(text)) {
        switch (c) {
            case '&':
                out += "&amp;";
                break;
            case '<':
                out += "&lt;";
                break;
            case '>':
                out += "&gt;";
                break;
            case '"':
                out += "&quot;";
                break;
            case '\'':
                out += "&#39;";
                break;
            default:
                out += c;
        }
    }
    return out;
}

std::string first_line(const std::string& text) {
    std::istringstream in(text);
    std::string line;
    while (std::getline(in, line)) {
        const size_t begin = line.find_first_not_of(" \t\r");
        if (begin == std::string::npos) continue;
        return line.substr(begin, line.find_last_not_of(" \t\r") - begin + 1);
    }
    return {};
}

std::string points(double value) {
    std::string text = fixed(value, 2);
    text.erase(text.find_last_not_of('0') + 1);
    if (text.back() == '.') text.pop_back();
    return text == "-0" ? "0" : text;
}

std::string in_dir(const std::string& out_dir, const std::string& relative) {
    std::filesystem::path path(relative);
    return path.is_absolute() ? relative : (std::filesystem::path(out_dir) / path).string();
}

void write_text_file(const std::string& path, const std::string& text) {
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    if (file) file << text;
    if (file) file.close();
    if (!file)
        throw fw::Error("cannot write the report " + path + ": " + std::strerror(errno) +
                        "; check that its directory exists and is writable, or pick another --out");
}

}  // namespace report

std::string lab_table(const GradeRun& run) {
    using report::ascii;
    using report::points;
    std::vector<std::array<std::string, 5>> rows{{"lab", "score", "checks", "status", "seconds"}};
    for (const LabResult& lab : run.labs)
        rows.push_back(
            {ascii(lab.lab), points(lab.score()) + "/" + points(lab.max_score()),
             std::to_string(report::passed_count(lab)) + "/" + std::to_string(lab.checks.size()),
             ascii(report::first_line(lab.status)), report::fixed(lab.seconds, 1)});
    std::array<size_t, 5> width{};
    for (const auto& row : rows)
        for (size_t i = 0; i < row.size(); ++i) width[i] = std::max(width[i], row[i].size());

    // Text columns align left, numbers right.
    const std::array<bool, 5> right{false, true, true, false, true};
    std::string table;
    for (const auto& row : rows) {
        std::array<std::string, 5> cells;
        for (size_t i = 0; i < row.size(); ++i) {
            const std::string pad(width[i] - row[i].size(), ' ');
            cells[i] = right[i] ? pad + row[i] : row[i] + pad;
        }
        const std::string line = fw::join(cells, "  ");
        table += line.substr(0, line.find_last_not_of(' ') + 1) + "\n";
    }
    if (run.labs.empty()) table += "(no labs were graded)\n";
    return table;
}

std::string summary_table(const GradeRun& run) {
    using report::ascii;
    using report::points;
    std::string table = lab_table(run);
    std::string failed;
    size_t passed = 0;
    for (const LabResult& lab : run.labs) {
        passed += report::passed_count(lab);
        for (const CheckResult& c : lab.checks) {
            if (c.passed) continue;
            // The Observed line says what went wrong; the Expected line only
            // repeats the check.
            const std::string why = check_failure(lab, c);
            failed += "  " +
                      ascii(lab.lab + "/" + c.checkpoint + ": " + c.title +
                            (why.empty() ? "" : " - " + why)) +
                      "\n";
        }
    }
    if (!failed.empty()) table += "\nFailed checks:\n" + failed;

    const size_t labs = run.labs.size();
    table += "\nTotal: " + points(run.score()) + "/" + points(run.max_score()) + " points, " +
             std::to_string(passed) + " of " + std::to_string(report::check_count(run)) +
             " checks passed, " + std::to_string(labs) + (labs == 1 ? " lab, " : " labs, ") +
             report::fixed(run.seconds, 1) + " s" +
             (run.backend.empty() ? "" : ", backend " + ascii(run.backend)) + "\n";
    if (!run.sandbox.empty())
        table += "Sandbox: " + ascii(report::sandbox_line(run.sandbox)) + "\n";
    return table;
}

void write_reports(const GradeRun& run, const std::string& out_dir, const ResultsFile& results) {
    std::error_code error;
    std::filesystem::create_directories(out_dir, error);
    if (error)
        throw fw::Error("cannot create the report directory " + out_dir + ": " + error.message() +
                        "; pick another --out");
    if (!results.path.empty()) {
        const std::filesystem::path parent = std::filesystem::path(results.path).parent_path();
        if (!parent.empty()) std::filesystem::create_directories(parent, error);
        if (error)
            throw fw::Error("cannot create the directory of --results " + results.path + ": " +
                            error.message());
    }
    report::write_text_file(report::in_dir(out_dir, "summary.txt"), summary_table(run));
    report::write_text_file(
        results.path.empty() ? report::in_dir(out_dir, "results.json") : results.path,
        results.format == ResultsFormat::PrairieLearn ? prairielearn_results_json(run, out_dir)
                                                      : report::results_json(run, out_dir));
    report::write_text_file(report::in_dir(out_dir, "junit.xml"), report::junit_xml(run));
    report::write_text_file(report::in_dir(out_dir, "index.html"),
                            report::html_report(run, out_dir));
}

}  // namespace grading
