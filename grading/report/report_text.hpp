// Text handling shared by the report writers (reports.cpp: summary.txt,
// results.json, junit.xml; report_html.cpp: index.html). A check's output
// comes from a child running student code, so it may hold anything: bytes
// that are not UTF-8, terminal escapes, "<" and "&". Every report cleans it
// through these functions before writing it.
#pragma once

#include <string>
#include <vector>

#include "grading/report/reports.hpp"
#include "grading/results/results.hpp"

namespace grading::report {

// `text` as valid UTF-8 that XML 1.0 accepts: a byte that does not start a
// well-formed sequence becomes U+FFFD; control characters other than tab,
// newline and carriage return are dropped ("Char ::= #x9 | #xA | #xD |
// [#x20-#xD7FF] | [#xE000-#xFFFD] | [#x10000-#x10FFFF]", XML 1.0 section 2.2),
// and terminal colour sequences with them.
std::string clean_text(const std::string& text);

// clean_text(), then & < > " ' as character references: safe in XML and HTML
// alike, in element content and in quoted attribute values.
std::string escape_markup(const std::string& text);

// clean_text(), cut to about `cap` bytes (on a UTF-8 character boundary)
// with a line saying how many more bytes were cut and `why` ("results.json
// must stay under 1 MB"); as it is when it fits.
std::string cut_text(const std::string& text, size_t cap, const std::string& why);

// The first non-empty line of `text`, without surrounding blanks.
std::string first_line(const std::string& text);

// A score without needless decimals: 10, 2.5, 0.33.
std::string points(double value);
// `value` with `decimals` digits after the point, "%.*f".
std::string fixed(double value, int decimals);
// junit.xml (junit.cpp): one <testcase> per checkpoint, failures first.
std::string junit_xml(const GradeRun& run);

// `relative` (a path inside the output directory) joined to `out_dir`.
std::string in_dir(const std::string& out_dir, const std::string& relative);

// Writes `text` to `path` (`parts` one after another); throws fw::Error
// naming the path and the reason.
void write_text_file(const std::string& path, const std::string& text);
void write_text_file(const std::string& path, const std::vector<std::string>& parts);

// The sandbox's layers: in one line (summary.txt), and as a collapsed HTML
// list (index.html, and the overview in results.json).
std::string sandbox_line(const std::vector<SandboxLayer>& layers);
std::string sandbox_html(const std::vector<SandboxLayer>& layers);

// index.html, in parts to be written in turn (its pictures are megabytes,
// never copied into one string): reads the images the checks name (relative
// to out_dir), but those a lab's page_images already holds.
std::vector<std::string> html_report(const GradeRun& run, const std::string& out_dir);

// Every picture the page can show of `lab`'s checks, read from its files
// under out_dir into lab.page_images: for a lab judged while the next one
// renders, so that the page, made last, only puts them together.
void read_page_images(LabResult& lab, const std::string& out_dir);

// index.html's style sheet (the text of its <style> block, without the
// images), which the class's page (`course grade-class`) shares.
const char* report_style();

// The checks of `lab` that passed, and the checks of the whole run.
size_t passed_count(const LabResult& lab);
size_t check_count(const GradeRun& run);

// results.json in Gradescope's autograder format (gradescope_results.cpp):
// a test per checkpoint, pictures of what failed within kResultsLimit; a
// hidden checkpoint's test has the visibility `hidden_as`.
std::string gradescope_results_json(const GradeRun& run, const std::string& out_dir,
                                    HiddenAs hidden_as = HiddenAs::AfterDueDate);

}  // namespace grading::report
