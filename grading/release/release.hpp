// `course release`: the student version of the repository (docs/contract.md, `course
// release`). The text transformations are pure functions of a file's text, so
// they are tested without files; release_tree() applies them to a tree.
//
// Release markers, in C++ and GLSL alike: a line whose text is exactly
// `// BEGIN SOLUTION` opens a solution block and `// END SOLUTION` closes it.
// The student version drops the block; each line inside it of the form
// `<indent>// STUDENT: <code>` becomes `<indent><code>`, so both versions
// compile. Blocks do not nest.
#pragma once

#include <cstddef>
#include <filesystem>
#include <string>
#include <vector>

namespace grading {

// `course release OUT`: the student version of source_root() in OUT
// (release_tree.cpp); the exit status as every `course` command's.
int release_command(const std::string& out_dir);

// Whether a file's name marks it as C++ or GLSL, the files that may hold
// release markers: .cpp .hpp .h .vert .frag .geom .tesc .tese .comp .glsl.
bool is_marked_source(const std::string& path);

// One solution block: the 1-based lines of its BEGIN and END markers.
struct SolutionBlock {
    int begin_line = 0;
    int end_line = 0;
};

// The blocks of `text`, checked: every BEGIN has its END, no block nests in
// another, a STUDENT line sits inside a block and a marker is spelt exactly.
// Throws fw::Error "PATH:LINE: what is wrong; how to fix it" (`path` only
// names the text in messages).
std::vector<SolutionBlock> solution_blocks(const std::string& text, const std::string& path);

// The student version of `text`: every block replaced by its STUDENT lines.
// Line endings (LF or CRLF) are kept; text without markers comes back as is.
std::string student_text(const std::string& text, const std::string& path);

// `text` with only block `index` (in solution_blocks order) in its student
// version and every other block, markers included, as written.
std::string student_text_of_block(const std::string& text, const std::string& path,
                                  std::size_t index);

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
// (labs/NN_name/grading/), CI and the staff README (the student README,
// docs/student/README.md, takes its place).
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
ReleaseSummary release_tree(const std::string& source, const std::string& out);

}  // namespace grading
