// Running one `lab grade-child` (framework/runner/grade_child.hpp) as an
// untrusted process: its own process group, a wall-clock timeout, resource
// limits, a cap on what it may print and write, optionally another user. What
// it leaves in its work directory is read back only through ChildOutputs,
// which refuses links, special files and anything over its size limit.
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <functional>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "grading/results/results.hpp"
#include "grading/sandbox/limits.hpp"

namespace grading {

// Throws fw::UsageError when not root or when there is no such user.
RunAsUser lookup_user(const std::string& name);
// Whether `user` may access `path` with `mode` (R_OK, W_OK, X_OK), tested by
// a process running as that user.
bool user_can_access(const RunAsUser& user, const std::string& path, int mode);

struct ChildRun {
    LabStatus status;  // LabResult::status
    std::string log;   // the last log_kept bytes of stdout + stderr
    double seconds = 0.0;
    bool ok() const { return status.ok(); }
};

// A fresh work directory under $TMPDIR (or /tmp), mode 0700, course's until
// hand_over() gives it to `user` (when given); removed with everything in it
// when the object goes.
class WorkDir {
public:
    explicit WorkDir(const RunAsUser* user);
    ~WorkDir();
    WorkDir(const WorkDir&) = delete;
    WorkDir& operator=(const WorkDir&) = delete;
    const std::string& path() const { return path_; }
    // Gives the directory, and everything course put in it, to the user.
    void hand_over();

private:
    std::string path_;
    const RunAsUser* user_ = nullptr;
};

// For a child that grades several labs in turn: the file whose appearance
// ends each lab (its child.json, renamed into place when the lab is done),
// and, as they appear, each ended lab's seconds and output. Each lab's
// timeout and caps on output and on what it adds to the work directory
// count from the end of the lab before it, as if it ran alone. `on_end`,
// when set, is called with a lab's index as soon as it has ended, on the
// thread that watches the child.
struct LabMarks {
    std::vector<std::string> files;
    struct Ended {
        double seconds = 0.0;
        std::string log;
    };
    std::vector<Ended> ended;
    std::function<void(size_t)> on_end;
};

// What a child sends on its output descriptor (`lab grade-child --output-fd`,
// always kOutputFd in the child) instead of writing files: records
// "OUTPUT SIZE PATH\n" followed by SIZE bytes, each standing for the file PATH
// in the work directory `dir` (DIR/NAME or DIR/I/NAME, NAME without a slash).
// No file, and no page cache, is made for a frame. read() takes what the pipe
// holds, on the thread that watches the child; a record over the per-file
// cap, more bytes since the lab began than the work directory's cap, or
// anything that is not a record stops the child (the reason in `why`). A
// record cut short by the child's end is dropped, like a file never written.
constexpr int kOutputFd = 3;
// Told of each record as soon as it is complete, on the watching thread:
// its PATH and its bytes (a copy is the callee's to make).
using RecordDone = std::function<void(const std::string& path, const std::string& bytes)>;
class StreamedOutputs {
public:
    explicit StreamedOutputs(std::string dir, RecordDone done = {})
        : dir_(std::move(dir)), done_(std::move(done)) {}
    // Reads until the pipe is empty (`all`) or for at most 16 MiB; false
    // with `why` when the child must be stopped, and then never reads again.
    bool read(int fd, const ChildLimits& limits, bool all, std::string& why);
    bool eof() const { return eof_; }
    // Bytes of the records begun since the last lab_began(): its share of the
    // work directory's cap.
    std::uint64_t lab_bytes() const { return received_ - lab_base_; }
    void lab_began() { lab_base_ = received_; }
    // The outputs of `sub` (the work directory itself or DIR/I), by NAME,
    // removed from here.
    std::map<std::string, std::string> take(const std::string& sub);

private:
    bool fill(int fd, const ChildLimits& limits, bool all, std::string& why);
    bool header(const ChildLimits& limits, std::string& why);
    void completed();
    std::string dir_;
    RecordDone done_;
    std::map<std::string, std::string> files_;  // by PATH
    std::string pending_;                       // read, not yet a header or body
    std::string* body_ = nullptr;               // the record being filled
    std::string body_path_;
    size_t got_ = 0;
    std::uint64_t received_ = 0, lab_base_ = 0;
    bool eof_ = false;
};

// Runs argv[0] with argv in `dir` and waits for it within the limits. `env`
// ("NAME=value") is added to course's environment, replacing what it names.
// With `streamed`, the child's kOutputFd is a pipe read into it; with
// `job_gate`, that descriptor is the child's kJobGateFd (job_gate.hpp).
ChildRun run_child(const std::vector<std::string>& argv, const std::string& dir,
                   const ChildLimits& limits, const RunAsUser* user,
                   const std::vector<std::string>& env = {}, LabMarks* marks = nullptr,
                   StreamedOutputs* streamed = nullptr, int job_gate = -1);

// The files a finished child left, and the outputs it sent instead of files
// (StreamedOutputs::take), read with limits. Every failure is a sentence fit
// for a check's output.
class ChildOutputs {
public:
    ChildOutputs(std::string dir, const ChildRun& run, const ChildLimits& limits,
                 std::map<std::string, std::string> streamed = {});

    // The bytes of `name`, or false and `why`: missing (and then why: the
    // child crashed, timed out, or wrote NAME.error.txt instead), not a regular
    // file, or over `limit` bytes ("output too large").
    bool read(const std::string& name, std::uint64_t limit, std::string& bytes,
              std::string& why) const;
    // The same, without a copy of what the child sent: `bytes` views the
    // sent record, or `storage` where the output is a file. Valid while this
    // object and `storage` are.
    bool read_view(const std::string& name, std::uint64_t limit, std::string_view& bytes,
                   std::string& storage, std::string& why) const;
    // Why there is no `name` when the child did not write it.
    std::string missing_reason(const std::string& name) const;
    // Non-empty when the work directory as a whole is over its cap.
    const std::string& too_large() const { return too_large_; }
    // How the child ended.
    const LabStatus& status() const { return run_.status; }

private:
    // An output the child left as a file in its work directory.
    bool read_file(const std::string& name, std::uint64_t limit, std::string& bytes,
                   std::string& why) const;
    std::string dir_;
    ChildRun run_;
    std::map<std::string, std::string> streamed_;  // by name, as a file in dir_ would be
    std::string too_large_;  // set when the directory as a whole is over its cap
};

// The `lab` grade-child run for one job: writes JOB.json into a fresh work
// directory, runs the child there and keeps the directory for reading.
struct LabChild {
    std::shared_ptr<WorkDir> dir;  // shared by the labs of one child (run_lab_children)
    ChildRun run;
    // Shared: a child's last lab is judged as it ends, and again with what
    // the child printed after it, on the same outputs (run_lab_children).
    std::shared_ptr<ChildOutputs> outputs;
    // The child's Mesa made its shader cache under a key the --shader-cache
    // did not hold (seed_key_missed), so it compiled its shaders afresh.
    bool cache_missed = false;
};
//
// Mesa's shader cache: with `shader_cache` empty, the child uses Mesa's default
// (under its HOME, which --run-as makes the fresh work directory: always
// cold). Otherwise it is a single-file Mesa cache directory (course
// warm-cache), and the child starts from a private copy of it, so that no lab
// can change what another lab's shaders compile to; with `shared`, the
// child writes into the directory itself (only for warming it).
struct ShaderCache {
    std::string dir;
    bool shared = false;
    // The keys of Mesa's caches in `dir` (mesa_cache_keys), listed once
    // before grading, for seed_key_missed.
    std::set<std::string> mesa_keys;
};
// The keys of the Mesa shader caches in `dir` (single-file caches, one
// folder each under mesa_shader_cache_sf).
std::set<std::string> mesa_cache_keys(const std::string& dir);
// Whether a child that started from a private copy of `cache` in
// `work_dir` made a Mesa cache of a key the copy did not have: Mesa's
// llvmpipe keys its cache by the CPU (model and features, the CPUs
// installed and those the process may use), so a cache warmed where these
// differ serves nothing. False for a shared cache, or one without Mesa's
// (no `mesa_keys`).
bool seed_key_missed(const ShaderCache& cache, const std::string& work_dir);
// `done`, when given, is told of each output record as it arrives
// (StreamedOutputs), for work that need not wait for the lab's end.
LabChild run_lab_child(const std::string& lab_binary, const nlohmann::json& job,
                       const std::string& backend, const ChildLimits& limits, const RunAsUser* user,
                       const ShaderCache& shader_cache = {}, const RecordDone& done = {});
// The same for a job already in its file's text.
LabChild run_lab_child(const std::string& lab_binary, const std::string& job_text,
                       const std::string& backend, const ChildLimits& limits, const RunAsUser* user,
                       const ShaderCache& shader_cache = {}, const RecordDone& done = {});

// Several labs in one child, in turn (`lab grade-child` with a --job and
// --out for each), each in a subdirectory of one work directory, for the
// cost of one process start. A lab that did not end normally there (the
// child crashed, hung or broke a limit in it, or ended before it) is graded
// again in a child of its own, and the labs after it in another child, so
// that a lab's result never depends on the labs beside it. `ready` gets each
// job's index and result as soon as it is known (a lab that ended in the
// child while the child goes on with the next), on the calling thread or the
// one watching the child (the last lab too, as the child exits). `ready`
// gets a lab a second time, to replace the first: the last lab with what the
// child printed after it added to its log, when it printed anything; every
// lab, each graded again alone, when the child fails after its last lab.
// `done` as run_lab_child's.
using LabReady = std::function<void(size_t, LabChild&&)>;
void run_lab_children(const std::string& lab_binary, const std::vector<nlohmann::json>& jobs,
                      const std::string& backend, const ChildLimits& limits, const RunAsUser* user,
                      const ShaderCache& shader_cache, const LabReady& ready,
                      const RecordDone& done = {});
// The same for the labs `labs` (their ids) whose jobs are not yet planned:
// the child starts at once, and `feed`, on a thread of its own, plans them
// and gives each job's text (any order, from any thread) as it is made; the
// child opens lab i's job once it and those before it are given
// (job_gate.hpp). `ready` is called for lab i only after `feed` gave it, and
// sees what the feed made before it. What `feed` throws is thrown here once
// the child has ended.
using JobGive = std::function<void(size_t, std::string)>;
using JobFeed = std::function<void(const JobGive&)>;
void run_lab_children(const std::string& lab_binary, const std::vector<std::string>& labs,
                      const JobFeed& feed, const std::string& backend, const ChildLimits& limits,
                      const RunAsUser* user, const ShaderCache& shader_cache, const LabReady& ready,
                      const RecordDone& done = {});

// Bytes in regular files under `dir`, not following links.
std::uint64_t directory_bytes(const std::string& dir);

// "crashed (signal 11, SIGSEGV)".
std::string signal_status(int signal);

// The last `lines` lines of a child's log, indented and cut to 200
// characters each, for the console.
std::string indented_tail(const std::string& log, int lines);

}  // namespace grading
