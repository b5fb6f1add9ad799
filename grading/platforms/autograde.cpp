// `course autograde` (gradescope.hpp): what Gradescope and PrairieLearn run
// for each submission, through their shims (run_autograder, grade.sh), as
// root. It puts the submitted files in place of those in the course's tree,
// rebuilds `lab`, grades it with `course grade` and copies the results to
// results/results.json. Whatever the submission does, it leaves a complete
// results.json: for Gradescope, a lab whose C++ does not compile scores 0
// on its own checks, the others built with its starting code; a submission
// that does not build even so, or a grader that fails, scores 0 on every
// check with the reason in the output; for PrairieLearn a submission that
// does not build is not gradable, with the reason.
#include <fcntl.h>
#include <pwd.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <vector>

#include "framework/error.hpp"
#include "framework/text.hpp"
#include "grading/diagnosis/file_isolation.hpp"
#include "grading/platforms/autograder.hpp"
#include "grading/platforms/compile_units.hpp"
#include "grading/platforms/run_logged.hpp"
#include "grading/platforms/submitted_files.hpp"
#include "grading/report/prairielearn_results.hpp"
#include "grading/report/report_text.hpp"
#include "grading/run/child.hpp"
#include "grading/run/parallel.hpp"

namespace fs = std::filesystem;

namespace grading {

namespace {

// Where the paths of a layout are (gradescope.hpp, AutogradeOptions).
struct Layout {
    ResultsFormat format = ResultsFormat::Gradescope;
    fs::path source;      // the course's tree, built; its student files are replaced
    fs::path data;        // LAB_ROOT of `course grade`: checkpoints and references
    fs::path submission;  // the submitted files
    fs::path results;     // results.json goes here
    std::string prefix;   // of the lines printed to the log
};

Layout resolve_layout(const AutogradeOptions& options) {
    Layout l;
    if (options.layout == ResultsFormat::PrairieLearn) {
        const fs::path root = options.root.empty() ? "/grade" : options.root;
        if (options.data.empty())
            throw fw::UsageError(
                "--layout prairielearn needs --data DIR: the checkpoints and references "
                "(grade.sh passes its own folder in serverFilesCourse)");
        l.format = ResultsFormat::PrairieLearn;
        l.source = options.source.empty() ? "/course" : options.source;
        l.data = options.data;
        l.submission = root / "student";
        l.results = root / "results";
        l.prefix = "grade.sh: ";
    } else {
        const fs::path root = options.root.empty() ? "/autograder" : options.root;
        if (!options.source.empty() || !options.data.empty())
            throw fw::UsageError("--source and --data belong to --layout prairielearn");
        l.source = root / "source";
        l.data = l.source;
        l.submission = root / "submission";
        l.results = root / "results";
        l.prefix = "run_autograder: ";
    }
    return l;
}

// The results.json written when not even the failed reports can be made.
std::string fallback_json(const Layout& layout, const std::string& reason,
                          const std::string& details) {
    if (layout.format == ResultsFormat::PrairieLearn)
        return prairielearn_not_gradable_json(reason, details);
    return nlohmann::ordered_json{{"score", 0},
                                  {"output", report::clean_text(reason + "\n\n" + details)}}
               .dump(2) +
           "\n";
}

class Autograder {
public:
    Autograder(const AutogradeOptions& options, const Layout& layout)
        : options_(options),
          layout_(layout),
          source_(layout.source),
          results_(layout.results),
          lab_(source_ / "build" / "bin" / "lab"),
          as_user_(geteuid() == 0 && getpwnam(options.user.c_str()) != nullptr) {}

    void run() {
        prepare_results();
        try {
            work_ = std::make_unique<WorkDir>(nullptr);
        } catch (const fw::Error&) {
            const char* tmp = std::getenv("TMPDIR");
            const std::string where = tmp && *tmp ? tmp : "/tmp";
            report::write_text_file(
                (results_ / "results.json").string(),
                fallback_json(layout_,
                              "the autograder could not create a work directory in " + where,
                              "please tell the course staff"));
            return;
        }
        private_data();
        if (timed("copying the submitted files", [this] { return place_submitted_files(); }) &&
            timed("building lab", [this] { return build_lab(); }))
            timed("grading", [this] {
                grade();
                return true;
            });
    }

    // Runs one step and says in the log how long it took (the figures of
    // bench/bench_gradescope.sh, and a hint for staff when grading is slow).
    template <class Step>
    bool timed(const char* what, Step step) {
        const auto start = std::chrono::steady_clock::now();
        const bool ok = step();
        std::printf(
            "%s%s took %.1f s\n", layout_.prefix.c_str(), what,
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
        std::fflush(stdout);
        return ok;
    }

    // Reports that fail every check with `reason` and the tail of `log` ("":
    // none); if even that fails, a results.json with the score and the reason.
    void not_graded(const std::string& reason, const std::string& log) {
        std::printf("%s%s\n", layout_.prefix.c_str(), reason.c_str());
        std::fflush(stdout);
        const fs::path grade = results_ / "grade";
        std::error_code ec;
        fs::remove_all(grade, ec);
        try {
            not_graded_command(reason, log, grade.string(), layout_.format, options_.labs,
                               options_.hidden_as);
            fs::copy_file(grade / "results.json", results_ / "results.json",
                          fs::copy_options::overwrite_existing);
        } catch (const std::exception& e) {
            std::printf("course autograde: error: %s\n", e.what());
            write_fallback(reason, log, e.what());
        }
    }

private:
    // The results are root's: submitted code must not write them.
    void prepare_results() {
        fs::create_directories(results_);
        std::error_code ec;
        fs::remove(results_ / "results.json", ec);
        fs::remove_all(results_ / "grade", ec);
        if (geteuid() == 0 && chown(results_.c_str(), 0, 0) == 0) chmod(results_.c_str(), 0755);
    }

    // What only course may read, kept from the user before any submitted code runs:
    // the course's text of the student shaders
    // (grading/diagnosis/file_isolation.hpp), and PrairieLearn's data folder, which
    // PrairieLearn brings with each job to /grade, where the user may read. Course
    // grades with a copy of the data in the work directory, which only root may
    // enter (Gradescope's setup.sh protects its own tree); `course grade --run-as`
    // then checks that the user cannot read the references.
    void private_data() {
        if (!as_user_) return;
        const RunAsUser user = lookup_user(options_.user);
        if (layout_.data == source_) {
            lock_away(user, source_ / kSolutionShaders);
            return;
        }
        lock_away(user, layout_.data);
        const fs::path copy = fs::path(work_->path()) / "data";
        std::error_code ec;
        fs::create_directories(copy, ec);
        for (const char* folder : {"labs", kSolutionShaders})
            if (!ec && fs::exists(layout_.data / folder))
                fs::copy(layout_.data / folder, copy / folder, fs::copy_options::recursive, ec);
        if (ec)
            throw fw::Error("cannot copy the checkpoints and references of " +
                            layout_.data.string() + " to " + copy.string() + ": " + ec.message());
        setenv("LAB_ROOT", copy.c_str(), 1);
    }

    // `dir`, where it exists, becomes root's with mode 0700; an error unless
    // `user` then cannot read it.
    static void lock_away(const RunAsUser& user, const fs::path& dir) {
        if (!fs::exists(dir)) return;
        if (chown(dir.c_str(), 0, 0) != 0 || chmod(dir.c_str(), 0700) != 0)
            throw fw::Error("cannot keep " + dir.string() + " from the user '" + user.name +
                            "': " + std::strerror(errno));
        if (user_can_access(user, dir.string(), R_OK))
            throw fw::Error("the user '" + user.name + "' can still read " + dir.string() +
                            ", which holds what only the grader may read");
    }

    bool place_submitted_files() {
        std::printf("%sthe submitted files\n", layout_.prefix.c_str());
        const std::vector<std::string> files = read_lines(source_ / "student_files.txt");
        const SubmittedFiles submitted(layout_.submission, source_ / "student_versions", files);
        for (const std::string& rel : files) {
            const Chosen chosen = submitted.choose(rel);
            const fs::path to = source_ / rel;
            // Unchanged files keep their timestamps, so the rebuild stays small.
            if (!same_contents(chosen.from, to) && !copy_contents(chosen.from, to)) {
                not_graded(
                    "the autograder could not copy " + chosen.from.string() + " to " + to.string(),
                    "");
                return false;
            }
            std::printf("  %-48s %s\n", rel.c_str(), chosen.how.c_str());
        }
        return true;
    }

    // Only `lab` holds submitted code; course is the autograder's own build.
    // The compiler runs as the user, who cannot read references or checkpoint
    // files, so no #include can quote them into the message.
    bool build_lab() {
        std::vector<std::string> command = compile_as_user();
        command.insert(command.end(), {"cmake", "--build", (source_ / "build").string(), "--target",
                                       "lab", "-j", std::to_string(affinity_cpus())});
        const std::string as = as_user_ ? " as " + options_.user : "";
        std::printf("%sbuilding lab%s\n", layout_.prefix.c_str(), as.c_str());
        std::error_code ec;
        fs::remove(lab_, ec);
        fs::path log = fs::path(work_->path()) / "build.log";
        if (run_logged(command, log, false) == 0 && access(lab_.c_str(), X_OK) == 0) return true;
        if (layout_.format == ResultsFormat::Gradescope &&
            build_without_labs_at_fault(command, log))
            return true;
        not_graded(layout_.format == ResultsFormat::PrairieLearn
                       ? "the submission does not build (the compiler's message is under Output)"
                       : "the submission does not build (the compiler's message is at the top "
                         "of the results)",
                   log.string());
        return false;
    }

    // What runs a compiler as the user, before its command; none unless as_user_.
    std::vector<std::string> compile_as_user() const {
        if (!as_user_) return {};
        // A compiler cache, where the image has one, is root's: the user compiles plainly.
        return {"runuser", "-u", options_.user, "--", "env", "CCACHE_DISABLE=1"};
    }

    // Gradescope, after a failed build: the labs whose C++ does not compile
    // (each file compiled alone, as the user) are built from their starting
    // code, so that `lab` builds for the others, and are graded as not built
    // (course grade --not-built). False when no lab's C++ is at fault, or
    // `lab` still does not build (`log` is then that build's).
    bool build_without_labs_at_fault(const std::vector<std::string>& command, fs::path& log) {
        const std::vector<std::string> files = read_lines(source_ / "student_files.txt");
        const fs::path versions = source_ / "student_versions", work = work_->path();
        std::string as;
        for (const std::string& word : compile_as_user()) as += fw::shell_quote(word) + " ";
        not_built_ = labs_not_compiling(source_, files, versions, as, work);
        if (not_built_.empty()) return false;
        for (const std::string& rel : files)
            if (not_built_.count(lab_folder(rel)) && fs::path(rel).extension() == ".cpp" &&
                !copy_contents(versions / rel, source_ / rel))
                return false;
        for (const auto& [lab, said] : not_built_)
            std::printf(
                "%s%s does not compile: built from its starting code for the other labs; "
                "it scores 0\n",
                layout_.prefix.c_str(), lab.c_str());
        log = work / "build-again.log";
        if (run_logged(command, log, false) != 0 || access(lab_.c_str(), X_OK) != 0) return false;
        report::write_text_file((work / "not-built.json").string(),
                                nlohmann::json(not_built_).dump() + "\n");
        return true;
    }

    // With one worker (no --jobs): no lab's own child, whose log reaches the
    // results, runs beside a child given the course's text of a shader
    // (grading/diagnosis/file_isolation.hpp).
    void grade() {
        std::vector<std::string> command = {own_path(),  "grade",
                                            "--lab",     lab_.string(),
                                            "--out",     (results_ / "grade").string(),
                                            "--timeout", options_.timeout};
        std::string shown = "course grade --timeout " + options_.timeout;
        if (as_user_) {
            command.insert(command.end(), {"--run-as", options_.user});
            shown += " --run-as " + options_.user;
        }
        // The shader cache setup.sh warmed beside course (root's, like course).
        const fs::path cache = fs::path(own_path()).parent_path() / "shader-cache";
        if (fs::is_directory(cache)) {
            command.insert(command.end(), {"--shader-cache", cache.string()});
            shown += " --shader-cache " + cache.filename().string();
        }
        if (layout_.format == ResultsFormat::PrairieLearn) {
            command.insert(command.end(), {"--format", "prairielearn"});
            shown += " --format prairielearn";
        } else {
            command.insert(command.end(), {"--hidden-as", name_of(options_.hidden_as)});
            shown += std::string(" --hidden-as ") + name_of(options_.hidden_as);
        }
        if (!not_built_.empty()) {
            command.insert(command.end(),
                           {"--not-built", (fs::path(work_->path()) / "not-built.json").string()});
            shown += " --not-built not-built.json";
        }
        for (const std::string& lab : options_.labs) {
            command.push_back(lab);
            shown += " " + lab;
        }
        // The log keeps the sandbox's layers (bench/bench_gradescope.sh reads them).
        command.push_back("--verbose");
        shown += " --verbose";
        std::printf("%s%s\n", layout_.prefix.c_str(), shown.c_str());
        const fs::path log = fs::path(work_->path()) / "grade.log";
        const int status = run_logged(command, log, true);
        std::error_code ec;
        if (status <= 1 && fs::exists(results_ / "grade" / "results.json")) {
            fs::copy_file(results_ / "grade" / "results.json", results_ / "results.json",
                          fs::copy_options::overwrite_existing, ec);
            if (!ec) return;
        }
        not_graded("course grade failed (exit status " + std::to_string(status) +
                       "), so nothing was graded; please tell the course staff",
                   log.string());
    }

    static std::string own_path() {
        std::error_code ec;
        const fs::path self = fs::read_symlink("/proc/self/exe", ec);
        if (ec) throw fw::Error("cannot find course's own executable (/proc/self/exe)");
        return self.string();
    }

    void write_fallback(const std::string& reason, const std::string& log,
                        const std::string& error) {
        std::string text;
        try {
            if (!log.empty()) text += log_tail(log, 200) + "\n";
        } catch (const std::exception& e) {
            text += e.what() + std::string("\n");
        }
        text += "\n" + error + "\n";
        std::error_code ec;
        fs::create_directories(results_, ec);
        report::write_text_file((results_ / "results.json").string(),
                                fallback_json(layout_, reason, text));
    }

    AutogradeOptions options_;
    Layout layout_;
    fs::path source_, results_, lab_;
    bool as_user_;                   // build and grade as options_.user (root, and the user exists)
    std::unique_ptr<WorkDir> work_;  // for the logs
    // The labs whose C++ did not compile, by folder: what the compiler said.
    std::map<std::string, std::string> not_built_;
};

}  // namespace

int autograde_command(const AutogradeOptions& options) {
    const auto start = std::chrono::steady_clock::now();
    const Layout layout = resolve_layout(options);
    // course grades with these checkpoints and references; `lab` reads its
    // shaders from the tree it was built from.
    setenv("LAB_ROOT", layout.data.c_str(), 1);
    setenv("LAB_SOURCES", layout.source.c_str(), 1);
    unsetenv("LAB_SHADER_DIR");
    Autograder autograder(options, layout);
    try {
        autograder.run();
    } catch (const std::exception& e) {
        autograder.not_graded(std::string("the autograder failed: ") + e.what(), "");
    }
    const auto seconds =
        std::chrono::duration_cast<std::chrono::seconds>(std::chrono::steady_clock::now() - start);
    std::printf("%sdone in %lld s\n", layout.prefix.c_str(),
                static_cast<long long>(seconds.count()));
    return 0;
}

}  // namespace grading
