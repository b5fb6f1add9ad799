// The autograder's side of `course gradescope` and `course prairielearn`: the
// folders each platform takes, and `course autograde`, which their scripts,
// run_autograder (grading/platforms/gradescope/) and grade.sh
// (grading/platforms/prairielearn/), call for each submission.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "grading/judge/checks.hpp"
#include "grading/report/reports.hpp"

namespace grading {

// `course gradescope OUT` and `course prairielearn OUT`: the folders each
// platform takes (gradescope/gradescope_folder.cpp,
// prairielearn/prairielearn_folder.cpp).
// `hidden_as` goes into run_autograder: how Gradescope shows the tests of
// hidden checkpoints (reports.hpp, HiddenAs); `labs` (names, empty: all)
// makes the folder an assignment of those labs only: run_autograder grades
// them, and takes only their files from a submission. An unknown lab, or one
// without a student part, is a fw::UsageError.
int gradescope_command(const std::string& out_dir, HiddenAs hidden_as = HiddenAs::AfterDueDate,
                       const std::vector<std::string>& labs = {});
int prairielearn_command(const std::string& out_dir);

// The files students edit (those with solution blocks, staff files such as
// the mistake suite left out: is_staff_only), each with its
// student version (`course release`), in the order of `files` (paths
// relative to `source`, from project_files()). Throws fw::Error listing
// every file whose markers are wrong, or when no file has a solution block.
using StudentFiles = std::vector<std::pair<std::string, std::string>>;
StudentFiles student_files(const std::filesystem::path& source,
                           const std::vector<std::string>& files);

// Writes DEST/student_files.txt (a path a line) and
// DEST/student_versions/PATH: the files `course autograde` takes from a
// submission, and what it grades in place of one the submission lacks.
void write_student_files(const StudentFiles& students, const std::filesystem::path& dest);

// Writes DEST/solution_shaders/NN_name/FILE: the course's own text (from
// `source`) of each student file shaders/NN_name/FILE of `students`, which
// `course grade` puts in place of the student's to tell which file is wrong
// (grading/diagnosis/file_isolation.hpp) where the student's replace the
// course's. Returns how many it wrote.
size_t write_solution_shaders(const StudentFiles& students, const std::filesystem::path& source,
                              const std::filesystem::path& dest);

// Throws fw::Error unless SOURCE/FOLDER/NAME, a script an autograder folder
// is written with, exists.
void require_template(const std::filesystem::path& source, const std::string& folder,
                      const std::string& name);

// `course autograde [LAB...] [--layout L] [--root DIR] [--source DIR] [--data DIR]
// [--user USER] [--timeout SEC] [--hidden-as V]` (autograde.cpp): grades a submission and
// writes ROOT/results/results.json, complete whatever the submission does;
// exits 0 unless its own arguments are wrong. The layouts:
// - gradescope: ROOT (/autograder) holds source/ (the autograder folder,
//   built, with the checkpoints and references), submission/ and results/;
// - prairielearn: ROOT (/grade) holds student/ and results/; SOURCE (/course)
//   is the built student version of the course in the grader's image, and
//   DATA the checkpoints and references (from serverFilesCourse).
struct AutogradeOptions {
    std::vector<std::string> labs;  // empty: every lab
    // --layout: the platform whose folders and results.json are used.
    ResultsFormat layout = ResultsFormat::Gradescope;
    std::string root;              // empty: /autograder or /grade
    std::string source;            // prairielearn; empty: /course
    std::string data;              // prairielearn; required
    std::string user = "student";  // builds and runs the submission (when root)
    std::string timeout = "60";    // seconds each lab may run; passed on to `course grade`
    // gradescope: the visibility of a hidden checkpoint's test (run_autograder
    // passes what `course gradescope --hidden-as` wrote into it).
    HiddenAs hidden_as = HiddenAs::AfterDueDate;
};
int autograde_command(const AutogradeOptions& options);

// The reports of a run in which no lab could be graded (the submission does
// not build, or `course grade` itself failed), written into `out_dir`: every
// check of the labs (all when `labs` is empty), failed with `reason`, so
// Gradescope's results.json still lists every test with its points; its
// overall output is `reason` and the last 200 lines of `log_file` ("":
// none). PrairieLearn's results.json says instead that the submission was
// not gradable (prairielearn.hpp). The summary table goes to stdout unless
// `print` is false. Returns 1, the exit status of a failed grading.
int not_graded_command(const std::string& reason, const std::string& log_file,
                       const std::string& out_dir, ResultsFormat format = ResultsFormat::Gradescope,
                       const std::vector<std::string>& labs = {},
                       HiddenAs hidden_as = HiddenAs::AfterDueDate, bool print = true);

// The result of a lab that no child ran (its checks parsed): every check
// failed, `reason` its status and `log` its log.
LabResult not_run_lab(const LabData& lab, const std::string& reason, const std::string& log,
                      const std::string& out_dir);

// The last `lines` lines of the file at `path`, taken from at most its last
// MiB; throws fw::Error when it cannot be read.
std::string log_tail(const std::string& path, int lines);

}  // namespace grading
