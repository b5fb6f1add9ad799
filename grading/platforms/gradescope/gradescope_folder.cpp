// `course gradescope --out DIR` (docs/contract.md, `course gradescope`): the folder
// a course uploads to Gradescope as its autograder. It holds
// - the whole repository, solutions, hidden checkpoints and references
//   included (what `course grade` needs), without build folders or .git;
// - setup.sh and run_autograder at the top (from grading/platforms/gradescope/):
//   Gradescope runs setup.sh once, as root, to build its image, and
//   run_autograder (which runs `course autograde`) for each submission;
//   run_autograder's `hidden_as=` line holds `--hidden-as`, how Gradescope
//   shows the tests of hidden checkpoints, and its `labs=` line the labs the
//   assignment grades (empty: all);
// - student_files.txt: the files students edit (those with solution blocks;
//   for an assignment of some labs, only those labs' files), and
//   student_versions/<file>: their student versions (`course release`),
//   which `course autograde` grades in place of a file a submission lacks,
//   so that a solution is never graded as a student's work;
// - solution_shaders/NN_name/FILE: the course's own text of each student
//   shader, which `course grade` reads to tell which file is wrong once
//   the submission's files replace the course's (setup.sh and `course
//   autograde` keep it from the user).
#include <sys/stat.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <utility>
#include <vector>

#include "framework/error.hpp"
#include "framework/text.hpp"
#include "grading/diagnosis/file_isolation.hpp"
#include "grading/judge/checks.hpp"
#include "grading/platforms/autograder.hpp"
#include "grading/release/release.hpp"
#include "grading/run/repository.hpp"

namespace fs = std::filesystem;

namespace grading {

namespace {

// The scripts, in the repository and at the top of the folder: setup.sh as
// it is, run_autograder with the folder's lines written in.
constexpr const char* kTemplates = "grading/platforms/gradescope";
enum class Script { Setup, RunAutograder };
struct ScriptFile {
    Script script;
    const char* name;
};
constexpr ScriptFile kScripts[] = {{Script::Setup, "setup.sh"},
                                   {Script::RunAutograder, "run_autograder"}};
constexpr const char* kStudentFiles = "student_files.txt";
constexpr const char* kStudentVersions = "student_versions";

// run_autograder's `line` ("hidden_as=after_due_date", "labs=") as `value`.
std::string with_line(std::string text, const fs::path& from, const std::string& line,
                      const std::string& value, const char* option) {
    const size_t at = text.find("\n" + line + "\n");
    if (at == std::string::npos)
        throw fw::Error("'" + from.string() + "' has no line '" + line +
                        "', where course gradescope writes " + option);
    return text.replace(at + 1, line.size(), value);
}

// What the folder will hold, read and checked before anything is written.
struct FolderPlan {
    std::vector<std::string> files;  // of the repository
    StudentFiles students;
    std::vector<std::string> missing;  // tracked, not in the tree
    std::vector<std::string> labs;     // the assignment's, by name (empty: all)
};

// Whether `rel` is a file of `lab`: under labs/DIR/ or shaders/DIR/.
bool of_lab(const std::string& rel, const LabData& lab) {
    for (const char* top : {"labs/", "shaders/"})
        if (rel.rfind(top + lab.dir + "/", 0) == 0) return true;
    return false;
}

// The student files of an assignment of `labs` only: the others stay as the
// folder has them, so that no file of another lab can break the build.
StudentFiles assignment_files(const StudentFiles& all, const std::vector<LabData>& labs) {
    StudentFiles kept;
    for (const auto& file : all)
        for (const LabData& lab : labs)
            if (of_lab(file.first, lab)) {
                kept.push_back(file);
                break;
            }
    return kept;
}

FolderPlan plan_folder(const fs::path& source, const std::vector<std::string>& labs) {
    for (const ScriptFile& s : kScripts) require_template(source, kTemplates, s.name);
    FolderPlan plan;
    plan.files = project_files(source.string());
    for (const std::string& rel : plan.files)
        if (!fs::exists(fs::symlink_status(source / rel))) plan.missing.push_back(rel);
    plan.students = student_files(source, plan.files);
    if (labs.empty()) return plan;
    const std::vector<LabData> chosen = select_labs(discover_labs(source.string()), labs);
    for (const LabData& lab : chosen) {
        if (assignment_files(plan.students, {lab}).empty())
            throw fw::UsageError("lab '" + lab.id +
                                 "' has no file with a solution block (under labs/" + lab.dir +
                                 "/ or shaders/" + lab.dir +
                                 "/), so an assignment of it would grade nothing a student wrote");
        plan.labs.push_back(lab.id);
    }
    plan.students = assignment_files(plan.students, chosen);
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
    for (const ScriptFile& s : kScripts) {
        const fs::path from = source / kTemplates / s.name;
        std::string text = read_file(from);
        if (s.script == Script::RunAutograder) {
            text = with_line(text, from, "hidden_as=after_due_date",
                             std::string("hidden_as=") + name_of(hidden_as), "--hidden-as");
            if (!plan.labs.empty())
                text = with_line(text, from, "labs=", "labs=\"" + fw::join(plan.labs, " ") + "\"",
                                 "the labs of an assignment");
        }
        write_file(dest / s.name, text, kExecutable);
    }
    write_student_files(plan.students, dest);
    write_solution_shaders(plan.students, source, dest);
    return copied;
}

void print_folder(const FolderPlan& plan, const fs::path& source, size_t copied,
                  const std::string& out_dir, HiddenAs hidden_as) {
    std::printf("course gradescope: the autograder for %s\n", source.string().c_str());
    std::printf("  %zu files of the repository (solutions and hidden checkpoints included)\n",
                copied);
    for (const ScriptFile& s : kScripts)
        std::printf("  %-48s from %s/%s\n", s.name, kTemplates, s.name);
    std::printf("  hidden checkpoints' tests shown on Gradescope: %s (--hidden-as)\n",
                name_of(hidden_as));
    if (plan.labs.empty())
        std::printf("  graded: every lab (name labs after --out for an assignment of some)\n");
    else
        std::printf(
            "  graded: %s only (the assignment's labs; the other labs' files are not "
            "taken from a submission)\n",
            fw::join(plan.labs, ", ").c_str());
    std::printf("  %-48s %zu files students edit:\n", kStudentFiles, plan.students.size());
    for (const auto& [rel, text] : plan.students)
        std::printf("    %s (student version in %s/)\n", rel.c_str(), kStudentVersions);
    std::printf("  %-48s the course's text of the student shaders (which file is wrong)\n",
                (std::string(kSolutionShaders) + "/").c_str());
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

size_t write_solution_shaders(const StudentFiles& students, const fs::path& source,
                              const fs::path& dest) {
    size_t written = 0;
    for (const auto& [rel, text] : students) {
        if (rel.rfind("shaders/", 0) != 0) continue;
        write_file(dest / kSolutionShaders / rel.substr(std::string("shaders/").size()),
                   read_file(source / rel), kReadable);
        ++written;
    }
    return written;
}

int gradescope_command(const std::string& out_dir, HiddenAs hidden_as,
                       const std::vector<std::string>& labs) {
    const fs::path source(source_root()), dest(out_dir);
    require_new_output_dir(dest);
    const FolderPlan plan = plan_folder(source, labs);
    const size_t copied = write_folder(plan, source, dest, hidden_as);
    print_folder(plan, source, copied, out_dir, hidden_as);
    return 0;
}

}  // namespace grading
