// The text reports of a grading run: summary.txt (the score table `course
// grade` also prints) and junit.xml (for CI dashboards). results.json is in
// gradescope_results.cpp (Gradescope's autograder format),
// prairielearn_results.cpp (PrairieLearn's) or github_classroom_results.cpp
// (GitHub Classroom's); index.html is in report_html.cpp.
#include "grading/report/reports.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <future>
#include <nlohmann/json.hpp>
#include <sstream>
#include <vector>

#include "framework/error.hpp"
#include "framework/text.hpp"
#include "grading/report/by_checkpoint.hpp"
#include "grading/report/github_classroom_results.hpp"
#include "grading/report/prairielearn_results.hpp"
#include "grading/report/report_text.hpp"

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

}  // namespace

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

std::string cut_text(const std::string& text, size_t cap, const std::string& why) {
    std::string clean = clean_text(text);
    if (clean.size() <= cap) return clean;
    size_t end = cap;
    while (end > 0 && (static_cast<unsigned char>(clean[end]) & 0xC0) == 0x80) --end;
    const size_t cut = clean.size() - end;
    clean.resize(end);
    return clean + "\n[" + std::to_string(cut) + " more bytes cut here: " + why + "]\n";
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

std::string points(double value) { return fw::trimmed_decimals(value, 2); }

std::string in_dir(const std::string& out_dir, const std::string& relative) {
    std::filesystem::path path(relative);
    return path.is_absolute() ? relative : (std::filesystem::path(out_dir) / path).string();
}

void write_text_file(const std::string& path, const std::string& text) {
    write_text_file(path, std::vector<std::string>{text});
}

void write_text_file(const std::string& path, const std::vector<std::string>& parts) {
    std::ofstream file(path, std::ios::binary | std::ios::trunc);
    for (const std::string& text : parts)
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
             ascii(report::first_line(lab.status.text())), report::fixed(lab.seconds, 1)});
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

namespace report {
namespace {

// `text`'s lines, each after `prefix`, as plain ASCII.
std::string indented(const std::string& text, const std::string& prefix) {
    std::string out;
    std::istringstream in(ascii(text));
    for (std::string line; std::getline(in, line);)
        out += line.empty() ? "\n" : prefix + line + "\n";
    return out;
}

// A line per failed check (where, what, its points, why in a line), then
// what most likely went wrong and, for a unit check, its first failing case.
std::string failed_checks(const GradeRun& run, size_t max_failed) {
    std::string failed;
    size_t shown = 0, more = 0;
    for (const LabResult& lab : run.labs) {
        for (const CheckResult& c : lab.checks) {
            if (c.passed) continue;
            if (shown == max_failed) {
                ++more;
                continue;
            }
            ++shown;
            // The Observed line says what went wrong; the Expected line only
            // repeats the check.
            const std::string why = check_failure(lab, c);
            failed +=
                "  " +
                ascii(lab.lab + "/" + c.checkpoint + ": " + c.title + " (" + points(c.score) + "/" +
                      points(c.max_score) + " points)" + (why.empty() ? "" : " - " + why)) +
                "\n";
            failed += indented(c.diagnosis, "    ") + indented(c.first_case, "  ");
        }
    }
    if (more)
        failed += "  ... and " + std::to_string(more) + " more failed check" +
                  (more == 1 ? "" : "s") +
                  ": the report and summary.txt list them all (--verbose prints them here)\n";
    return failed.empty() ? "" : "\nFailed checks:\n" + failed;
}

// What the total means: the points of hidden checkpoints in it (a
// student's copy has none, so there it says nothing of them), and, when a
// check failed, how a starting copy scores.
std::string score_meaning(const GradeRun& run) {
    double hidden = 0.0;
    for (const LabResult& lab : run.labs)
        for (const CheckResult& c : lab.checks)
            if (c.visibility == Visibility::Hidden) hidden += c.max_score;
    const GradeRun::LeftOut left_out = run.hidden_left_out();
    std::string text;
    if (hidden > 0)
        text += points(rounded_points(hidden)) + " of these points are in hidden checkpoints: " +
                "a student's copy leaves them out, and they are graded on submission.\n";
    else if (left_out.checkpoints > 0)
        text += "On submission the autograder adds " + std::to_string(left_out.checkpoints) +
                " hidden checkpoint" + (left_out.checkpoints == 1 ? "" : "s") + " (" +
                points(left_out.points) + " points) to these: the same code with other " +
                "parameters.\n";
    const GradeRun::LeftOut state = run.state_left_out();
    if (state.checkpoints > 0)
        text += "On submission the autograder also judges " + std::to_string(state.checkpoints) +
                " state check" + (state.checkpoints == 1 ? "" : "s") + " (" + points(state.points) +
                " points) that this copy leaves out: the state of your draws against the "
                "solution's record of them, which this copy does not hold.\n";
    if (!run.passed())
        text +=
            "A check's points come when it passes; a unit check gives points in proportion "
            "to the cases it passes (to 0.1 point). A lab's starting copy scores low until "
            "its TODO parts are written.\n";
    return text;
}

}  // namespace
}  // namespace report

std::string summary_table(const GradeRun& run, bool sandbox, size_t max_failed) {
    using report::ascii;
    using report::points;
    size_t passed = 0;
    for (const LabResult& lab : run.labs) passed += report::passed_count(lab);
    std::string table = lab_table(run) + report::failed_checks(run, max_failed);
    const size_t labs = run.labs.size();
    table += "\nTotal: " + points(run.score()) + "/" + points(run.max_score()) + " points, " +
             std::to_string(passed) + " of " + std::to_string(report::check_count(run)) +
             " checks passed, " + std::to_string(labs) + (labs == 1 ? " lab, " : " labs, ") +
             report::fixed(run.seconds, 1) + " s" +
             (run.backend.empty() ? "" : ", backend " + ascii(run.backend)) + "\n";
    table += report::score_meaning(run);
    if (sandbox && run.course_cpu_seconds >= 0.0 && run.children_cpu_seconds >= 0.0)
        table += "CPU: " + report::fixed(run.course_cpu_seconds, 2) +
                 " s in course (judging, the report's images), " +
                 report::fixed(run.children_cpu_seconds, 2) +
                 " s in the labs' children (rendering)\n";
    if (sandbox && !run.sandbox.empty())
        table += "Sandbox: " + ascii(report::sandbox_line(run.sandbox)) + "\n";
    if (sandbox && !run.seed_from.empty())
        table += "Seed: " + std::to_string(run.seed) + " (" + ascii(run.seed_from) +
                 "), of the unit checks' random cases\n";
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
    // The page, the longest to make, made and written on a thread of its own
    // while the others are; all of them only read the run and the lab folders.
    std::future<void> html = std::async(std::launch::async, [&] {
        report::write_text_file(report::in_dir(out_dir, "index.html"),
                                report::html_report(run, out_dir));
    });
    report::write_text_file(report::in_dir(out_dir, "summary.txt"), summary_table(run));
    const std::string results_path =
        results.path.empty() ? report::in_dir(out_dir, "results.json") : results.path;
    if (results.format == ResultsFormat::PrairieLearn)
        report::write_text_file(results_path, prairielearn_results_json(run, out_dir));
    else if (results.format == ResultsFormat::GitHubClassroom)
        report::write_text_file(results_path, github_classroom_results_json(run));
    else
        report::write_text_file(results_path,
                                report::gradescope_results_json(run, out_dir, results.hidden_as));
    report::write_text_file(report::in_dir(out_dir, "junit.xml"), report::junit_xml(run));
    html.get();
}

}  // namespace grading
