// Running `lab grade-child` for one lab, or for several in one child (child.hpp:
// run_lab_child, run_lab_children): the work directory, its job files and
// its shader cache, and what each lab left there.
#include <sys/stat.h>

#include <filesystem>
#include <fstream>

#include "framework/error.hpp"
#include "framework/text.hpp"
#include "grading/run/child.hpp"

namespace grading {

namespace fs = std::filesystem;

namespace {

void write_job(const std::string& path, const nlohmann::json& job) {
    // Written while the directory is still course's: nothing of the user's
    // can have put a link in its place.
    std::ofstream out(path);
    if (!(out << job.dump() << "\n")) throw fw::Error("cannot write '" + path + "'");
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
    child.outputs = std::make_unique<ChildOutputs>(dir, child.run, limits, streamed.take(dir));
    if (child.run.ok() && !child.outputs->too_large().empty())
        child.run.status = LabStatus::failed(child.outputs->too_large());
}

// A work directory for several labs: lab i's job in DIR/i/JOB.json and its
// outputs in DIR/i, its child.json there the mark of its end. Returns the
// child's command line.
std::vector<std::string> lay_out_labs(const WorkDir& dir, const std::vector<nlohmann::json>& jobs,
                                      const std::string& lab_binary, const std::string& backend,
                                      LabMarks& marks) {
    std::vector<std::string> argv = {lab_binary, "grade-child"};
    for (size_t i = 0; i < jobs.size(); ++i) {
        const std::string lab_dir = dir.path() + "/" + std::to_string(i);
        if (mkdir(lab_dir.c_str(), 0700) != 0)
            throw fw::Error("cannot create '" + lab_dir + "' in the work directory");
        write_job(lab_dir + "/JOB.json", jobs[i]);
        argv.insert(argv.end(), {"--job", lab_dir + "/JOB.json", "--out", lab_dir});
        marks.files.push_back(lab_dir + "/child.json");
    }
    if (!backend.empty()) argv.insert(argv.end(), {"--backend", backend});
    argv.insert(argv.end(), {"--output-fd", std::to_string(kOutputFd)});
    return argv;
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
    LabChild child;
    child.dir = std::make_shared<WorkDir>(user);
    const std::string dir = child.dir->path();
    const std::string job_path = dir + "/JOB.json";
    write_job(job_path, job);
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
    auto alone = [&](size_t i) {
        ready(i, run_lab_child(lab_binary, jobs[i], backend, limits, user, shader_cache, done));
    };
    if (jobs.size() == 1) alone(0);
    if (jobs.size() <= 1) return;

    const auto dir = std::make_shared<WorkDir>(user);
    LabMarks marks;
    const std::vector<std::string> argv = lay_out_labs(*dir, jobs, lab_binary, backend, marks);
    std::vector<std::string> labs;
    for (const nlohmann::json& job : jobs) labs.push_back(job.value("lab", "?"));
    const std::vector<std::string> env = shader_cache_env(shader_cache, dir->path());
    dir->hand_over();
    StreamedOutputs streamed(dir->path(), done);
    // A lab that ended in the child, with `tail` added to its log.
    auto ended_lab = [&](size_t i, const std::string& tail) {
        LabChild child;
        child.dir = dir;
        child.run.seconds = marks.ended[i].seconds;
        child.run.log = marks.ended[i].log + tail;
        read_back(child, dir->path() + "/" + std::to_string(i), limits, streamed);
        child.cache_missed = seed_key_missed(shader_cache, dir->path());
        return child;
    };
    // Each lab but the last is judged while the child goes on; the last
    // takes what the child printed after it (its exit), and strays.
    marks.on_end = [&](size_t i) {
        if (i + 1 < jobs.size()) ready(i, ended_lab(i, ""));
    };
    const ChildRun run = run_child(argv, dir->path(), limits, user, env, &marks, &streamed);
    const size_t ended = marks.ended.size();
    if (ended == jobs.size()) {
        ready(ended - 1,
              ended_lab(ended - 1, run.log.empty()
                                       ? ""
                                       : "\ncourse: after the last lab of a child "
                                         "that graded " +
                                             fw::join(labs, ", ") + " in turn:\n" + run.log));
        // Every lab ended, but the child then did not end normally (a crash
        // on exit, ...): which lab's code broke it is unknown, so each is
        // graded again alone, its result replacing the first.
        if (!run.ok())
            for (size_t i = 0; i < jobs.size(); ++i) alone(i);
        return;
    }
    // The lab that broke the child, alone; then the rest, in one child again.
    alone(ended);
    const std::vector<nlohmann::json> rest(jobs.begin() + static_cast<long>(ended) + 1, jobs.end());
    run_lab_children(
        lab_binary, rest, backend, limits, user, shader_cache,
        [&](size_t i, LabChild&& c) { ready(ended + 1 + i, std::move(c)); }, done);
}

}  // namespace grading
