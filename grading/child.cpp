#include "grading/child.hpp"

#include <fcntl.h>
#include <grp.h>
#include <poll.h>
#include <pwd.h>
#include <signal.h>
#include <sys/prctl.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <thread>

#include "framework/error.hpp"

extern char** environ;

namespace grading {

namespace fs = std::filesystem;

namespace {

std::string mib_text(std::uint64_t bytes) { return std::to_string(bytes / kMiB) + " MiB"; }

std::string seconds_text(double s) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", s);
    return buf;
}

// After fork() in a threaded program only async-signal-safe calls may run
// until exec: no malloc, no stdio. These write a fixed message and the errno.
void child_fail(const char* what) {
    int e = errno;
    char digits[16];
    int n = 0;
    do digits[n++] = static_cast<char>('0' + e % 10);
    while ((e /= 10) > 0 && n < 15);
    const char* prefix = "course: in the child, before running the lab: ";
    ssize_t ignored = write(2, prefix, std::strlen(prefix));
    ignored = write(2, what, std::strlen(what));
    ignored = write(2, " failed, errno ", 15);
    while (n > 0) ignored = write(2, &digits[--n], 1);
    ignored = write(2, "\n", 1);
    (void)ignored;
    _exit(126);
}

void switch_user(const RunAsUser& user) {
    // Groups first: after setuid the process may no longer change them.
    if (setgroups(user.groups.size(), user.groups.data()) != 0) child_fail("setgroups");
    if (setgid(user.gid) != 0) child_fail("setgid");
    if (setuid(user.uid) != 0) child_fail("setuid");
    if (getuid() != user.uid || geteuid() != user.uid || getegid() != user.gid)
        child_fail("setuid check");
}

// Bytes in regular files under `dir`, not following links.
std::uint64_t directory_bytes(const std::string& dir) {
    std::uint64_t total = 0;
    std::error_code ec;
    for (fs::recursive_directory_iterator
             it(dir, fs::directory_options::skip_permission_denied, ec),
         end;
         !ec && it != end; it.increment(ec)) {
        struct stat st;
        if (lstat(it->path().c_str(), &st) == 0 && S_ISREG(st.st_mode))
            total += static_cast<std::uint64_t>(st.st_size);
    }
    return total;
}

void set_limit(int resource, rlim_t value, const char* name) {
    struct rlimit r {
        value, value
    };
    if (setrlimit(resource, &r) != 0) child_fail(name);
}

}  // namespace

std::string signal_status(int signal) {
    const char* abbrev = sigabbrev_np(signal);
    return "crashed (signal " + std::to_string(signal) + ", " +
           (abbrev ? "SIG" + std::string(abbrev) : std::string("unknown")) + ")";
}

std::string indented_tail(const std::string& log, int lines) {
    std::vector<std::string> all;
    for (size_t pos = 0; pos < log.size();) {
        size_t nl = std::min(log.find('\n', pos), log.size());
        all.push_back(log.substr(pos, nl - pos));
        pos = nl + 1;
    }
    std::string out;
    for (size_t i = all.size() > size_t(lines) ? all.size() - size_t(lines) : 0; i < all.size();
         ++i)
        out += "    | " + (all[i].size() > 200 ? all[i].substr(0, 200) + "..." : all[i]) + "\n";
    return out;
}

RunAsUser lookup_user(const std::string& name) {
    if (geteuid() != 0)
        throw fw::UsageError(
            "--run-as " + name + " needs root, but course runs as uid " +
            std::to_string(geteuid()) +
            ": run course as root, or leave out --run-as to run the child as yourself");
    struct passwd pw, *found = nullptr;
    std::vector<char> buf(16384);
    if (getpwnam_r(name.c_str(), &pw, buf.data(), buf.size(), &found) != 0 || !found)
        throw fw::UsageError("--run-as: no user '" + name +
                             "' on this machine; name an existing unprivileged user, e.g. nobody");
    if (pw.pw_uid == 0)
        throw fw::UsageError("--run-as " + name +
                             ": that user is root, which would give the child "
                             "root's rights; name an unprivileged user, e.g. nobody");
    RunAsUser user{name, pw.pw_uid, pw.pw_gid, {}};
    int count = 64;
    user.groups.resize(static_cast<size_t>(count));
    while (getgrouplist(name.c_str(), pw.pw_gid, user.groups.data(), &count) < 0)
        user.groups.resize(static_cast<size_t>(count));
    user.groups.resize(static_cast<size_t>(count));
    return user;
}

bool user_can_access(const RunAsUser& user, const std::string& path, int mode) {
    pid_t pid = fork();
    if (pid < 0)
        throw fw::Error(std::string("cannot fork to test access: ") + std::strerror(errno));
    if (pid == 0) {
        switch_user(user);
        _exit(access(path.c_str(), mode) == 0 ? 0 : 1);
    }
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) > 1)
        throw fw::Error("cannot test what user '" + user.name + "' may do with '" + path +
                        "': switching to that user failed");
    return WEXITSTATUS(status) == 0;
}

WorkDir::WorkDir(const RunAsUser* user) {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/course-XXXXXX";
    std::vector<char> name(pattern.begin(), pattern.end());
    name.push_back('\0');
    if (!mkdtemp(name.data()))  // mode 0700
        throw fw::Error("cannot create a work directory '" + pattern +
                        "': " + std::strerror(errno) + "; set TMPDIR to a writable directory");
    path_ = name.data();
    user_ = user;
}

void WorkDir::hand_over() {
    if (user_ && chown(path_.c_str(), user_->uid, user_->gid) != 0)
        throw fw::Error("cannot give the work directory '" + path_ + "' to user '" + user_->name +
                        "': " + std::strerror(errno));
}

WorkDir::~WorkDir() {
    std::error_code ec;
    // Take the directory back first, so that nothing left of the user's can
    // write into it while it is removed; remove_all does not follow links.
    if (user_ && chown(path_.c_str(), 0, 0) == 0) chmod(path_.c_str(), 0700);
    fs::remove_all(path_, ec);
}

ChildRun run_child(const std::vector<std::string>& argv, const std::string& dir,
                   const ChildLimits& limits, const RunAsUser* user) {
    // Everything the forked process needs is built before fork().
    std::vector<char*> cargv;
    for (const std::string& a : argv) cargv.push_back(const_cast<char*>(a.c_str()));
    cargv.push_back(nullptr);
    std::vector<std::string> env_store;
    for (char** e = environ; *e; ++e) {
        std::string entry = *e;
        if (user && (entry.rfind("HOME=", 0) == 0 || entry.rfind("USER=", 0) == 0 ||
                     entry.rfind("LOGNAME=", 0) == 0))
            continue;
        env_store.push_back(entry);
    }
    if (user) {
        env_store.push_back("HOME=" + dir);
        env_store.push_back("USER=" + user->name);
        env_store.push_back("LOGNAME=" + user->name);
    }
    std::vector<char*> cenv;
    for (std::string& e : env_store) cenv.push_back(e.data());
    cenv.push_back(nullptr);
    // llvmpipe renders on every core and RLIMIT_CPU sums all threads: the
    // wall-clock timeout is the real limit; this one only stops a child that
    // outlives a killed course.
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    const rlim_t cpu_seconds = static_cast<rlim_t>(std::ceil(limits.timeout_seconds)) * cores + 10;

    int fds[2];
    if (pipe2(fds, O_CLOEXEC) != 0) throw fw::Error(std::string("pipe: ") + std::strerror(errno));
    int devnull = open("/dev/null", O_RDONLY | O_CLOEXEC);
    const pid_t parent = getpid();
    const auto start = std::chrono::steady_clock::now();
    pid_t pid = fork();
    if (pid < 0) throw fw::Error(std::string("cannot fork the lab child: ") + std::strerror(errno));
    if (pid == 0) {
        setpgid(0, 0);  // its own group: a timeout kills whatever it started too
        if (dup2(devnull, 0) < 0 || dup2(fds[1], 1) < 0 || dup2(fds[1], 2) < 0) child_fail("dup2");
        if (chdir(dir.c_str()) != 0) child_fail("chdir to the work directory");
        set_limit(RLIMIT_CPU, cpu_seconds, "RLIMIT_CPU");
        set_limit(RLIMIT_FSIZE, limits.file_cap, "RLIMIT_FSIZE");
        set_limit(RLIMIT_NOFILE, static_cast<rlim_t>(limits.open_files), "RLIMIT_NOFILE");
        set_limit(RLIMIT_CORE, 0, "RLIMIT_CORE");
#if !defined(__SANITIZE_ADDRESS__)
        // Not under AddressSanitizer: its shadow memory reserves terabytes of
        // address space, so any RLIMIT_AS would stop the (equally sanitized)
        // child before main().
        set_limit(RLIMIT_AS, limits.memory_cap, "RLIMIT_AS");
#endif
        if (user) switch_user(*user);
        // Killed with course (set after setuid, which clears it).
        if (prctl(PR_SET_PDEATHSIG, SIGKILL) != 0 || getppid() != parent) child_fail("prctl");
        execve(cargv[0], cargv.data(), cenv.data());
        child_fail("exec of the lab executable");
    }
    setpgid(pid, pid);  // also here, so that killpg works before the child gets to it
    close(fds[1]);
    if (devnull >= 0) close(devnull);
    fcntl(fds[0], F_SETFL, O_NONBLOCK);

    ChildRun run;
    std::uint64_t written = 0;
    bool killed = false, exited = false, eof = false;
    int wait_status = 0;
    auto elapsed = [&] {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    };
    auto stop = [&](const std::string& why) {
        if (!killed) run.status = why;
        killed = true;
        killpg(pid, SIGKILL);
    };
    double next_size_check = 0.25, drain_until = 0.0;
    char buf[65536];
    // Until it has exited and its pipe is drained (or held open past the
    // drain time by something it left behind).
    while (!(exited && (eof || elapsed() > drain_until))) {
        struct pollfd p {
            fds[0], POLLIN, 0
        };
        poll(&p, eof ? 0 : 1, 50);  // after EOF: just wait
        while (!eof) {
            ssize_t n = read(fds[0], buf, sizeof buf);
            if (n > 0) {
                written += static_cast<std::uint64_t>(n);
                run.log.append(buf, static_cast<size_t>(n));
                if (run.log.size() > 2 * limits.log_kept)
                    run.log.erase(0, run.log.size() - limits.log_kept);
                if (written > limits.output_cap)
                    stop("wrote more than " + mib_text(limits.output_cap) + " to stdout/stderr");
                continue;
            }
            if (n == 0) eof = true;
            break;
        }
        if (!exited && waitpid(pid, &wait_status, WNOHANG) == pid) {
            exited = true;
            killpg(pid, SIGKILL);  // anything it started and left running
            drain_until =
                elapsed() + 0.5;  // what is still in the pipe, unless something holds it open
        }
        if (!exited && elapsed() > limits.timeout_seconds)
            stop("timed out after " + seconds_text(limits.timeout_seconds) + " s");
        if (!exited && elapsed() > next_size_check) {
            next_size_check = elapsed() + 0.25;
            if (directory_bytes(dir) > limits.work_dir_cap)
                stop("wrote more than " + mib_text(limits.work_dir_cap) +
                     " into its work directory");
        }
    }
    close(fds[0]);
    run.seconds = elapsed();
    if (run.log.size() > limits.log_kept) run.log.erase(0, run.log.size() - limits.log_kept);
    if (killed) return run;
    if (WIFSIGNALED(wait_status)) {
        const int sig = WTERMSIG(wait_status);
        run.status = signal_status(sig);
        if (sig == SIGXFSZ)
            run.status += ": it wrote a file over the " + mib_text(limits.file_cap) + " limit";
        if (sig == SIGXCPU)
            run.status += ": it used more than " + std::to_string(cpu_seconds) + " s of CPU time";
    } else if (WIFEXITED(wait_status) && WEXITSTATUS(wait_status) != 0) {
        run.status = "exit status " + std::to_string(WEXITSTATUS(wait_status));
    }
    return run;
}

ChildOutputs::ChildOutputs(std::string dir, const ChildRun& run, const ChildLimits& limits)
    : dir_(std::move(dir)), run_(run) {
    const std::uint64_t total = directory_bytes(dir_);
    if (total > limits.work_dir_cap)
        too_large_ = "output too large: the child left " + std::to_string(total) +
                     " bytes in its work directory, more than the " +
                     mib_text(limits.work_dir_cap) + " limit";
}

std::string ChildOutputs::missing_reason(const std::string& name) const {
    if (!run_.ok()) return "the child " + run_.status + " before writing " + name;
    const std::string error_file = name.substr(0, name.find('.')) + ".error.txt";
    std::string text, why;
    if (error_file != name && read(error_file, 64 * 1024, text, why)) {
        while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
        return "the lab could not produce " + name + ": " + text;
    }
    return "the child exited normally without writing " + name;
}

bool ChildOutputs::read(const std::string& name, std::uint64_t limit, std::string& bytes,
                        std::string& why) const {
    if (!too_large_.empty()) {
        why = too_large_;
        return false;
    }
    const std::string file = dir_ + "/" + name;
    struct stat st;
    if (lstat(file.c_str(), &st) != 0) {
        why = errno == ENOENT ? missing_reason(name) : name + ": " + std::strerror(errno);
        return false;
    }
    // A link could point at a reference image or any file course may read.
    if (!S_ISREG(st.st_mode) || st.st_nlink != 1) {
        why = name + " is not a regular file with one link; refused";
        return false;
    }
    if (static_cast<std::uint64_t>(st.st_size) > limit) {
        why = "output too large: " + name + " is " + std::to_string(st.st_size) +
              " bytes, more than the limit of " + std::to_string(limit);
        return false;
    }
    int fd = open(file.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        why = "cannot read " + name + ": " + std::strerror(errno);
        return false;
    }
    bytes.clear();
    char buf[65536];
    ssize_t n;
    while ((n = ::read(fd, buf, sizeof buf)) > 0 && bytes.size() <= limit)
        bytes.append(buf, static_cast<size_t>(n));
    close(fd);
    if (bytes.size() > limit) {
        why = "output too large: " + name + " grew past " + std::to_string(limit) + " bytes";
        return false;
    }
    return true;
}

LabChild run_lab_child(const std::string& lab_binary, const nlohmann::json& job,
                       const std::string& backend, const ChildLimits& limits,
                       const RunAsUser* user) {
    LabChild child;
    child.dir = std::make_unique<WorkDir>(user);
    const std::string dir = child.dir->path();
    const std::string job_path = dir + "/JOB.json";
    {
        // Written while the directory is still course's: nothing of the
        // user's can have put a link in its place.
        std::ofstream out(job_path);
        if (!(out << job.dump(1) << "\n")) throw fw::Error("cannot write '" + job_path + "'");
    }
    child.dir->hand_over();
    std::vector<std::string> argv = {lab_binary, "grade-child", "--job", job_path, "--out", dir};
    if (!backend.empty()) argv.insert(argv.end(), {"--backend", backend});
    child.run = run_child(argv, dir, limits, user);
    child.outputs = std::make_unique<ChildOutputs>(dir, child.run, limits);
    if (child.run.ok() && !child.outputs->too_large().empty())
        child.run.status = child.outputs->too_large();
    return child;
}

}  // namespace grading
