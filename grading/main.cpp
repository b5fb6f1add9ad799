// `course`: the trusted grading and course tool (docs/contract.md, `course`). It
// never links lab code: it runs the `lab` executable in child processes and
// decides pass or fail from the data files and its own reference code.
#include <malloc.h>

#include <CLI/CLI.hpp>
#include <cstdio>
#include <functional>
#include <initializer_list>
#include <string>
#include <utility>
#include <vector>

#include "framework/cli.hpp"
#include "framework/error.hpp"
#include "grading/class/class_rows.hpp"
#include "grading/class/grade_class.hpp"
#include "grading/commands/commands.hpp"
#include "grading/platforms/autograder.hpp"
#include "grading/release/release.hpp"

namespace {

using fw::cli::Command;

const char* const kBackendHelp =
    "auto|osmesa|egl (default $LAB_BACKEND, else auto: EGL, then OSMesa)";

// The names of a typed option's values, as the command line spells them.
template <class E>
using Choices = std::initializer_list<std::pair<const char*, E>>;
const Choices<grading::ResultsFormat> kPlatforms = {
    {"gradescope", grading::ResultsFormat::Gradescope},
    {"prairielearn", grading::ResultsFormat::PrairieLearn}};
// `course grade --format`: the platforms, and GitHub Classroom, which runs
// `course grade` itself (the workflow of `course release --github-classroom`).
const Choices<grading::ResultsFormat> kFormats = {
    {"gradescope", grading::ResultsFormat::Gradescope},
    {"prairielearn", grading::ResultsFormat::PrairieLearn},
    {"github-classroom", grading::ResultsFormat::GitHubClassroom}};
const Choices<grading::HiddenAs> kHiddenAs = {
    {"after_due_date", grading::HiddenAs::AfterDueDate},
    {"after_published", grading::HiddenAs::AfterPublished},
    {"hidden", grading::HiddenAs::Hidden}};
const char* const kHiddenAsHelp =
    "How Gradescope shows a hidden checkpoint's test: after_due_date, after_published or "
    "hidden (never; Gradescope then hides the student's total too) (default after_due_date)";
const Choices<grading::GradeOptions::Sandbox> kSandboxes = {
    {"auto", grading::GradeOptions::Sandbox::Auto},
    {"strict", grading::GradeOptions::Sandbox::Strict}};

// An option whose value is one of `choices`, stored as its enum value; any
// other value is a usage error listing the names.
template <class E>
CLI::Option* add_choice(CLI::App* app, const std::string& name, E& target, Choices<E> choices,
                        const std::string& help) {
    std::vector<std::string> names;
    for (const auto& c : choices) names.push_back(c.first);
    const auto store = [&target, choices](const std::string& value) {
        for (const auto& c : choices)
            if (value == c.first) target = c.second;
    };
    return app->add_option_function<std::string>(name, store, help)->check(CLI::IsMember(names));
}

Command add_grade(CLI::App& app, grading::GradeOptions& g) {
    auto* grade = app.add_subcommand("grade", "Grade labs offscreen and write the reports");
    grade->add_option("LAB", g.labs, "Labs to grade (default: all)");
    grade->add_option("--lab", g.lab_binary,
                      "The lab executable to grade (default: beside course)");
    grade->add_option("--out", g.out, "Report directory (default build/grade)");
    grade->add_option("--backend", g.backend, kBackendHelp);
    grade
        ->add_option(
            "--jobs", g.jobs,
            "Children grading labs in parallel, the costliest labs first, each to the least loaded")
        ->check(CLI::Range(1, 64));
    grade->add_option("--timeout", g.timeout_seconds, "Seconds per lab (default 60)")
        ->check(CLI::Range(1.0, 3600.0));
    grade->add_option("--run-as", g.run_as, "Run the child as this user (when root)");
    add_choice(grade, "--format", g.format, kFormats,
               "What results.json holds: gradescope, prairielearn or github-classroom "
               "(default gradescope)");
    grade->add_option("--results", g.results, "Write results.json here (default: into --out)");
    add_choice(grade, "--hidden-as", g.hidden_as, kHiddenAs, kHiddenAsHelp);
    grade->add_option("--shader-cache", g.shader_cache,
                      "Start each lab from a copy of this shader cache (course warm-cache)");
    add_choice(grade, "--sandbox", g.sandbox, kSandboxes,
               "auto: every sandbox layer the machine allows; strict: refuse to grade "
               "without namespaces and cgroups (default auto)");
    grade->add_flag("--verbose", g.verbose,
                    "Also print the sandbox's layers (summary.txt and index.html have them)");
    grade
        ->add_option("--memory", g.memory_mib,
                     "MiB of memory per lab, where a cgroup enforces it (default 2048)")
        ->check(CLI::Range(64, 65536));
    grade->add_option("--not-built", g.not_built,
                      "A JSON file of labs whose C++ did not compile (course autograde): lab "
                      "folder -> the compiler's output; they fail every check, unrun");
    return {grade, [&g] { return grading::grade_command(g); }};
}

Command add_bless(CLI::App& app, grading::BlessOptions& b) {
    auto* bless = app.add_subcommand("bless", "Re-render the reference images from this build");
    bless->add_option("LAB", b.labs, "Labs to bless (default: all)");
    bless->add_option("--lab", b.lab_binary, "The lab executable (default: beside course)");
    bless->add_option("--backend", b.backend, kBackendHelp);
    return {bless, [&b] { return grading::bless_command(b); }};
}

Command add_warm_cache(CLI::App& app, grading::WarmCacheOptions& w) {
    auto* warm = app.add_subcommand(
        "warm-cache", "Fill a shader cache (Mesa's or NVIDIA's) for course grade --shader-cache");
    warm->add_option("DIR", w.dir, "The cache directory (created if missing)")->required();
    warm->add_option("LAB", w.labs, "Labs to render (default: all)");
    warm->add_option("--lab", w.lab_binary, "The lab executable (default: beside course)");
    warm->add_option("--backend", w.backend, kBackendHelp);
    return {warm, [&w] { return grading::warm_cache_command(w); }};
}

Command add_cases(CLI::App& app, grading::CasesOptions& c) {
    auto* cases = app.add_subcommand(
        "cases", "Record a lab's unit cases as course release writes them (grading/cases.json)");
    cases->add_option("LAB", c.lab, "The lab")->required();
    cases->add_option("--out", c.out, "File to write (default labs/NN_name/grading/cases.json)");
    cases->add_option("--seed", c.seed, "Seed of the random cases (default 1)");
    cases->add_option("--max-random", c.max_random, "Random cases per check at most (default 50)")
        ->check(CLI::Range(0, 100000));
    return {cases, [&c] { return grading::cases_command(c); }};
}

Command add_release(CLI::App& app, std::string& out, grading::ReleaseOptions& options) {
    auto* release = app.add_subcommand("release", "Write the student version of the repository");
    release->add_option("--out", out, "Directory to write (must not exist or be empty)")
        ->required();
    release->add_flag("--github-classroom", options.github_classroom,
                      "Also write .github/workflows/classroom.yml: GitHub Classroom's autograding "
                      "of the visible checkpoints");
    return {release, [&out, &options] { return grading::release_command(out, options); }};
}

Command add_gradescope(CLI::App& app, std::string& out, grading::HiddenAs& hidden_as,
                       std::vector<std::string>& labs) {
    auto* gradescope = app.add_subcommand("gradescope", "Write a Gradescope autograder folder");
    gradescope->add_option("--out", out, "Directory to write")->required();
    add_choice(gradescope, "--hidden-as", hidden_as, kHiddenAs, kHiddenAsHelp);
    gradescope->add_option("LAB", labs,
                           "An assignment of these labs only: graded, and their files taken from "
                           "a submission (default: every lab)");
    return {gradescope, [&out, &hidden_as, &labs] {
                return grading::gradescope_command(out, hidden_as, labs);
            }};
}

Command add_prairielearn(CLI::App& app, std::string& out) {
    auto* prairielearn =
        app.add_subcommand("prairielearn", "Write PrairieLearn's grader image and course files");
    prairielearn->add_option("--out", out, "Directory to write")->required();
    return {prairielearn, [&out] { return grading::prairielearn_command(out); }};
}

// Hidden: the autograders' scripts (run_autograder in grading/platforms/gradescope/,
// grade.sh in grading/platforms/prairielearn/) run it for each submission. The timeout
// is passed on to `course grade` as given, so that a value grade refuses
// fails the grading with grade's own message.
Command add_autograde(CLI::App& app, grading::AutogradeOptions& a) {
    auto* autograde = app.add_subcommand(
        "autograde", "Grade a submission and write results/results.json under --root");
    autograde->group("");
    autograde->add_option("LAB", a.labs, "Labs to grade (default: all)");
    add_choice(autograde, "--layout", a.layout, kPlatforms,
               "gradescope or prairielearn (gradescope)");
    autograde->add_option("--root", a.root,
                          "gradescope: holds source/, submission/, results/ (/autograder); "
                          "prairielearn: holds student/, results/ (/grade)");
    autograde->add_option("--source", a.source,
                          "prairielearn: the built course with its student_files.txt (/course)");
    autograde->add_option("--data", a.data,
                          "prairielearn: the checkpoints and references course grades with");
    autograde->add_option("--user", a.user, "Build and run the submission as this user (student)");
    autograde->add_option("--timeout", a.timeout, "Seconds per lab, for course grade (60)");
    add_choice(autograde, "--hidden-as", a.hidden_as, kHiddenAs, kHiddenAsHelp);
    return {autograde, [&a] { return grading::autograde_command(a); }};
}

// canvas.csv's and moodle.csv's options, grade-class's and merge-class's alike.
void add_lms_options(CLI::App* cmd, grading::cls::LmsOptions& lms) {
    cmd->add_option("--roster", lms.roster,
                    "Canvas's gradebook export (Grades > Export), or Moodle's (Export > Plain "
                    "text file): canvas.csv and moodle.csv name its students as it does");
    cmd->add_option("--canvas-column", lms.canvas_columns,
                    "canvas.csv's assignment columns: NAME, one column for the total of the "
                    "labs; or LAB=NAME to title a lab's column (default: a column per lab, "
                    "titled by its id); repeat it for several labs");
    cmd->add_flag("--moodle-total", lms.moodle_total,
                  "moodle.csv has a Total column after the labs' (import it only into a grade "
                  "item of its own: Moodle's course total adds the labs up already)");
}

}  // namespace

Command add_grade_class(CLI::App& app, grading::cls::GradeClassOptions& c) {
    auto* cmd = app.add_subcommand(
        "grade-class",
        "Grade a class's submissions (folders, archives, Gradescope's export or git "
        "repositories) into per-student reports, grades.csv and Canvas's and Moodle's "
        "import files");
    cmd->add_option("SUBMISSIONS", c.submissions, "The folder of submissions")->required();
    cmd->add_option("--out", c.out, "Where the reports and grades.csv go")->required();
    cmd->add_option("--labs", c.labs, "The assignment's labs (default: all)")->delimiter(',');
    cmd->add_option("--jobs", c.jobs, "Submissions graded at once (default: the cores)")
        ->check(CLI::Range(1, 256));
    cmd->add_option("--deadline", c.deadline,
                    "git repositories: grade the last commit before this time "
                    "(YYYY-MM-DDTHH:MM[:SS][Z|+HH:MM], UTC unless a zone is given); "
                    "Gradescope's export: mark later submissions late");
    cmd->add_option("--shard", c.shard, "K/N: grade only the K-th of N fixed slices");
    cmd->add_option("--timeout", c.timeout, "Seconds per lab (default 60)");
    cmd->add_option("--backend", c.backend, kBackendHelp);
    add_lms_options(cmd, c.lms);
    return {cmd, [&c] { return grading::cls::grade_class_command(c); }};
}

Command add_merge_class(CLI::App& app, std::string& out, std::vector<std::string>& dirs,
                        grading::cls::LmsOptions& lms) {
    auto* cmd = app.add_subcommand("merge-class",
                                   "Merge the slices of grade-class --shard into one gradebook");
    cmd->add_option("OUT", out, "Where the merged reports and grades.csv go")->required();
    cmd->add_option("DIR", dirs, "The --out folders of the slices")->required();
    add_lms_options(cmd, lms);
    return {cmd, [&out, &dirs, &lms] { return grading::cls::merge_class_command(out, dirs, lms); }};
}

int main(int argc, char** argv) {
    // Frames are a megabyte each and come and go by the hundred: keep them
    // in the heap rather than mapping and zeroing fresh pages for each.
    mallopt(M_MMAP_THRESHOLD, 64 << 20);
    mallopt(M_TRIM_THRESHOLD, 256 << 20);
    CLI::App app{"course: grade the labs, bless references, release the student version"};
    app.require_subcommand(1);
    grading::GradeOptions grade;
    grading::cls::GradeClassOptions grade_class;
    std::string merge_out;
    std::vector<std::string> merge_dirs;
    grading::cls::LmsOptions merge_lms;
    grading::BlessOptions bless;
    grading::WarmCacheOptions warm;
    grading::CasesOptions cases;
    std::string release_out, gradescope_out, prairielearn_out;
    grading::ReleaseOptions release;
    grading::AutogradeOptions autograde;
    grading::HiddenAs gradescope_hidden_as = grading::HiddenAs::AfterDueDate;
    std::vector<std::string> gradescope_labs;
    const std::vector<Command> commands = {
        add_grade(app, grade),
        add_bless(app, bless),
        add_warm_cache(app, warm),
        add_cases(app, cases),
        add_release(app, release_out, release),
        add_gradescope(app, gradescope_out, gradescope_hidden_as, gradescope_labs),
        add_prairielearn(app, prairielearn_out),
        add_autograde(app, autograde),
        add_grade_class(app, grade_class),
        add_merge_class(app, merge_out, merge_dirs, merge_lms)};

    // Every error of course, the set-up's included, exits with 2.
    const auto usage = [](const fw::Error&) { return 2; };
    return fw::cli::run(app, argc, argv, commands, "course", {usage, 2});
}
