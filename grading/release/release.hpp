// `course release`: the student version of the repository (docs/contract.md, `course
// release`). The text transformations are pure functions of a file's text, so
// they are tested without files; release_tree() applies them to a tree.
//
// Release markers (grading/diagnosis/solution_blocks.hpp, which judging reads
// too): a solution block's student version is its STUDENT lines.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

#include "grading/diagnosis/solution_blocks.hpp"
#include "grading/judge/checks.hpp"

namespace grading {

// What `course release` writes besides the student version of the tree.
struct ReleaseOptions {
    // --github-classroom: kGitHubClassroomWorkflow, GitHub Classroom's
    // autograding of the released labs (github_classroom.cpp).
    bool github_classroom = false;
};

// `course release OUT`: the student version of source_root() in OUT
// (release_tree.cpp); the exit status as every `course` command's.
int release_command(const std::string& out_dir, const ReleaseOptions& options = {});

// GitHub Classroom's workflow in the student repository: on a push, in a
// Debian 12 container, scripts/setup.sh builds lab and course (the Debian
// packages and the compiler cache kept between runs); one step per lab,
// whose id is its runner id, grades it with `course grade --format
// github-classroom` and outputs its results.json in base64; and GitHub
// Classroom's reporter reads them all. Throws fw::Error when `labs` is empty
// or two labs would have the same runner id.
constexpr const char* kGitHubClassroomWorkflow = ".github/workflows/classroom.yml";
std::string github_classroom_workflow(const std::vector<LabData>& labs);
// A lab's runner id: "lab" and its folder's number ("00_pipeline": "lab00"),
// else the letters and digits of its name, lower case.
std::string classroom_runner(const LabData& lab);

// A checkpoints file (framework/checkpoints.hpp) without its hidden
// checkpoints. The text is cut rather than rewritten, so the remaining
// entries keep their layout and comments; the comment lines directly above a
// hidden entry (no blank line between) describe it and go with it. What the
// student's copy keeps of them is a top-level "hidden": {"checkpoints": N,
// "points": P}, so that its reports can say what the autograder adds. The
// result is parsed back and must hold exactly that, else fw::Error.
struct VisibleCheckpoints {
    std::string text;
    std::vector<std::string> dropped;  // names of the hidden checkpoints, in file order
    double hidden_points = 0.0;        // the points of their checks
};
VisibleCheckpoints drop_hidden_checkpoints(const std::string& text, const std::string& path);

// What release_tree() did, for the summary `course release` prints.
struct ReleaseSummary {
    std::size_t files = 0;
    std::vector<std::pair<std::string, int>> blocks;  // file -> blocks removed
    std::vector<std::pair<std::string, std::vector<std::string>>>
        hidden;                                    // checkpoints file -> names
    std::vector<std::string> references_left_out;  // hidden checkpoints' reference files
    std::vector<std::string> missing;              // tracked by git but absent from the tree
    std::vector<std::string> untracked;            // not tracked by git: never released
    std::size_t staff_only = 0;                    // staff files left out (is_staff_only)
    std::vector<std::pair<std::string, std::size_t>> cases;  // cases.json written -> bytes
    std::vector<std::string>
        starting;                    // starting.json written (grading/diagnosis/starting_code.hpp)
    std::size_t classroom_labs = 0;  // labs in kGitHubClassroomWorkflow, when written
};

// The recorded unit cases a release writes: at most this many random cases
// per unit check (the autograder draws fresh ones), from this seed.
constexpr unsigned kCasesSeed = 1;
constexpr int kCasesPerCheck = 50;

// The project's files under `source`, relative: in a git checkout, those git
// tracks and, apart, the untracked ones git does not ignore; elsewhere every
// file outside build*/, .git/ and .cache/, all counted as tracked.
struct ProjectFiles {
    std::vector<std::string> tracked, untracked;
};
ProjectFiles project_file_lists(const std::string& source);
// Both lists in one, sorted.
std::vector<std::string> project_files(const std::string& source);

// Whether the staff file `rel` stays out of the student repository: the
// course's own tests and benchmarks, the unit checks' references
// (labs/NN_name/grading/), the solution's records
// (labs/NN_name/reference/*.record.json), CI, the staff README (the student README,
// docs/student/README.md, takes its place), the staff's guide (docs/staff.md),
// docs/performance.md and docs/cluster/.
bool is_staff_only(const std::string& rel);
constexpr const char* kStudentReadme = "docs/student/README.md";

// A project file's whole text; throws fw::Error naming it when unreadable.
std::string read_file(const std::filesystem::path& path);

// Throws fw::UsageError unless `dir` does not exist or is an empty directory:
// `course release` and `course gradescope` write only into a new folder.
void require_new_output_dir(const std::filesystem::path& dir);

// Copies `from` to `to`, making `to`'s folders: a link as a link, a file with
// its mode. Throws fw::Error naming the paths.
void copy_entry(const std::filesystem::path& from, const std::filesystem::path& to);

// The modes of what course writes into a folder it makes: a script (0755)
// and any other file (0644).
constexpr std::filesystem::perms kExecutable =
    std::filesystem::perms::owner_all | std::filesystem::perms::group_read |
    std::filesystem::perms::group_exec | std::filesystem::perms::others_read |
    std::filesystem::perms::others_exec;
constexpr std::filesystem::perms kReadable =
    std::filesystem::perms::owner_read | std::filesystem::perms::owner_write |
    std::filesystem::perms::group_read | std::filesystem::perms::others_read;

// Writes `text` to `path` with `mode`, making its folders. Throws fw::Error
// naming the path.
void write_file(const std::filesystem::path& path, const std::string& text,
                std::filesystem::perms mode);

// Writes the student version of `source` into `out` (which must not exist or
// be empty), keeping file modes. Every file is transformed and checked before
// anything is written: a marker error leaves `out` untouched.
ReleaseSummary release_tree(const std::string& source, const std::string& out,
                            const ReleaseOptions& options = {});

}  // namespace grading
