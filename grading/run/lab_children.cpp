// Running `lab grade-child` for one lab, or for several in one child (child.hpp:
// run_lab_child, run_lab_children): the work directory, its job files and
// its shader cache, and what each lab left there.
#include <sys/stat.h>

#include <exception>
#include <filesystem>
#include <fstream>
#include <thread>

#include "framework/error.hpp"
#include "framework/text.hpp"
#include "grading/run/child.hpp"
#include "grading/run/job_gate.hpp"

namespace grading {

namespace fs = std::filesystem;

namespace {

void write_job(const std::string& path, const std::string& text) {
    // Written while the directory is still course's: nothing of the user's
    // can have put a link in its place.
    std::ofstream out(path);
    if (!(out << text << "\n")) throw fw::Error("cannot write '" + path + "'");
}

// The child's Mesa and NVIDIA shader caches: with a --shader-cache, a copy
// of it in the work directory (or the directory itself when shared), else
// the driver's default.
std::vector<std::string> shader_cache_env(const ShaderCache& shader_cache, const std::string& dir) {
    if (shader_cache.dir.empty()) return {};
    std::string cache = shader_cache.dir;
    if (!shader_cache.shared) {
        cache = dir + "/shader-cache";
        std::error_code ec;
        fs::copy(shader_cache.dir, cache, fs::copy_options::recursive, ec);
        if (ec)
            throw fw::Error("cannot copy the shader cache '" + shader_cache.dir +
                            "' into the lab's work directory: " + ec.message());
    }
    // Mesa's cache (llvmpipe, and Mesa's GPU drivers) and NVIDIA's, both
    // in the copy; a driver that keeps neither compiles every shader.
    return {"MESA_SHADER_CACHE_DIR=" + cache,       "MESA_DISK_CACHE_SINGLE_FILE=1",
            "MESA_SHADER_CACHE_DISABLE=false",      "__GL_SHADER_DISK_CACHE=1",
            "__GL_SHADER_DISK_CACHE_PATH=" + cache, "__GL_SHADER_DISK_CACHE_SKIP_CLEANUP=1"};
}

// A lab's outputs in `dir`, as the run left them and sent them.
void read_back(LabChild& child, const std::string& dir, const ChildLimits& limits,
               StreamedOutputs& streamed) {
    child.outputs = std::make_shared<ChildOutputs>(dir, child.run, limits, streamed.take(dir));
    if (child.run.ok() && !child.outputs->too_large().empty())
        child.run.status = LabStatus::failed(child.outputs->too_large());
}

// A work directory for several labs: lab i's job in DIR/i/JOB.json and its
// outputs in DIR/i, its child.json there the mark of its end. Returns the
// child's command line; the directories are in `dirs`.
std::vector<std::string> lay_out_labs(const WorkDir& dir, size_t count,
                                      const std::string& lab_binary, const std::string& backend,
                                      LabMarks& marks, std::vector<std::string>& dirs) {
    std::vector<std::string> argv = {lab_binary, "grade-child"};
    for (size_t i = 0; i < count; ++i) {
        const std::string lab_dir = dir.path() + "/" + std::to_string(i);
        if (mkdir(lab_dir.c_str(), 0700) != 0)
            throw fw::Error("cannot create '" + lab_dir + "' in the work directory");
        argv.insert(argv.end(), {"--job", lab_dir + "/JOB.json", "--out", lab_dir});
        marks.files.push_back(lab_dir + "/child.json");
        dirs.push_back(lab_dir);
    }
    if (!backend.empty()) argv.insert(argv.end(), {"--backend", backend});
    argv.insert(argv.end(), {"--output-fd", std::to_string(kOutputFd), "--job-gate-fd",
                             std::to_string(kJobGateFd)});
    return argv;
}

// The feed of jobs already made.
JobFeed given(const std::vector<std::string>& texts) {
    return [&texts](const JobGive& give) {
        for (size_t i = 0; i < texts.size(); ++i) give(i, texts[i]);
    };
}

// Lab i of a child of several labs, as it ended (`mark`): its outputs in
// DIR/i.
LabChild ended_lab(const std::shared_ptr<WorkDir>& dir, const LabMarks::Ended& mark, size_t i,
                   const ChildLimits& limits, StreamedOutputs& streamed,
                   const ShaderCache& shader_cache) {
    LabChild child;
    child.dir = dir;
    child.run.seconds = mark.seconds;
    child.run.log = mark.log;
    read_back(child, dir->path() + "/" + std::to_string(i), limits, streamed);
    child.cache_missed = seed_key_missed(shader_cache, dir->path());
    return child;
}

// The child, run while `feed` plans its jobs and gives them to `gate` on a
// thread of its own; what the feed throws is thrown once the child has ended.
ChildRun run_fed(const std::vector<std::string>& argv, const WorkDir& dir,
                 const ChildLimits& limits, const RunAsUser* user,
                 const std::vector<std::string>& env, LabMarks& marks, StreamedOutputs& streamed,
                 JobGate& gate, const JobFeed& feed) {
    std::exception_ptr feed_failed;
    std::thread feeder([&] {
        try {
            feed([&gate](size_t i, std::string text) { gate.give(i, std::move(text)); });
        } catch (...) {
            feed_failed = std::current_exception();
        }
        gate.end();
    });
    ChildRun run;
    try {
        run = run_child(argv, dir.path(), limits, user, env, &marks, &streamed, gate.child_end());
    } catch (...) {
        feeder.join();
        throw;
    }
    feeder.join();
    if (feed_failed) std::rethrow_exception(feed_failed);
    return run;
}

}  // namespace

std::set<std::string> mesa_cache_keys(const std::string& dir) {
    std::set<std::string> keys;
    std::error_code ec;
    for (fs::directory_iterator it(fs::path(dir) / "mesa_shader_cache_sf", ec), end;
         !ec && it != end; it.increment(ec))
        keys.insert(it->path().filename().string());
    return keys;
}

bool seed_key_missed(const ShaderCache& cache, const std::string& work_dir) {
    if (cache.shared || cache.mesa_keys.empty()) return false;
    for (const std::string& key : mesa_cache_keys(work_dir + "/shader-cache"))
        if (!cache.mesa_keys.count(key)) return true;
    return false;
}

LabChild run_lab_child(const std::string& lab_binary, const nlohmann::json& job,
                       const std::string& backend, const ChildLimits& limits, const RunAsUser* user,
                       const ShaderCache& shader_cache, const RecordDone& done) {
    return run_lab_child(lab_binary, job.dump(), backend, limits, user, shader_cache, done);
}

LabChild run_lab_child(const std::string& lab_binary, const std::string& job_text,
                       const std::string& backend, const ChildLimits& limits, const RunAsUser* user,
                       const ShaderCache& shader_cache, const RecordDone& done) {
    LabChild child;
    child.dir = std::make_shared<WorkDir>(user);
    const std::string dir = child.dir->path();
    const std::string job_path = dir + "/JOB.json";
    write_job(job_path, job_text);
    const std::vector<std::string> env = shader_cache_env(shader_cache, dir);
    child.dir->hand_over();
    std::vector<std::string> argv = {
        lab_binary, "grade-child", "--job",       job_path,
        "--out",    dir,           "--output-fd", std::to_string(kOutputFd)};
    if (!backend.empty()) argv.insert(argv.end(), {"--backend", backend});
    StreamedOutputs streamed(dir, done);
    child.run = run_child(argv, dir, limits, user, env, nullptr, &streamed);
    read_back(child, dir, limits, streamed);
    child.cache_missed = seed_key_missed(shader_cache, dir);
    return child;
}

void run_lab_children(const std::string& lab_binary, const std::vector<nlohmann::json>& jobs,
                      const std::string& backend, const ChildLimits& limits, const RunAsUser* user,
                      const ShaderCache& shader_cache, const LabReady& ready,
                      const RecordDone& done) {
    std::vector<std::string> labs, texts;
    for (const nlohmann::json& job : jobs) {
        labs.push_back(job.value("lab", "?"));
        texts.push_back(job.dump());
    }
    run_lab_children(lab_binary, labs, given(texts), backend, limits, user, shader_cache, ready,
                     done);
}

void run_lab_children(const std::string& lab_binary, const std::vector<std::string>& labs,
                      const JobFeed& feed, const std::string& backend, const ChildLimits& limits,
                      const RunAsUser* user, const ShaderCache& shader_cache, const LabReady& ready,
                      const RecordDone& done) {
    if (labs.size() == 1) {
        std::string text;
        feed([&text](size_t, std::string t) { text = std::move(t); });
        ready(0, run_lab_child(lab_binary, text, backend, limits, user, shader_cache, done));
    }
    if (labs.size() <= 1) return;

    const auto dir = std::make_shared<WorkDir>(user);
    LabMarks marks;
    std::vector<std::string> lab_dirs;
    const std::vector<std::string> argv =
        lay_out_labs(*dir, labs.size(), lab_binary, backend, marks, lab_dirs);
    const std::vector<std::string> env = shader_cache_env(shader_cache, dir->path());
    JobGate gate(lab_dirs, user);  // before the hand-over: course's own directories
    dir->hand_over();
    StreamedOutputs streamed(dir->path(), done);
    // Each lab is judged as soon as it has ended, while the child goes on
    // (the last while the child exits); the last is judged again, with what
    // the child printed after it (its exit, strays) in its log, when there
    // is any. A lab ends only once its job was given: its plan is there.
    LabChild last;
    marks.on_end = [&](size_t i) {
        gate.sync();
        LabChild child = ended_lab(dir, marks.ended[i], i, limits, streamed, shader_cache);
        if (i + 1 == labs.size()) last = child;
        ready(i, std::move(child));
    };
    const ChildRun run = run_fed(argv, *dir, limits, user, env, marks, streamed, gate, feed);
    const std::vector<std::string> jobs = gate.texts();
    const size_t ended = marks.ended.size();
    if (ended == labs.size()) {
        if (!run.log.empty()) {
            last.run.log += "\ncourse: after the last lab of a child that graded " +
                            fw::join(labs, ", ") + " in turn:\n" + run.log;
            ready(ended - 1, std::move(last));
        }
        // Every lab ended, but the child then did not end normally (a crash
        // on exit, ...): which lab's code broke it is unknown, so each is
        // graded again alone, its result replacing the first.
        if (!run.ok())
            for (size_t i = 0; i < labs.size(); ++i)
                ready(i, run_lab_child(lab_binary, jobs[i], backend, limits, user, shader_cache,
                                       done));
        return;
    }
    // The lab that broke the child, alone; then the rest, in one child again.
    ready(ended, run_lab_child(lab_binary, jobs[ended], backend, limits, user, shader_cache, done));
    const std::vector<std::string> rest_labs(labs.begin() + static_cast<long>(ended) + 1,
                                             labs.end());
    const std::vector<std::string> rest(jobs.begin() + static_cast<long>(ended) + 1, jobs.end());
    run_lab_children(
        lab_binary, rest_labs, given(rest), backend, limits, user, shader_cache,
        [&](size_t i, LabChild&& c) { ready(ended + 1 + i, std::move(c)); }, done);
}

}  // namespace grading
