// The reports of a grading run (docs/contract.md, Reports), all written into
// the output directory: summary.txt (the table also printed), results.json
// (Gradescope's format, PrairieLearn's or GitHub Classroom's), junit.xml, and
// a self-contained index.html.
#pragma once

#include <cstddef>
#include <string>

#include "grading/results/results.hpp"

namespace grading {

// What results.json holds (`course grade --format`) and where it goes (`--results`).
enum class ResultsFormat { Gradescope, PrairieLearn, GitHubClassroom };
// How Gradescope shows the tests of hidden checkpoints (`--hidden-as`): one
// of its results.json's visibility values. after_due_date (the default) and
// after_published keep the student's total score in view; hidden (never
// shown) hides the total as well, which Gradescope does whenever a test is
// hidden.
enum class HiddenAs { AfterDueDate, AfterPublished, Hidden };
const char* name_of(HiddenAs hidden_as);  // "after_due_date", "after_published", "hidden"

struct ResultsFile {
    ResultsFormat format = ResultsFormat::Gradescope;
    std::string path;                             // empty: results.json in the output directory
    HiddenAs hidden_as = HiddenAs::AfterDueDate;  // Gradescope's format only
};

// The score table: one line per lab with its score and status; every failed
// check with why in a line, what most likely went wrong and, for a unit
// check, its first failing case; the total and what it means; and, with
// `sandbox`, the run's CPU seconds (where measured) and the sandbox's layers,
// a line each (summary.txt has them always, the terminal with `course grade
// --verbose`). The terminal shows the first
// `max_failed` failed checks and counts the rest (summary.txt: all).
std::string summary_table(const GradeRun& run, bool sandbox = true,
                          std::size_t max_failed = static_cast<std::size_t>(-1));

// Where the run's time went, one line per lab (LabTime) and the total, and
// the seconds the reports took (`course grade --verbose` prints it; no report
// holds it: its figures differ from run to run).
std::string time_table(const GradeRun& run, double reports_seconds);

// How many failed checks `course grade` prints without --verbose.
constexpr std::size_t kTerminalFailedChecks = 25;

// The first part of that table: a header and one line per lab (score, checks
// passed, status, seconds), without the failed checks or the total.
std::string lab_table(const GradeRun& run);

// Writes all four files; throws fw::Error naming a file that cannot be written.
void write_reports(const GradeRun& run, const std::string& out_dir,
                   const ResultsFile& results = {});

}  // namespace grading
