// `course release`, the tree: which files, in what order, with what modes;
// the text transformations are in release.cpp.
#include <sys/wait.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>

#include "framework/checkpoints.hpp"
#include "framework/error.hpp"
#include "framework/text.hpp"
#include "grading/diagnosis/starting_code.hpp"
#include "grading/judge/cases.hpp"
#include "grading/judge/course_seed.hpp"
#include "grading/release/release.hpp"
#include "grading/run/repository.hpp"

namespace fs = std::filesystem;

namespace grading {

namespace {

// A file the release writes: its text when transformed, else copied as is
// (from `from`, the same path but for the student README).
struct Planned {
    std::string rel, from;
    bool transformed = false;
    std::string text;
};

// A release read and checked, before anything is written.
struct ReleasePlan {
    std::vector<Planned> files;
    std::map<std::string, std::set<std::string>> hidden;  // labs/NN_name -> hidden names
    std::vector<LabData> labs;                            // the labs released, parsed
};

// How the file `rel` goes into the release; what it changes goes into
// `plan.hidden` and `summary`. Throws fw::Error for a marker or data error.
Planned plan_file(const fs::path& root, const std::string& rel, ReleasePlan& plan,
                  ReleaseSummary& summary) {
    const fs::path src = root / rel, r(rel);
    Planned p;
    p.rel = rel;
    p.from = rel;
    if (fs::is_regular_file(fs::symlink_status(src)) && is_marked_source(rel)) {
        const std::string text = read_file(src);
        const size_t blocks = solution_blocks(text, rel).size();
        if (blocks > 0) {
            p.transformed = true;
            p.text = student_text(text, rel);
            summary.blocks.push_back({rel, static_cast<int>(blocks)});
        }
    } else if (r.filename() == "checkpoints.json" && r.parent_path().parent_path() == "labs") {
        // Its structure first, with the framework's messages.
        fw::read_checkpoint_file(src.string());
        VisibleCheckpoints v = drop_hidden_checkpoints(read_file(src), rel);
        if (!v.dropped.empty()) {
            p.transformed = true;
            p.text = v.text;
            plan.hidden[r.parent_path().string()].insert(v.dropped.begin(), v.dropped.end());
            summary.hidden.push_back({rel, v.dropped});
        }
    }
    return p;
}

// The student's copy has no references (they give the solutions away) and
// no solution blocks: for each lab, what `course` built there needs of them,
// as data in the lab's grading/ folder. cases.json: its visible unit
// checks' cases and course's results (grading/judge/cases.hpp).
// starting.json: a hash of each part's starting code, so that a part still
// as released is known there (grading/diagnosis/starting_code.hpp).
void plan_lab_data(const fs::path& root, const std::vector<std::string>& tracked, ReleasePlan& plan,
                   ReleaseSummary& summary) {
    for (LabData& lab : discover_labs(root.string())) {
        // A lab git does not track is not released (its files are named as such).
        const std::string file = "labs/" + lab.dir + "/checkpoints.json";
        if (std::find(tracked.begin(), tracked.end(), file) == tracked.end()) continue;
        parse_checks(lab);
        plan.labs.push_back(lab);
        if (!lab.parts.empty()) {
            Planned p;
            p.rel = starting_file(lab.dir);
            p.transformed = true;
            p.text = starting_file_text(root.string(), lab.parts);
            summary.starting.push_back(p.rel);
            plan.files.push_back(std::move(p));
        }
        const nlohmann::json cases = record_unit_cases(lab, kCasesSeed, kCasesPerCheck);
        if (cases.value("checks", nlohmann::json::array()).empty()) continue;
        Planned p;
        p.rel = "labs/" + lab.dir + "/grading/cases.json";
        p.transformed = true;
        p.text = cases.dump() + "\n";
        summary.cases.push_back({p.rel, p.text.size()});
        plan.files.push_back(std::move(p));
    }
}

// Pass 1: reads, transforms and checks every tracked file a student gets;
// nothing is written yet.
ReleasePlan plan_release(const fs::path& root, ReleaseSummary& summary) {
    ReleasePlan plan;
    std::string errors;
    ProjectFiles lists = project_file_lists(root.string());
    summary.untracked = std::move(lists.untracked);
    for (const std::string& rel : lists.tracked) {
        if (!fs::exists(fs::symlink_status(root / rel))) {
            summary.missing.push_back(rel);
            continue;
        }
        if (rel == kStudentReadme) plan.files.push_back({"README.md", rel, false, ""});
        if (is_staff_only(rel)) {
            ++summary.staff_only;
            continue;
        }
        try {
            plan.files.push_back(plan_file(root, rel, plan, summary));
        } catch (const fw::Error& e) {
            errors += std::string("\n  ") + e.what();
        }
    }
    if (!errors.empty()) throw fw::Error("the release was not written: fix these first:" + errors);
    plan_lab_data(root, lists.tracked, plan, summary);
    return plan;
}

// Whether `rel` is the reference image of a hidden checkpoint
// (labs/NN_name/reference/CHECKPOINT.png), or one of the files of its known
// mistakes' frames (reference/mistakes/CHECKPOINT.json, CHECKPOINT.N.png).
bool is_hidden_reference(const ReleasePlan& plan, const std::string& rel) {
    const fs::path r(rel);
    fs::path folder = r.parent_path();
    if (folder.filename() == "mistakes") folder = folder.parent_path();
    const auto lab = plan.hidden.find(folder.parent_path().string());
    if (folder.filename() != "reference" || lab == plan.hidden.end()) return false;
    const std::string name = r.filename().string();
    return lab->second.count(name.substr(0, name.find('.'))) > 0;
}

void create_parent(const fs::path& path) {
    std::error_code ec;
    fs::create_directories(path.parent_path(), ec);
    if (ec)
        throw fw::Error("cannot create directory '" + path.parent_path().string() +
                        "': " + ec.message());
}

}  // namespace

bool is_staff_only(const std::string& rel) {
    std::vector<std::string> parts;
    for (const fs::path& part : fs::path(rel)) parts.push_back(part.string());
    if (parts.empty()) return false;
    static const std::set<std::string> kStaffFolders = {"tests", "bench", ".ci"};
    static const std::set<std::string> kStaffFiles = {
        "README.md",   "Dockerfile", ".dockerignore", "scripts/test.sh", "scripts/fresh-debian.sh",
        kStudentReadme};
    if (kStaffFolders.count(parts[0]) || kStaffFiles.count(rel)) return true;
    // The seed of the course's random cases (grading/judge/course_seed.hpp).
    if (rel == kCourseSeedFile) return true;
    // The staff's guide, grading a class on a cluster, and the staff's
    // measurements.
    if (rel == "docs/staff.md" || rel == "docs/performance.md" ||
        (parts.size() >= 2 && parts[0] == "docs" && parts[1] == "cluster"))
        return true;
    // labs/NN_name/tests/ and labs/NN_name/grading/ (the references), and
    // the solution's records (reference/CHECKPOINT.record.json: its exact
    // state and uniforms, the answers of the unit functions among them).
    const auto ends_with = [](const std::string& s, const std::string& end) {
        return s.size() >= end.size() && s.compare(s.size() - end.size(), end.size(), end) == 0;
    };
    return parts.size() >= 4 && parts[0] == "labs" &&
           (parts[2] == "tests" || parts[2] == "grading" ||
            (parts[2] == "reference" && parts.size() == 4 && ends_with(rel, ".record.json")));
}

void require_new_output_dir(const fs::path& dir) {
    std::error_code ec;
    if (fs::exists(dir, ec) && (!fs::is_directory(dir, ec) || !fs::is_empty(dir, ec)))
        throw fw::UsageError("output directory '" + dir.string() + "' " +
                             (fs::is_directory(dir, ec) ? "is not empty" : "is not a directory") +
                             "; give a new directory or empty this one");
}

void copy_entry(const fs::path& from, const fs::path& to) {
    create_parent(to);
    std::error_code ec;
    if (fs::is_symlink(from))
        fs::copy_symlink(from, to, ec);
    else
        fs::copy_file(from, to, ec);
    if (ec)
        throw fw::Error("cannot copy '" + from.string() + "' to '" + to.string() +
                        "': " + ec.message());
    if (!fs::is_symlink(from)) fs::permissions(to, fs::status(from).permissions(), ec);
    if (ec) throw fw::Error("cannot set the mode of '" + to.string() + "': " + ec.message());
}

void write_file(const fs::path& path, const std::string& text, fs::perms mode) {
    create_parent(path);
    std::ofstream out(path, std::ios::binary);
    out << text;
    if (!out.flush())
        throw fw::Error("cannot write '" + path.string() + "': check the disk and permissions");
    std::error_code ec;
    fs::permissions(path, mode, ec);
    if (ec) throw fw::Error("cannot set the mode of '" + path.string() + "': " + ec.message());
}

std::string read_file(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw fw::Error("cannot read '" + path.string() +
                        "': check that it exists and is readable");
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

namespace {

// `git ls-files -z ARGS` in the checkout `source`, one path per entry.
std::vector<std::string> git_files(const std::string& source, const std::string& args) {
    const std::string command = "git -C " + fw::shell_quote(source) + " ls-files -z " + args;
    FILE* p = popen(command.c_str(), "r");
    if (!p) throw fw::Error("cannot run '" + command + "': is git installed?");
    std::string listing;
    char buf[4096];
    size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) listing.append(buf, n);
    const int status = pclose(p);
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
        throw fw::Error("'" + command + "' failed in the git checkout '" + source +
                        "' (see git's message above); install git or fix the checkout");
    std::vector<std::string> files;
    for (size_t b = 0, e; b < listing.size(); b = e + 1) {
        e = listing.find('\0', b);
        if (e == std::string::npos) e = listing.size();
        if (e > b) files.push_back(listing.substr(b, e - b));
    }
    return files;
}

// Every file under `root` outside build*/ (at the top), .git/ and .cache/.
std::vector<std::string> walked_files(const fs::path& root) {
    std::vector<std::string> files;
    for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator();
         ++it) {
        const std::string name = it->path().filename().string();
        const bool top = it.depth() == 0;
        if (it->is_directory() &&
            (name == ".git" || name == ".cache" || (top && name.rfind("build", 0) == 0))) {
            it.disable_recursion_pending();
            continue;
        }
        if (!it->is_directory()) files.push_back(fs::relative(it->path(), root).string());
    }
    return files;
}

void sort_unique(std::vector<std::string>& files) {
    std::sort(files.begin(), files.end());
    files.erase(std::unique(files.begin(), files.end()), files.end());
}

}  // namespace

ProjectFiles project_file_lists(const std::string& source) {
    const fs::path root(source);
    if (!fs::is_directory(root))
        throw fw::Error("source tree '" + source +
                        "' is not a directory; set LAB_ROOT to the repository");
    ProjectFiles out;
    if (fs::exists(root / ".git")) {
        out.tracked = git_files(source, "--cached");
        out.untracked = git_files(source, "--others --exclude-standard");
    } else {
        out.tracked = walked_files(root);
    }
    sort_unique(out.tracked);
    sort_unique(out.untracked);
    return out;
}

std::vector<std::string> project_files(const std::string& source) {
    // Untracked files count too: a build of a working tree compiles them (a
    // new lab not yet committed included).
    ProjectFiles lists = project_file_lists(source);
    std::vector<std::string> files = std::move(lists.tracked);
    files.insert(files.end(), lists.untracked.begin(), lists.untracked.end());
    sort_unique(files);
    return files;
}

ReleaseSummary release_tree(const std::string& source, const std::string& out,
                            const ReleaseOptions& options) {
    const fs::path root(source), dest(out);
    require_new_output_dir(dest);
    ReleaseSummary summary;
    ReleasePlan plan = plan_release(root, summary);
    if (options.github_classroom) {
        for (const Planned& p : plan.files)
            if (p.rel == kGitHubClassroomWorkflow)
                throw fw::Error("the release was not written: " + p.from +
                                " would be replaced by the GitHub Classroom workflow that "
                                "--github-classroom writes; rename it or leave the option out");
        plan.files.push_back(
            {kGitHubClassroomWorkflow, "", true, github_classroom_workflow(plan.labs)});
        summary.classroom_labs = plan.labs.size();
    }

    // Pass 2: write, leaving out the hidden checkpoints' references.
    std::error_code ec;
    fs::create_directories(dest, ec);
    if (ec) throw fw::Error("cannot create output directory '" + out + "': " + ec.message());
    for (const Planned& p : plan.files) {
        if (is_hidden_reference(plan, p.rel)) {
            summary.references_left_out.push_back(p.rel);
            continue;
        }
        const fs::path src = root / p.from;
        if (p.from.empty())
            write_file(dest / p.rel, p.text, kReadable);
        else if (p.transformed && !fs::is_symlink(src))
            write_file(dest / p.rel, p.text, fs::status(src).permissions());
        else
            copy_entry(src, dest / p.rel);
        ++summary.files;
    }
    return summary;
}

int release_command(const std::string& out_dir, const ReleaseOptions& options) {
    const std::string source = source_root();
    ReleaseSummary s = release_tree(source, out_dir, options);
    int blocks = 0;
    size_t checkpoints = 0;
    std::printf("course release: the student version of %s\n", source.c_str());
    for (const auto& [file, n] : s.blocks) {
        std::printf("  %-48s %d solution block%s removed\n", file.c_str(), n, n == 1 ? "" : "s");
        blocks += n;
    }
    for (const auto& [file, names] : s.hidden) {
        const std::string list = fw::join(names, ", ");
        std::printf("  %-48s %zu hidden checkpoint%s dropped: %s\n", file.c_str(), names.size(),
                    names.size() == 1 ? "" : "s", list.c_str());
        checkpoints += names.size();
    }
    for (const std::string& file : s.references_left_out)
        std::printf("  %-48s left out (reference of a hidden checkpoint)\n", file.c_str());
    for (const std::string& file : s.missing)
        std::printf("  %-48s not written: tracked by git but missing from the tree\n",
                    file.c_str());
    for (const auto& [file, bytes] : s.cases)
        std::printf("  %-48s written: the visible unit checks' cases (%zu bytes)\n", file.c_str(),
                    bytes);
    for (const std::string& file : s.starting)
        std::printf("  %-48s written: the hashes of the parts' starting code\n", file.c_str());
    if (s.classroom_labs > 0)
        std::printf("  %-48s written: GitHub Classroom's autograding of %zu labs\n",
                    kGitHubClassroomWorkflow, s.classroom_labs);
    for (const std::string& file : s.untracked)
        std::printf("  %-48s not released: git does not track it (commit it to release it)\n",
                    file.c_str());
    std::printf(
        "  %zu staff files left out: the course's tests, benchmarks, references and CI; "
        "%s is the student's README.md\n",
        s.staff_only, kStudentReadme);
    std::printf(
        "%zu files written to %s; %d solution blocks removed from %zu files; %zu hidden "
        "checkpoints and %zu reference files left out\n",
        s.files, out_dir.c_str(), blocks, s.blocks.size(), checkpoints,
        s.references_left_out.size());
    return 0;
}

}  // namespace grading
