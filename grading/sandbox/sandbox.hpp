// The sandbox around each lab's child, in layers, each used where the machine
// allows it (docs/contract.md, `course`, Sandbox):
//   - everywhere: a seccomp filter (no sockets but AF_UNIX, no ptrace,
//     process_vm_readv/writev, keyctl, bpf, perf_event_open, mount, unshare,
//     kexec, modules, io_uring; each fails with EPERM), installed with
//     PR_SET_NO_NEW_PRIVS just before the lab executable runs; course is a
//     child subreaper, so whatever a lab leaves running comes back to course
//     and is killed when the lab ends;
//   - under --run-as USER: RLIMIT_NPROC, and, where there is no cgroup, after
//     each lab every process of USER that no running lab started is killed
//     (a setsid() escape too);
//   - as root with CAP_SYS_ADMIN: namespaces and a cgroup (isolation.hpp).
#pragma once

#include <linux/filter.h>
#include <sys/types.h>

#include <string>
#include <vector>

#include "grading/sandbox/limits.hpp"

namespace grading {

// The seccomp program, compiled (by libseccomp) before fork, so that the
// forked child only has to hand it to the kernel: no allocation there.
class SeccompFilter {
public:
    SeccompFilter();  // throws fw::Error when libseccomp cannot build it
    // In the forked child, after everything else and before execve. Returns
    // false (errno set) when the kernel refused it.
    bool install() const noexcept;
    // One line per rule, for the reports: "socket (all but AF_UNIX)", ...
    static std::vector<std::string> denied();

private:
    std::vector<sock_filter> program_;
};

// Makes course a child subreaper (PR_SET_CHILD_SUBREAPER): an orphan of a
// lab's child becomes course's child, not init's.
bool become_subreaper();

// The lab children now running, so that strays can be told from them.
// fork_lab() forks (returning as fork() does) and, in the parent, counts the
// child as running in the same step: under --jobs a kill_strays() in another
// thread can never see the new child before it counts, and kill it as a stray.
pid_t fork_lab();
void lab_ended(pid_t pid);

// Kills and reaps every process that no running lab started: course's
// adopted children, and with `user` every process of that user. Returns how
// many processes it killed, each once. A zombie is not a stray: course reaps
// its own, and leaves another's (of `user`, whose parent never reaps it) alone.
int kill_strays(const RunAsUser* user);

// Every layer, active or not, as the reports list them. `namespaces_why` and
// `cgroups_why` say why those are missing when they are.
std::vector<SandboxLayer> sandbox_layers(const RunAsUser* user, const ChildLimits& limits,
                                         const std::string& namespaces_why,
                                         const std::string& cgroups_why);

// RLIMIT_NPROC of a child under --run-as: processes and threads of that
// user, all its labs together (llvmpipe starts a thread per core in each).
constexpr int kRunAsProcesses = 1024;

}  // namespace grading
