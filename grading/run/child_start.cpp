#include "grading/run/child_start.hpp"

#include <fcntl.h>
#include <signal.h>
#include <sys/prctl.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <thread>

#include "grading/run/child.hpp"
#include "grading/run/job_gate.hpp"
#include "grading/run/run_as.hpp"
#include "grading/sandbox/isolation.hpp"

extern char** environ;

namespace grading {

namespace {

// After fork() in a threaded program only async-signal-safe calls may run
// until exec: no malloc, no stdio. These write a fixed message and the errno.
[[noreturn]] void child_fail(const char* what) {
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

void set_limit(int resource, rlim_t value, const char* name) {
    rlimit r{value, value};
    if (setrlimit(resource, &r) != 0) child_fail(name);
}

}  // namespace

namespace {

// llvmpipe renders on every core and RLIMIT_CPU sums all threads: the
// wall-clock timeout is the real limit; this one only stops a child that
// outlives a killed course.
rlim_t cpu_seconds_for(const ChildLimits& limits) {
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    return static_cast<rlim_t>(std::ceil(limits.timeout_seconds)) * cores + 10;
}

}  // namespace

ChildStart::ChildStart(const std::vector<std::string>& args, const std::string& work_dir,
                       const ChildLimits& child_limits, const RunAsUser* run_as,
                       const std::vector<std::string>& env)
    : dir(work_dir), limits(child_limits), user(run_as), cpu_seconds(cpu_seconds_for(limits)) {
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    std::vector<std::string> added = env;
    if (user) {
        added.push_back("HOME=" + dir);
        added.push_back("USER=" + user->name);
        added.push_back("LOGNAME=" + user->name);
    }
    auto replaced = [&added](const std::string& entry) {
        for (const std::string& a : added)
            if (entry.compare(0, a.find('=') + 1, a, 0, a.find('=') + 1) == 0) return true;
        return false;
    };
    for (char** e = environ; *e; ++e)
        if (!replaced(*e)) env_store.push_back(*e);
    env_store.insert(env_store.end(), added.begin(), added.end());
    for (std::string& e : env_store) envp.push_back(e.data());
    envp.push_back(nullptr);
}

[[noreturn]] void exec_child(const ChildStart& c) {
    setpgid(0, 0);  // its own group: a timeout kills whatever it started too
    // Out of the way of the descriptors set below, first.
    int gate = c.gate;
    if (gate >= 0 && gate <= kJobGateFd &&
        (gate = fcntl(gate, F_DUPFD_CLOEXEC, kJobGateFd + 1)) < 0)
        child_fail("fcntl of the job gate");
    if (c.cgroup_fds)
        for (const int fd : *c.cgroup_fds)
            if (write(fd, "0", 1) != 1) child_fail("joining the lab's cgroup");
    if (dup2(c.devnull, 0) < 0 || dup2(c.out, 1) < 0 || dup2(c.out, 2) < 0) child_fail("dup2");
    // Already kOutputFd, the descriptor keeps its close-on-exec flag: cleared.
    if (c.outputs >= 0 &&
        (c.outputs == kOutputFd ? fcntl(kOutputFd, F_SETFD, 0) : dup2(c.outputs, kOutputFd)) < 0)
        child_fail("dup2 of the output descriptor");
    if (gate >= 0 && dup2(gate, kJobGateFd) < 0) child_fail("dup2 of the job gate");
    if (chdir(c.dir.c_str()) != 0) child_fail("chdir to the work directory");
    set_limit(RLIMIT_CPU, c.cpu_seconds, "RLIMIT_CPU");
    set_limit(RLIMIT_FSIZE, c.limits.file_cap, "RLIMIT_FSIZE");
    set_limit(RLIMIT_NOFILE, static_cast<rlim_t>(c.limits.open_files), "RLIMIT_NOFILE");
    set_limit(RLIMIT_CORE, 0, "RLIMIT_CORE");
#if !defined(__SANITIZE_ADDRESS__)
    // Not under AddressSanitizer: its shadow memory reserves terabytes of
    // address space, so any RLIMIT_AS would stop the (equally sanitized)
    // child before main().
    set_limit(RLIMIT_AS, c.limits.memory_cap, "RLIMIT_AS");
#endif
    // From here on the lab's own process, in new namespaces under an init.
    if (c.limits.namespaces) enter_namespaces(child_fail);
    if (c.user) {
        // Counted per user at each fork: a fork bomb stops here.
        set_limit(RLIMIT_NPROC, kRunAsProcesses, "RLIMIT_NPROC");
        switch_user(*c.user, child_fail);
    }
    // Killed with course, or with the namespace's init (set after setuid,
    // which clears it).
    if (prctl(PR_SET_PDEATHSIG, SIGKILL) != 0 || (!c.limits.namespaces && getppid() != c.parent))
        child_fail("prctl");
    // Last: from here on no socket but AF_UNIX, no ptrace, ... (sandbox.hpp).
    if (c.filter && !c.filter->install()) child_fail("installing the seccomp filter");
    execve(c.argv[0], c.argv.data(), c.envp.data());
    child_fail("exec of the lab executable");
}

}  // namespace grading
