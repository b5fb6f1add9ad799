// `course grade` (docs/contract.md, `course grade`): one `lab grade-child` per lab, judged
// by course from the child's raw outputs, then the reports.
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <future>
#include <map>
#include <mutex>
#include <optional>
#include <set>

#include "framework/error.hpp"
#include "framework/text.hpp"
#include "grading/commands/commands.hpp"
#include "grading/commands/grade_setup.hpp"
#include "grading/commands/lab_shares.hpp"
#include "grading/commands/lab_sources.hpp"
#include "grading/diagnosis/file_isolation.hpp"
#include "grading/diagnosis/state_diff.hpp"
#include "grading/judge/checks.hpp"
#include "grading/judge/course_seed.hpp"
#include "grading/platforms/autograder.hpp"
#include "grading/platforms/compile_units.hpp"
#include "grading/release/release.hpp"
#include "grading/report/report_text.hpp"
#include "grading/report/reports.hpp"
#include "grading/run/parallel.hpp"
#include "grading/sandbox/isolation.hpp"
#include "grading/sandbox/sandbox.hpp"

namespace grading {

namespace fs = std::filesystem;

namespace {

// User and system seconds of getrusage(who); negative when it fails.
double cpu_seconds(int who) {
    rusage usage{};
    if (getrusage(who, &usage) != 0) return -1.0;
    auto seconds = [](const timeval& t) { return double(t.tv_sec) + double(t.tv_usec) / 1e6; };
    return seconds(usage.ru_utime) + seconds(usage.ru_stime);
}

// A grading's wall time, and course's CPU and its children's, since it
// began. Both CPU counts go on across exec() (scripts/grade.sh execs course
// after its build, whose compilers would count as children), hence the
// figures at the start.
struct RunClock {
    std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
    double self = cpu_seconds(RUSAGE_SELF);
    double children = cpu_seconds(RUSAGE_CHILDREN);

    // Into `run`, once every child has been waited for.
    void stop(GradeRun& run) const {
        const RunClock now;
        run.seconds = std::chrono::duration<double>(now.start - start).count();
        if (self >= 0.0 && now.self >= 0.0) run.course_cpu_seconds = now.self - self;
        if (children >= 0.0 && now.children >= 0.0)
            run.children_cpu_seconds = now.children - children;
    }
};

void set_owner_mode(const std::string& path, mode_t mode) {
    if (chown(path.c_str(), 0, 0) != 0 || chmod(path.c_str(), mode) != 0)
        throw fw::Error("cannot make '" + path + "' root's with mode " + std::to_string(mode) +
                        ": " + std::strerror(errno));
}

// The output directory and its per-lab image folders. With --run-as, the
// child's user must neither read a reference nor write a result: course
// makes every labs/*/reference folder (course's own tree) root's with mode
// 0700, the output directory root's 0755 and the image folders, which hold
// copies of references, 0700; then checks all that as the user.
void prepare(const std::string& out, const std::vector<LabData>& all,
             const std::vector<LabData>& graded, const std::string& lab_binary,
             const RunAsUser* user) {
    const bool created = !fs::exists(out);
    fs::create_directories(out);
    if (user && created) set_owner_mode(out, 0755);
    for (const LabData& lab : graded) {
        // Kept from a grading before, its files written again in place
        // (judge/report_files.hpp); anything but a folder there is replaced.
        const std::string dir = out + "/" + lab.id;
        if (!fs::is_directory(fs::symlink_status(dir))) fs::remove_all(dir);
        fs::create_directories(dir);
        if (user) set_owner_mode(dir, 0700);
    }
    if (!user) return;
    for (const LabData& lab : all)
        if (fs::exists(lab.reference_dir())) set_owner_mode(lab.reference_dir(), 0700);
    auto deny = [&](const std::string& what) {
        throw fw::UsageError("--run-as " + user->name + ": that user " + what);
    };
    if (user_can_access(*user, out, W_OK))
        deny("could write the output directory '" + out + "'; choose an --out it cannot write");
    for (const LabData& lab : all)
        if (fs::exists(lab.reference_dir()) && user_can_access(*user, lab.reference_dir(), R_OK))
            deny("could still read '" + lab.reference_dir() + "'");
    if (!user_can_access(*user, lab_binary, X_OK))
        deny("cannot run '" + lab_binary +
             "'; put the build where that user can read and execute it");
}

// The line `course grade` prints as a lab finishes, with the tail of its log
// when its child failed.
void print_progress(const LabResult& result) {
    const std::string score =
        fw::number_text(result.score()) + "/" + fw::number_text(result.max_score());
    std::printf("%-16s %9s  %5.1f s  %s\n", result.lab.c_str(), score.c_str(), result.seconds,
                result.status.text().c_str());
    if (!result.status.ok()) std::printf("%s", indented_tail(result.log, 12).c_str());
    std::fflush(stdout);
}

std::string backend_name(const GradeOptions& options) {
    const char* env_backend = std::getenv("LAB_BACKEND");
    return !options.backend.empty()      ? options.backend
           : env_backend && *env_backend ? env_backend
                                         : "auto";
}

// --shader-cache: the directory each child starts from a copy of.
ShaderCache shader_cache_of(const GradeOptions& options) {
    ShaderCache cache;
    if (options.shader_cache.empty()) return cache;
    if (!fs::is_directory(options.shader_cache))
        throw fw::UsageError("--shader-cache " + options.shader_cache +
                             ": no such directory; make it with course warm-cache");
    cache.dir = fs::absolute(options.shader_cache).string();
    cache.mesa_keys = mesa_cache_keys(cache.dir);
    return cache;
}

// For staff (the autograder's log): a --shader-cache that served a lab nothing.
void print_cache_missed(const GradeRun& run, const std::string& dir) {
    if (std::none_of(run.labs.begin(), run.labs.end(),
                     [](const LabResult& lab) { return lab.shader_cache_missed; }))
        return;
    std::fprintf(stderr,
                 "course: note: the shader cache %s was warmed on a machine whose CPUs differ "
                 "from this one's, so it served nothing and every shader was compiled afresh: "
                 "Mesa's llvmpipe keys its cache by the CPU's model and features, the number "
                 "of CPUs installed and the number this process may use. Warm it with course "
                 "warm-cache where grading runs, or on a machine with the same CPUs.\n",
                 dir.c_str());
}

// --sandbox strict: every layer but --run-as, or no grading at all.
void require_every_layer(const std::vector<SandboxLayer>& layers) {
    std::vector<std::string> missing;
    for (const SandboxLayer& layer : layers)
        if (!layer.active && layer.required_by_strict)
            missing.push_back(layer.name + ": " + layer.detail);
    if (!missing.empty())
        throw fw::EnvironmentError(
            "--sandbox strict: not grading, because these layers of the sandbox cannot be "
            "used here: " +
            fw::join(missing, "; ") +
            ". Run course as root with CAP_SYS_ADMIN and a cgroup hierarchy it may write, "
            "or grade with --sandbox auto");
}

// What every child is run with, the same for every lab of a run.
struct ChildSetup {
    std::string lab_binary, backend, out;
    ChildLimits limits;
    const RunAsUser* user = nullptr;
    ShaderCache cache;
    unsigned seed = 0;
};

// One lab's result from what its child left.
LabResult judge_child(const LabData& lab, const LabPlan& plan, const LabChild& child,
                      const std::string& out, int threads, EarlyUnits& early) {
    LabResult result;
    result.lab = lab.id;
    result.status = child.run.status;
    result.log = child.run.log;
    result.seconds = child.run.seconds;
    result.checks = judge_lab(lab, plan, *child.outputs, out, threads, &result.time, &early);
    report::read_page_images(result, out);
    child_seconds(*child.outputs, result.time);
    result.hidden_left_out = lab.file.hidden_checkpoints;
    result.hidden_points_left_out = lab.file.hidden_points;
    const StateLeftOut state = state_checks_left_out(lab);
    result.state_left_out = state.checks;
    result.state_points_left_out = state.points;
    result.shader_cache_missed = child.cache_missed;
    if (child.run.ok()) {
        const std::string shader_error = shader_error_status(*child.outputs);
        if (!shader_error.empty()) result.status = LabStatus::failed(shader_error);
    }
    return result;
}

// Labs graded by one child: planned here, on the worker, while the child
// starts and other workers' children run (a lab's unit checks' random
// arguments, seeded by the run's seed and the lab, are thousands of values),
// run in one child (a lab that breaks it is graded again alone:
// run_lab_children), and each judged, on as many threads as `threads()`
// says, as soon as it has ended, while the child goes on with the next.
std::vector<LabResult> grade_labs(const std::vector<const LabData*>& labs, const ChildSetup& setup,
                                  const std::function<int()>& threads, FreeLater& free_later) {
    std::vector<LabPlan> plans(labs.size());
    std::vector<nlohmann::json> jobs(labs.size());
    std::vector<double> plan_seconds(labs.size());
    std::vector<std::string> ids;
    for (const LabData* lab : labs) ids.push_back(lab->id);
    // Side by side, while the child starts: each plan depends on its lab and
    // the seed alone, and its job goes to the child as soon as it is made.
    const JobFeed plan_jobs = [&](const JobGive& give) {
        parallel_for(labs.size(), threads(), [&](size_t i) {
            const auto start = std::chrono::steady_clock::now();
            plans[i] = plan_lab(*labs[i], setup.seed, PlanFor::Grading);
            std::string text = plans[i].job.dump();
            // Kept: what file isolation reads (the lab and its renders), not
            // the thousands of unit cases the child has in its text.
            jobs[i] = std::move(plans[i].job);
            jobs[i].erase("units");
            plan_seconds[i] =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            give(i, std::move(text));
        });
    };
    std::vector<LabResult> results(labs.size());
    std::vector<char> ran(labs.size(), 0);  // the lab's child ran to its end
    // Each lab's unit results parsed as they come, while its frames are drawn.
    EarlyUnits early(labs.size());
    using Ended = std::pair<size_t, LabChild>;
    Pipeline<Ended> judging([&](Ended& e) {
        results[e.first] =
            judge_child(*labs[e.first], plans[e.first], e.second, setup.out, threads(), early);
        results[e.first].time.plan = plan_seconds[e.first];
        ran[e.first] = e.second.run.ok();
    });
    const LabReady ended = [&judging](size_t i, LabChild&& child) {
        judging.push({i, std::move(child)});
    };
    run_lab_children(setup.lab_binary, ids, plan_jobs, setup.backend, setup.limits, setup.user,
                     setup.cache, ended,
                     [&early](const std::string& path, const std::string& bytes) {
                         early.record_done(path, bytes);
                     });
    judging.finish();
    // Which file is wrong, for a lab whose frames failed
    // (grading/diagnosis/file_isolation.hpp): once its child is done, so that a
    // worker runs one child at a time.
    const ChildSpawn spawn{setup.lab_binary, setup.backend, setup.limits, setup.user, setup.cache};
    for (size_t i = 0; i < labs.size(); ++i) {
        if (!ran[i]) continue;
        // The judge's verdict on a frame rendered again.
        const auto passes = [&](const std::string& checkpoint, const ChildOutputs& outputs) {
            return frame_checks_pass(*labs[i], plans[i], checkpoint, outputs);
        };
        isolate_shader_mistakes(*labs[i], jobs[i], passes, results[i].checks, spawn);
    }
    free_later.free(std::move(plans));  // while the reports are made
    return results;
}

// Labs between their plan and their verdict: those sharing the cores.
class InFlight {
public:
    explicit InFlight(std::atomic<int>& count) : count_(count) { ++count_; }
    ~InFlight() { --count_; }
    InFlight(const InFlight&) = delete;
    InFlight& operator=(const InFlight&) = delete;

private:
    std::atomic<int>& count_;
};

// The labs of --not-built judged into run.labs, at their index in `labs`:
// no child runs them, every check fails, the status names the compiler's
// first error and the log is the start of what the compiler said. Returns
// the indices of the others, for the children.
std::vector<size_t> judge_not_built(const std::vector<LabData>& labs, const GradeOptions& options,
                                    GradeRun& run) {
    constexpr size_t kShown = 16 * 1024;
    const std::map<std::string, std::string> not_built = read_not_built(options.not_built);
    std::vector<size_t> others;
    for (size_t i = 0; i < labs.size(); ++i) {
        const auto said = not_built.find(labs[i].dir);
        if (said == not_built.end()) {
            others.push_back(i);
            continue;
        }
        const std::string first = first_error(said->second), log = said->second;
        run.labs[i] = not_run_lab(
            labs[i], "does not build" + (first.empty() ? "" : ": " + first),
            log.size() <= kShown ? log : log.substr(0, kShown) + "\n(the rest left out)\n",
            options.out);
        if (options.progress) print_progress(run.labs[i]);
    }
    return others;
}

// The labs of `labs` at `which`, each graded by a child into run.labs at the
// same index: --jobs workers, each with one child for its share of them
// (shares(): the costliest first, to the least loaded): one process start per
// worker, not per lab.
void grade_in_children(const std::vector<LabData>& labs, const std::vector<size_t>& which,
                       const ChildSetup& setup, const GradeOptions& options, GradeRun& run,
                       FreeLater& free_later) {
    std::mutex print_mutex;
    std::atomic<int> in_flight{0};
    const std::function<int()> threads = [&in_flight] { return judging_threads(in_flight); };
    const size_t workers = std::min<size_t>(which.size(), static_cast<size_t>(options.jobs));
    const std::vector<std::vector<size_t>> share_of = shares(labs, which, workers);
    parallel_for(workers, options.jobs, [&](size_t w) {
        std::vector<const LabData*> share;
        for (size_t k : share_of[w]) share.push_back(&labs[which[k]]);
        const InFlight flight(in_flight);
        std::vector<LabResult> results = grade_labs(share, setup, threads, free_later);
        for (size_t j = 0; j < results.size(); ++j) {
            LabResult& result = run.labs[which[share_of[w][j]]];
            result = std::move(results[j]);
            if (!options.progress) continue;
            std::lock_guard<std::mutex> lock(print_mutex);
            print_progress(result);
        }
    });
}

}  // namespace

int grade_command(const GradeOptions& options) {
    const RunClock timing;
    std::future<SandboxProbe> sandbox_probe = std::async(std::launch::async, probe_sandbox);
    const std::vector<LabData> all = discover_labs(source_root());
    std::vector<LabData> labs = labs_to_grade(all, options.labs);
    ChildSetup setup;
    setup.lab_binary = resolve_lab_binary(options.lab_binary);
    require_lab_up_to_date(setup.lab_binary, true, options.labs);
    setup.backend = options.backend;
    setup.out = options.out;
    std::optional<RunAsUser> user;
    if (!options.run_as.empty()) user = lookup_user(options.run_as);
    setup.user = user ? &*user : nullptr;
    prepare(options.out, all, labs, setup.lab_binary, setup.user);

    // Orphans of a lab's child (a setsid() daemon) come back to course.
    if (!become_subreaper()) throw fw::Error("cannot make course a child subreaper (prctl)");
    const CourseSeed seed = course_seed(source_root());
    setup.seed = seed.value;
    setup.cache = shader_cache_of(options);
    setup.limits.timeout_seconds = options.timeout_seconds;
    GradeRun run;
    run.backend = backend_name(options);
    run.seed = seed.value;
    run.seed_from = seed.from;
    const SandboxProbe sandbox = sandbox_probe.get();
    setup.limits.namespaces = sandbox.namespaces;
    setup.limits.cgroups = sandbox.cgroups.get();
    setup.limits.resident_cap = static_cast<std::uint64_t>(options.memory_mib) * kMiB;
    run.sandbox =
        sandbox_layers(setup.user, setup.limits, sandbox.namespaces_why, sandbox.cgroups_why);
    if (options.sandbox == GradeOptions::Sandbox::Strict) require_every_layer(run.sandbox);

    run.labs.resize(labs.size());
    FreeLater free_later;  // what grading no longer needs, freed while the reports are made
    grade_in_children(labs, judge_not_built(labs, options, run), setup, options, run, free_later);

    timing.stop(run);
    const auto reports_start = std::chrono::steady_clock::now();
    write_reports(run, options.out, {options.format, options.results, options.hidden_as});
    const double reports_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - reports_start).count();
    // The report's path last, where a student's eye ends.
    const size_t shown = options.verbose ? static_cast<size_t>(-1) : kTerminalFailedChecks;
    std::printf("%s", summary_table(run, options.verbose, shown).c_str());
    if (options.verbose) std::printf("%s", time_table(run, reports_seconds).c_str());
    std::printf("\nReport: %s\n", (fs::path(options.out) / "index.html").string().c_str());
    print_cache_missed(run, setup.cache.dir);
    return run.passed() ? 0 : 1;
}

}  // namespace grading
