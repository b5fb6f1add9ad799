// `course gradescope --out DIR` (docs/contract.md, `course gradescope`): the folder
// a course uploads to Gradescope as its autograder. It holds
// - the whole repository, solutions, hidden checkpoints and references
//   included (what `course grade` needs), without build folders or .git;
// - setup.sh and run_autograder at the top (from grading/platforms/gradescope/):
//   Gradescope runs setup.sh once, as root, to build its image, and
//   run_autograder (which runs `course autograde`) for each submission;
//   run_autograder's `hidden_as=` line holds `--hidden-as`, how Gradescope
//   shows the tests of hidden checkpoints;
// - student_files.txt: the files students edit (those with solution blocks),
//   and student_versions/<file>: their student versions (`course release`),
//   which `course autograde` grades in place of a file a submission lacks,
//   so that a solution is never graded as a student's work.
#include <sys/stat.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <utility>
#include <vector>

#include "framework/error.hpp"
#include "grading/platforms/autograder.hpp"
#include "grading/release/release.hpp"
#include "grading/run/repository.hpp"

namespace fs = std::filesystem;

namespace grading {

namespace {

// The scripts, in the repository and at the top of the folder.
constexpr const char* kTemplates = "grading/platforms/gradescope";
constexpr const char* kScripts[] = {"setup.sh", "run_autograder"};
constexpr const char* kStudentFiles = "student_files.txt";
constexpr const char* kStudentVersions = "student_versions";
// run_autograder's line that says how hidden checkpoints' tests are shown.
constexpr const char* kHiddenAsLine = "\nhidden_as=after_due_date\n";

// run_autograder's text, with `hidden_as` in its hidden_as= line.
std::string with_hidden_as(std::string text, const fs::path& from, HiddenAs hidden_as) {
    const size_t at = text.find(kHiddenAsLine);
    if (at == std::string::npos)
        throw fw::Error("'" + from.string() + "' has no line 'hidden_as=after_due_date', where " +
                        "course gradescope writes --hidden-as");
    return text.replace(at + 1, std::string(kHiddenAsLine).size() - 2,
                        std::string("hidden_as=") + name_of(hidden_as));
}

// What the folder will hold, read and checked before anything is written.
struct FolderPlan {
    std::vector<std::string> files;  // of the repository
    StudentFiles students;
    std::vector<std::string> missing;  // tracked, not in the tree
};

FolderPlan plan_folder(const fs::path& source) {
    for (const char* script : kScripts) require_template(source, kTemplates, script);
    FolderPlan plan;
    plan.files = project_files(source.string());
    for (const std::string& rel : plan.files)
        if (!fs::exists(fs::symlink_status(source / rel))) plan.missing.push_back(rel);
    plan.students = student_files(source, plan.files);
    return plan;
}

// Writes the folder; returns how many files of the repository it copied.
size_t write_folder(const FolderPlan& plan, const fs::path& source, const fs::path& dest,
                    HiddenAs hidden_as) {
    std::error_code ec;
    fs::create_directories(dest, ec);
    if (ec)
        throw fw::Error("cannot create output directory '" + dest.string() + "': " + ec.message());
    size_t copied = 0;
    for (const std::string& rel : plan.files) {
        if (std::count(plan.missing.begin(), plan.missing.end(), rel)) continue;
        copy_entry(source / rel, dest / rel);
        ++copied;
    }
    for (const char* script : kScripts) {
        const fs::path from = source / kTemplates / script;
        std::string text = read_file(from);
        if (std::string(script) == "run_autograder") text = with_hidden_as(text, from, hidden_as);
        write_file(dest / script, text, kExecutable);
    }
    write_student_files(plan.students, dest);
    return copied;
}

void print_folder(const FolderPlan& plan, const fs::path& source, size_t copied,
                  const std::string& out_dir, HiddenAs hidden_as) {
    std::printf("course gradescope: the autograder for %s\n", source.string().c_str());
    std::printf("  %zu files of the repository (solutions and hidden checkpoints included)\n",
                copied);
    for (const char* script : kScripts)
        std::printf("  %-48s from %s/%s\n", script, kTemplates, script);
    std::printf("  hidden checkpoints' tests shown on Gradescope: %s (--hidden-as)\n",
                name_of(hidden_as));
    std::printf("  %-48s %zu files students edit:\n", kStudentFiles, plan.students.size());
    for (const auto& [rel, text] : plan.students)
        std::printf("    %s (student version in %s/)\n", rel.c_str(), kStudentVersions);
    for (const std::string& rel : plan.missing)
        std::printf("  %-48s not copied: tracked by git but missing from the tree\n", rel.c_str());
    std::printf(
        "Zip the contents of %s (not the folder itself) and upload it to Gradescope as "
        "the autograder.\n",
        out_dir.c_str());
}

}  // namespace

void require_template(const fs::path& source, const std::string& folder, const std::string& name) {
    if (!fs::is_regular_file(source / folder / name))
        throw fw::Error("missing '" + (source / folder / name).string() +
                        "'; the autograder's scripts live in " + folder +
                        "/ of the repository (set LAB_ROOT to it)");
}

StudentFiles student_files(const fs::path& source, const std::vector<std::string>& files) {
    StudentFiles students;
    std::string errors;
    for (const std::string& rel : files) {
        const fs::path path = source / rel;
        if (!is_marked_source(rel) || is_staff_only(rel) ||
            !fs::is_regular_file(fs::symlink_status(path)))
            continue;
        try {
            const std::string text = read_file(path);
            if (!solution_blocks(text, rel).empty())
                students.emplace_back(rel, student_text(text, rel));
        } catch (const fw::Error& e) {
            errors += std::string("\n  ") + e.what();
        }
    }
    if (!errors.empty())
        throw fw::Error("the autograder was not written: fix these first:" + errors);
    if (students.empty())
        throw fw::Error("no file in '" + source.string() +
                        "' has a solution block, so a submission would have nothing to "
                        "replace; mark the student parts (docs/conventions.md, Student parts)");
    return students;
}

void write_student_files(const StudentFiles& students, const fs::path& dest) {
    std::string list;
    for (const auto& [rel, text] : students) {
        list += rel + "\n";
        write_file(dest / kStudentVersions / rel, text, kReadable);
    }
    write_file(dest / kStudentFiles, list, kReadable);
}

int gradescope_command(const std::string& out_dir, HiddenAs hidden_as) {
    const fs::path source(source_root()), dest(out_dir);
    require_new_output_dir(dest);
    const FolderPlan plan = plan_folder(source);
    const size_t copied = write_folder(plan, source, dest, hidden_as);
    print_folder(plan, source, copied, out_dir, hidden_as);
    return 0;
}

}  // namespace grading
