// `course gradescope --out DIR` (SPEC.md, `course gradescope`): the folder
// a course uploads to Gradescope as its autograder. It holds
// - the whole repository, solutions, hidden checkpoints and references
//   included (what `course grade` needs), without build folders or .git;
// - setup.sh and run_autograder at the top (from grading/gradescope/):
//   Gradescope runs setup.sh once, as root, to build its image, and
//   run_autograder for each submission;
// - student_files.txt: the files students edit (those with solution blocks),
//   and student_versions/<file>: their student versions (`course release`),
//   which run_autograder grades in place of a file a submission lacks, so
//   that a solution is never graded as a student's work.
// And `course not-graded`, which run_autograder calls when it cannot grade.
#include "grading/gradescope.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <vector>

#include "framework/error.hpp"
#include "grading/checks.hpp"
#include "grading/child.hpp"
#include "grading/commands.hpp"
#include "grading/release.hpp"
#include "grading/report_text.hpp"
#include "grading/reports.hpp"

namespace fs = std::filesystem;

namespace grading {

namespace {

// The scripts, in the repository and at the top of the folder.
constexpr const char* kTemplates = "grading/gradescope";
constexpr const char* kScripts[] = {"setup.sh", "run_autograder"};
constexpr const char* kStudentFiles = "student_files.txt";
constexpr const char* kStudentVersions = "student_versions";

void write_file(const fs::path& path, const std::string& text, fs::perms mode) {
    std::error_code ec;
    fs::create_directories(path.parent_path(), ec);
    std::ofstream out(path, std::ios::binary);
    out << text;
    if (ec || !out.flush())
        throw fw::Error("cannot write '" + path.string() + "': check the disk and permissions");
    fs::permissions(path, mode, ec);
    if (ec) throw fw::Error("cannot set the mode of '" + path.string() + "': " + ec.message());
}

void copy_entry(const fs::path& from, const fs::path& to) {
    std::error_code ec;
    fs::create_directories(to.parent_path(), ec);
    if (!ec) {
        if (fs::is_symlink(from))
            fs::copy_symlink(from, to, ec);
        else if (fs::copy_file(from, to, ec))
            fs::permissions(to, fs::status(from).permissions(), ec);
    }
    if (ec)
        throw fw::Error("cannot copy '" + from.string() + "' to '" + to.string() +
                        "': " + ec.message());
}

constexpr fs::perms kExecutable = fs::perms::owner_all | fs::perms::group_read |
                                  fs::perms::group_exec | fs::perms::others_read |
                                  fs::perms::others_exec;
constexpr fs::perms kReadable =
    fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read | fs::perms::others_read;

// The last `lines` lines of a file, at most its last MiB.
std::string tail_of_file(const std::string& path, int lines) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw fw::Error("cannot read the log '" + path + "': check that it exists and is readable");
    in.seekg(0, std::ios::end);
    const std::streamoff size = in.tellg();
    const std::streamoff from = std::max<std::streamoff>(0, size - std::streamoff(kMiB));
    in.seekg(from);
    std::string text(static_cast<size_t>(size - from), '\0');
    in.read(text.data(), static_cast<std::streamsize>(text.size()));
    while (!text.empty() && text.back() == '\n') text.pop_back();
    size_t start = text.size();
    for (int n = 0; n < lines && start != std::string::npos && start > 0; ++n)
        start = text.rfind('\n', start - 1);
    return start == std::string::npos || start == text.size() ? text : text.substr(start + 1);
}

}  // namespace

int gradescope_command(const std::string& out_dir) {
    const fs::path source(source_root()), dest(out_dir);
    std::error_code ec;
    if (fs::exists(dest, ec) && (!fs::is_directory(dest, ec) || !fs::is_empty(dest, ec)))
        throw fw::UsageError("output directory '" + out_dir + "' " +
                             (fs::is_directory(dest, ec) ? "is not empty" : "is not a directory") +
                             "; give a new directory or empty this one");
    for (const char* script : kScripts)
        if (!fs::is_regular_file(source / kTemplates / script))
            throw fw::Error("missing '" + (source / kTemplates / script).string() +
                            "'; the autograder's scripts live in " + kTemplates +
                            "/ of the repository (set LAB_ROOT to it)");

    // Everything is read and checked before anything is written.
    const std::vector<std::string> files = project_files(source.string());
    std::vector<std::pair<std::string, std::string>> students;  // file -> student version
    std::vector<std::string> missing;
    std::string errors;
    for (const std::string& rel : files) {
        const fs::path path = source / rel;
        if (!fs::exists(fs::symlink_status(path))) {
            missing.push_back(rel);
            continue;
        }
        if (!is_marked_source(rel) || !fs::is_regular_file(fs::symlink_status(path))) continue;
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
                        "replace; mark the student parts (SPEC.md, `course release`)");

    fs::create_directories(dest, ec);
    if (ec) throw fw::Error("cannot create output directory '" + out_dir + "': " + ec.message());
    size_t copied = 0;
    for (const std::string& rel : files) {
        if (std::count(missing.begin(), missing.end(), rel)) continue;
        copy_entry(source / rel, dest / rel);
        ++copied;
    }
    for (const char* script : kScripts)
        write_file(dest / script, read_file(source / kTemplates / script), kExecutable);
    std::string list;
    for (const auto& [rel, text] : students) {
        list += rel + "\n";
        write_file(dest / kStudentVersions / rel, text, kReadable);
    }
    write_file(dest / kStudentFiles, list, kReadable);

    std::printf("course gradescope: the autograder for %s\n", source.string().c_str());
    std::printf("  %zu files of the repository (solutions and hidden checkpoints included)\n",
                copied);
    for (const char* script : kScripts)
        std::printf("  %-48s from %s/%s\n", script, kTemplates, script);
    std::printf("  %-48s %zu files students edit:\n", kStudentFiles, students.size());
    for (const auto& [rel, text] : students)
        std::printf("    %s (student version in %s/)\n", rel.c_str(), kStudentVersions);
    for (const std::string& rel : missing)
        std::printf("  %-48s not copied: tracked by git but missing from the tree\n", rel.c_str());
    std::printf(
        "Zip the contents of %s (not the folder itself) and upload it to Gradescope as "
        "the autograder.\n",
        out_dir.c_str());
    return 0;
}

int not_graded_command(const std::string& reason, const std::string& log_file,
                       const std::string& out_dir) {
    const std::string log = log_file.empty() ? "" : tail_of_file(log_file, 200);
    // The checks, named and scored as `course grade` names them, judged on the
    // outputs of a child that never ran: an empty work directory.
    WorkDir empty(nullptr);
    ChildRun none;
    none.status = reason;
    const ChildOutputs outputs(empty.path(), none, ChildLimits{});
    GradeRun run;
    for (const LabData& lab : discover_labs(source_root())) {
        validate_checks(lab);
        LabResult result;
        result.lab = lab.id;
        result.status = reason;
        result.checks = judge_lab(lab, plan_lab(lab, 0, PlanFor::Grading), outputs, out_dir);
        for (CheckResult& check : result.checks) check.output.clear();  // the status says why
        run.labs.push_back(std::move(result));
    }
    write_reports(run, out_dir);

    // results.json's overall output: the reason once and the log, rather than
    // the reason once per lab.
    const std::string path = report::in_dir(out_dir, "results.json");
    nlohmann::ordered_json results = nlohmann::ordered_json::parse(read_file(path));
    results["output"] =
        report::clean_text("0/" + report::points(run.max_score()) + " points: " + reason +
                           (log.empty() ? "" : "\n\n" + log) + "\n");
    report::write_text_file(path, results.dump(2) + "\n");
    std::printf("%s", summary_table(run).c_str());
    return 1;
}

}  // namespace grading
