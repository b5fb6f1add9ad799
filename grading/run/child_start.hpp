// The forked side of running a lab child (grading/run/child.hpp): what the
// process needs, built before fork(), and what it does between fork() and
// exec of the lab: its group, descriptors, limits, namespaces, user and
// seccomp filter. run_child() (child.cpp) is the parent's side.
#pragma once

#include <sys/resource.h>
#include <sys/types.h>
#include <unistd.h>

#include <string>
#include <vector>

#include "grading/sandbox/limits.hpp"
#include "grading/sandbox/sandbox.hpp"

namespace grading {

// Everything the forked process needs, built before fork(): argv and the
// environment as execve() takes them (course's environment, with HOME, USER
// and LOGNAME those of `user`), and its limits.
struct ChildStart {
    ChildStart(const std::vector<std::string>& args, const std::string& work_dir,
               const ChildLimits& child_limits, const RunAsUser* run_as,
               const std::vector<std::string>& env);

    std::vector<char*> argv;
    std::vector<std::string> env_store;
    std::vector<char*> envp;
    std::string dir;
    ChildLimits limits;
    const RunAsUser* user;
    rlim_t cpu_seconds = 0;  // RLIMIT_CPU: the timeout on every core, and more
    const SeccompFilter* filter = nullptr;
    const std::vector<int>* cgroup_fds = nullptr;  // "0" into each: join the lab's cgroup
    pid_t parent = getpid();
    int devnull = -1;  // its stdin
    int out = -1;      // its stdout and stderr
    int outputs = -1;  // its kOutputFd, when it sends its outputs
    int gate = -1;     // its kJobGateFd, when its jobs come after its start
};

// The forked child, until it runs the lab (never returns: the lab runs, or
// the child exits 126 saying which step failed).
[[noreturn]] void exec_child(const ChildStart& c);

}  // namespace grading
