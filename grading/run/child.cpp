#include "grading/run/child.hpp"

#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <optional>

#include "framework/error.hpp"
#include "framework/text.hpp"
#include "grading/run/child_start.hpp"
#include "grading/sandbox/isolation.hpp"
#include "grading/sandbox/sandbox.hpp"

namespace grading {

namespace {

// The wall clock, as the kernel stamps a file's times with it (its coarse
// clock), in seconds.
double wall_seconds() {
    timespec now{};
    clock_gettime(CLOCK_REALTIME_COARSE, &now);
    return static_cast<double>(now.tv_sec) + static_cast<double>(now.tv_nsec) * 1e-9;
}

// The parent's side of a running child: keeps the tail of its output, and
// kills its whole process group, saying why, when it breaks a limit.
class ChildWatch {
public:
    using Clock = std::chrono::steady_clock;
    ChildWatch(pid_t pid, int out, const ChildStart& c, Clock::time_point start, LabMarks* marks,
               StreamedOutputs* streamed, int outputs)
        : pid_(pid),
          out_(out),
          outputs_(outputs),
          dir_(c.dir),
          limits_(c.limits),
          start_(start),
          marks_(marks),
          streamed_(streamed) {
        start_wall_ = last_end_wall_ = wall_seconds() - elapsed();  // a mark's clock at `start`
    }

    // Until the child has exited and its pipe is drained (or held open past
    // the drain time by something it left behind).
    void watch() {
        // With several labs, often enough that each lab's seconds are its own.
        const int tick_ms = marks_ ? 5 : 50;
        while (!(exited_ && ((eof_ && streamed_eof()) || elapsed() > drain_until_))) {
            // A pipe at its end is left out (-1): after both, just wait.
            pollfd p[2] = {{eof_ ? -1 : out_, POLLIN, 0},
                           {streamed_eof() ? -1 : outputs_, POLLIN, 0}};
            poll(p, 2, tick_ms);
            if (marks_) note_ended_labs();
            read_output();
            read_streamed(false);
            const pid_t waited = exited_ ? 0 : waitpid(pid_, &wait_status_, WNOHANG);
            if (waited < 0 && errno == ECHILD) {
                // Reaped by someone else: its end is unknown, and waiting
                // on would never end.
                exited_ = true;
                stop("ended unseen: course lost its exit status (a bug in course, not the lab)");
                drain_until_ = elapsed() + 0.5;
            } else if (waited == pid_) {
                exited_ = true;
                killpg(pid_, SIGKILL);  // anything it started and left running
                // What is still in the pipe, unless something holds it open.
                drain_until_ = elapsed() + 0.5;
            }
            if (!exited_) check_limits();
        }
        // A last lab that ended just before the child did.
        if (marks_) note_ended_labs();
        run_.seconds = elapsed();
        keep_tail(run_.log);
    }

    bool killed() const { return killed_; }
    int wait_status() const { return wait_status_; }
    ChildRun& run() { return run_; }

private:
    double elapsed() const { return std::chrono::duration<double>(Clock::now() - start_).count(); }

    void stop(const std::string& why) {
        if (!killed_) run_.status = LabStatus::failed(why);
        killed_ = true;
        killpg(pid_, SIGKILL);
    }

    void read_output() {
        char buf[65536];
        while (!eof_) {
            const ssize_t n = read(out_, buf, sizeof buf);
            if (n == 0) eof_ = true;
            if (n <= 0) return;
            written_ += static_cast<std::uint64_t>(n);
            run_.log.append(buf, static_cast<size_t>(n));
            if (run_.log.size() > 2 * limits_.log_kept)
                run_.log.erase(0, run_.log.size() - limits_.log_kept);
            if (written_ > limits_.output_cap)
                stop("wrote more than " + mib_text(limits_.output_cap) + " to stdout/stderr");
        }
    }

    bool streamed_eof() const { return !streamed_ || streamed_->eof(); }

    // What the child sent on its output descriptor: everything in the pipe
    // with `all`, else a share (so that a flood cannot hold up the limits).
    void read_streamed(bool all) {
        std::string why;
        if (streamed_ && !streamed_->read(outputs_, limits_, all, why)) stop(why);
    }

    // A lab whose mark is there has ended, all it printed and sent in the
    // pipes (written before the mark): that is its log and its outputs, and
    // the next lab's limits count from here. Its seconds end at the mark's
    // time, not at this look: under load two labs can end between two
    // looks, and the second would read 0 s. A time outside the child's run
    // so far (a mark's time can be set) is taken as the nearest within it.
    void note_ended_labs() {
        struct stat st;
        while (marks_->ended.size() < marks_->files.size() &&
               lstat(marks_->files[marks_->ended.size()].c_str(), &st) == 0) {
            read_output();
            read_streamed(true);
            const double now = elapsed();
            const double mark = static_cast<double>(st.st_mtim.tv_sec) +
                                static_cast<double>(st.st_mtim.tv_nsec) * 1e-9;
            const double end = std::clamp(mark, last_end_wall_, start_wall_ + now);
            keep_tail(run_.log);
            marks_->ended.push_back({end - last_end_wall_, std::move(run_.log)});
            last_end_wall_ = end;
            run_.log.clear();
            written_ = 0;
            lab_start_ = now;
            dir_base_ = directory_bytes(dir_);
            if (streamed_) streamed_->lab_began();
            if (marks_->on_end) marks_->on_end(marks_->ended.size() - 1);
        }
    }

    void keep_tail(std::string& log) const {
        if (log.size() > limits_.log_kept) log.erase(0, log.size() - limits_.log_kept);
    }

    void check_limits() {
        if (elapsed() - lab_start_ > limits_.timeout_seconds)
            stop("timed out after " + fw::number_text(limits_.timeout_seconds) + " s");
        if (elapsed() > next_size_check_) {
            next_size_check_ = elapsed() + 0.25;
            const std::uint64_t bytes = directory_bytes(dir_);
            const std::uint64_t sent = streamed_ ? streamed_->lab_bytes() : 0;
            if (bytes - std::min(dir_base_, bytes) + sent > limits_.work_dir_cap)
                stop("wrote more than " + mib_text(limits_.work_dir_cap) +
                     " into its work directory");
        }
    }

    pid_t pid_;
    int out_, outputs_;
    const std::string& dir_;
    const ChildLimits& limits_;
    Clock::time_point start_;
    LabMarks* marks_;
    StreamedOutputs* streamed_;
    double lab_start_ = 0.0;                         // when the lab now running began (marks_)
    double start_wall_ = 0.0, last_end_wall_ = 0.0;  // the wall clock at the start, the last mark
    std::uint64_t dir_base_ = 0;                     // the work directory's bytes then
    ChildRun run_;
    std::uint64_t written_ = 0;
    bool killed_ = false, exited_ = false, eof_ = false;
    int wait_status_ = 0;
    double next_size_check_ = 0.25, drain_until_ = 0.0;
};

// A pipe from a child: course keeps the read end (non-blocking, once
// keep_read_end() has closed its copy of the write end); both ends are
// closed however run_child() ends.
struct Pipe {
    int read_end = -1, write_end = -1;
    // `capacity`: bytes it holds (F_SETPIPE_SZ), where the system allows it.
    explicit Pipe(int capacity = 0) {
        int fds[2];
        if (pipe2(fds, O_CLOEXEC) != 0)
            throw fw::Error(std::string("pipe: ") + std::strerror(errno));
        read_end = fds[0];
        write_end = fds[1];
        if (capacity > 0) fcntl(write_end, F_SETPIPE_SZ, capacity);
    }
    ~Pipe() {
        for (const int fd : {read_end, write_end})
            if (fd >= 0) close(fd);
    }
    Pipe(const Pipe&) = delete;
    Pipe& operator=(const Pipe&) = delete;
    void keep_read_end() {
        close(write_end);
        write_end = -1;
        fcntl(read_end, F_SETFL, O_NONBLOCK);
    }
};

// How a child that was not killed ended, as ChildRun::status says it.
LabStatus exit_status(int wait_status, const ChildStart& c) {
    if (WIFSIGNALED(wait_status)) {
        const int sig = WTERMSIG(wait_status);
        std::string status = signal_status(sig);
        if (sig == SIGXFSZ)
            status += ": it wrote a file over the " + mib_text(c.limits.file_cap) + " limit";
        if (sig == SIGXCPU)
            status += ": it used more than " + std::to_string(c.cpu_seconds) + " s of CPU time";
        return LabStatus::failed(status);
    }
    if (WIFEXITED(wait_status) && WEXITSTATUS(wait_status) != 0)
        return LabStatus::failed("exit status " + std::to_string(WEXITSTATUS(wait_status)));
    return {};
}

}  // namespace

ChildRun run_child(const std::vector<std::string>& argv, const std::string& dir,
                   const ChildLimits& limits, const RunAsUser* user,
                   const std::vector<std::string>& env, LabMarks* marks, StreamedOutputs* streamed,
                   int job_gate) {
    static const SeccompFilter filter;  // built once, before any fork
    ChildStart start(argv, dir, limits, user, env);
    start.filter = &filter;
    start.gate = job_gate;
    if (marks) start.cpu_seconds *= std::max<rlim_t>(1, marks->files.size());
    std::unique_ptr<LabCgroup> cgroup;
    if (limits.cgroups) {
        cgroup =
            std::make_unique<LabCgroup>(*limits.cgroups, limits.resident_cap, limits.processes_cap);
        start.cgroup_fds = &cgroup->join_fds();
    }
    Pipe out;
    start.out = out.write_end;
    start.devnull = open("/dev/null", O_RDONLY | O_CLOEXEC);
    std::optional<Pipe> outputs;
    if (streamed) {
        outputs.emplace(1 << 20);  // a frame in one write, where the system allows it
        start.outputs = outputs->write_end;
    }
    const auto started = ChildWatch::Clock::now();
    const pid_t pid = fork_lab();
    if (pid < 0) throw fw::Error(std::string("cannot fork the lab child: ") + std::strerror(errno));
    if (pid == 0) exec_child(start);
    setpgid(pid, pid);  // also here, so that killpg works before the child gets to it
    if (start.devnull >= 0) close(start.devnull);
    out.keep_read_end();
    if (outputs) outputs->keep_read_end();

    ChildWatch watch(pid, out.read_end, start, started, marks, streamed,
                     outputs ? outputs->read_end : -1);
    watch.watch();
    ChildRun run = std::move(watch.run());
    if (!watch.killed()) run.status = exit_status(watch.wait_status(), start);
    lab_ended(pid);  // watch() has reaped it
    // Whatever it left running, setsid() or not, dies with its lab. With a
    // cgroup that is what is left in it (the lab itself is reaped), found and
    // killed first: then no process of the user outside it (another
    // program's) is touched, and the search below finds only what course
    // adopted from outside the cgroup, if anything.
    int strays = 0;
    if (cgroup) {
        strays = cgroup->kill_all();
        if (cgroup->oom_kills() > 0 && !run.ok())
            run.status =
                LabStatus::failed("killed for memory: more than " + mib_text(limits.resident_cap) +
                                  " in use (its cgroup's limit)");
    }
    strays += kill_strays(cgroup ? nullptr : user);
    if (strays > 0)
        run.log += "\ncourse: killed " + std::to_string(strays) +
                   " process(es) the lab left running after it ended\n";
    return run;
}

}  // namespace grading
