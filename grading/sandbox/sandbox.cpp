#include "grading/sandbox/sandbox.hpp"

#include <dirent.h>
#include <seccomp.h>
#include <signal.h>
#include <sys/mman.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <fstream>
#include <map>
#include <memory>
#include <mutex>
#include <set>
#include <sstream>
#include <thread>

#include "framework/error.hpp"
#include "framework/text.hpp"
#include "grading/sandbox/isolation.hpp"
#include "grading/sandbox/limits.hpp"

namespace grading {

std::string mib_text(std::uint64_t bytes) { return std::to_string(bytes / kMiB) + " MiB"; }

namespace {

// Denied outright: what a lab never needs and a submission could use
// against the grader or the machine.
const char* const kDenied[] = {
    "ptrace",
    "process_vm_readv",
    "process_vm_writev",
    "keyctl",
    "add_key",
    "request_key",
    "bpf",
    "perf_event_open",
    "mount",
    "umount2",
    "unshare",
    "setns",
    "pivot_root",
    "chroot",
    "kexec_load",
    "kexec_file_load",
    "init_module",
    "finit_module",
    "delete_module",
    "swapon",
    "swapoff",
    "reboot",
    "open_by_handle_at",
    "userfaultfd",
    "io_uring_setup",
    "io_uring_enter",
    "io_uring_register",
};

bool sanitized_build() {
#if defined(__SANITIZE_ADDRESS__)
    return true;
#else
    return false;
#endif
}

std::mutex g_labs_mutex;
std::set<pid_t> g_labs;

struct ProcInfo {
    pid_t pid = 0, ppid = 0;
    uid_t uid = 0;
    bool zombie = false;  // exited, not yet reaped: nothing left to kill
};

std::vector<ProcInfo> processes() {
    std::vector<ProcInfo> all;
    DIR* proc = opendir("/proc");
    if (!proc) return all;
    while (dirent* e = readdir(proc)) {
        char* end = nullptr;
        const long pid = std::strtol(e->d_name, &end, 10);
        if (*end != '\0' || pid <= 0) continue;
        std::ifstream status(std::string("/proc/") + e->d_name + "/status");
        ProcInfo p;
        p.pid = static_cast<pid_t>(pid);
        bool have_uid = false;
        for (std::string line; std::getline(status, line);) {
            if (line.rfind("State:", 0) == 0) {
                // "State:\tZ (zombie)"; X: dead, about to go.
                const size_t at = line.find_first_not_of(" \t", 6);
                p.zombie = at != std::string::npos && (line[at] == 'Z' || line[at] == 'X');
            }
            if (line.rfind("PPid:", 0) == 0) p.ppid = static_cast<pid_t>(std::stol(line.substr(5)));
            if (line.rfind("Uid:", 0) == 0) {
                std::istringstream fields(line.substr(4));
                unsigned long real = 0;
                fields >> real;
                p.uid = static_cast<uid_t>(real);
                have_uid = true;
            }
        }
        if (have_uid) all.push_back(p);
    }
    closedir(proc);
    return all;
}

}  // namespace

SeccompFilter::SeccompFilter() {
    const std::unique_ptr<void, void (*)(scmp_filter_ctx)> ctx(seccomp_init(SCMP_ACT_ALLOW),
                                                               seccomp_release);
    if (!ctx) throw fw::Error("libseccomp could not start a filter");
    auto fail = [](const std::string& what, int rc) {
        return fw::Error("cannot build the child's seccomp filter: " + what + ": " +
                         std::strerror(-rc));
    };
    int rc = 0;
    for (const char* name : kDenied) {
        // LeakSanitizer stops the threads it scans with ptrace: a sanitized
        // child needs it (sanitized builds are the project's own tests).
        if (sanitized_build() && std::strcmp(name, "ptrace") == 0) continue;
        const int nr = seccomp_syscall_resolve_name(name);
        if (nr == __NR_SCMP_ERROR) continue;  // not on this architecture
        if ((rc = seccomp_rule_add(ctx.get(), SCMP_ACT_ERRNO(EPERM), nr, 0)) < 0)
            throw fail(name, rc);
    }
    // Sockets only of AF_UNIX (Mesa and the C library use those locally).
    for (const int nr : {SCMP_SYS(socket), SCMP_SYS(socketpair)})
        if ((rc = seccomp_rule_add(ctx.get(), SCMP_ACT_ERRNO(EPERM), nr, 1,
                                   SCMP_A0(SCMP_CMP_NE, AF_UNIX))) < 0)
            throw fail("socket", rc);
    // The filter goes to the kernel from the forked child without
    // allocating: export it now, as BPF, through a memory file.
    const int fd = memfd_create("seccomp-bpf", MFD_CLOEXEC);
    if (fd < 0) throw fw::Error(std::string("memfd_create: ") + std::strerror(errno));
    if ((rc = seccomp_export_bpf(ctx.get(), fd)) < 0) {
        close(fd);
        throw fail("export", rc);
    }
    const off_t size = lseek(fd, 0, SEEK_END);
    program_.resize(static_cast<size_t>(size) / sizeof(sock_filter));
    const ssize_t got = pread(fd, program_.data(), program_.size() * sizeof(sock_filter), 0);
    close(fd);
    if (got != static_cast<ssize_t>(program_.size() * sizeof(sock_filter)) || program_.empty())
        throw fw::Error("cannot read back the child's seccomp filter");
}

bool SeccompFilter::install() const noexcept {
    sock_fprog prog{static_cast<unsigned short>(program_.size()),
                    const_cast<sock_filter*>(program_.data())};
    return prctl(PR_SET_NO_NEW_PRIVS, 1, 0, 0, 0) == 0 &&
           prctl(PR_SET_SECCOMP, SECCOMP_MODE_FILTER, &prog) == 0;
}

std::vector<std::string> SeccompFilter::denied() {
    std::vector<std::string> out = {"socket and socketpair but AF_UNIX"};
    for (const char* name : kDenied)
        if (!(sanitized_build() && std::strcmp(name, "ptrace") == 0)) out.emplace_back(name);
    return out;
}

bool become_subreaper() { return prctl(PR_SET_CHILD_SUBREAPER, 1, 0, 0, 0) == 0; }

pid_t fork_lab() {
    std::lock_guard<std::mutex> lock(g_labs_mutex);
    const pid_t pid = fork();
    if (pid > 0) g_labs.insert(pid);
    return pid;
}

void lab_ended(pid_t pid) {
    std::lock_guard<std::mutex> lock(g_labs_mutex);
    g_labs.erase(pid);
}

int kill_strays(const RunAsUser* user) {
    // Each process counts once: one that SIGKILL has not yet ended (a busy
    // machine) is still there, and killed again, next round.
    std::set<pid_t> killed;
    const pid_t self = getpid();
    // A killed process's children come to course in turn: go round until
    // nothing is left (a bounded number of times).
    for (int round = 0; round < 50; ++round) {
        std::vector<pid_t> strays;
        {
            // Held from reading the processes to killing the strays: no lab
            // starts in between (fork_lab), so none is taken for a stray.
            std::lock_guard<std::mutex> lock(g_labs_mutex);
            const std::vector<ProcInfo> all = processes();
            std::map<pid_t, pid_t> parent;
            for (const ProcInfo& p : all) parent[p.pid] = p.ppid;
            // Whether `pid` descends from a lab that is still running.
            auto in_running_lab = [&](pid_t pid) {
                for (int depth = 0; pid > 1 && depth < 4096; ++depth) {
                    if (g_labs.count(pid)) return true;
                    auto up = parent.find(pid);
                    if (up == parent.end()) return false;
                    pid = up->second;
                }
                return false;
            };
            for (const ProcInfo& p : all) {
                // A zombie has ended already: course reaps its own, and one
                // whose parent never reaps it (a container's init may not)
                // must not count as a stray round after round (kill() on a
                // zombie succeeds).
                if (p.zombie) {
                    if (p.ppid == self && !g_labs.count(p.pid)) waitpid(p.pid, nullptr, WNOHANG);
                    continue;
                }
                if (p.pid == self || in_running_lab(p.pid)) continue;
                const bool adopted = p.ppid == self;
                const bool users = user && p.uid == user->uid;
                if (adopted || users) strays.push_back(p.pid);
            }
            for (pid_t pid : strays)
                if (kill(pid, SIGKILL) == 0) killed.insert(pid);
        }
        if (strays.empty()) break;
        // Reap the ones that were course's own; the others' parents do.
        for (pid_t pid : strays) waitpid(pid, nullptr, WNOHANG);
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
        for (pid_t pid : strays) waitpid(pid, nullptr, WNOHANG);
    }
    return static_cast<int>(killed.size());
}

std::vector<SandboxLayer> sandbox_layers(const RunAsUser* user, const ChildLimits& limits,
                                         const std::string& namespaces_why,
                                         const std::string& cgroups_why) {
    std::vector<SandboxLayer> layers = {
        {"seccomp filter", true,
         "in every lab child; fails with EPERM: " + fw::join(SeccompFilter::denied(), ", ")},
        {"child subreaper", true,
         "course adopts whatever a lab leaves running (a setsid() daemon too) and kills it when "
         "the lab ends"}};
    if (user)
        layers.push_back({"--run-as " + user->name, true,
                          "the lab runs as " + user->name + " with RLIMIT_NPROC " +
                              std::to_string(kRunAsProcesses) +
                              (limits.cgroups ? ""
                                              : "; every process of " + user->name +
                                                    " is killed after each lab (no cgroup here)"),
                          false});
    else
        layers.push_back({"--run-as", false,
                          "the labs run as course's own user (no --run-as USER given)", false});
    if (limits.namespaces)
        layers.push_back({"namespaces", true,
                          "new PID, network (loopback only), mount and IPC namespaces: the lab "
                          "sees only its own processes, and all of them end with it"});
    else
        layers.push_back({"namespaces", false, namespaces_why});
    if (limits.cgroups)
        layers.push_back(
            {limits.cgroups->describe(), true,
             "memory " + mib_text(limits.resident_cap) + ", " +
                 std::to_string(limits.processes_cap) + " processes" +
                 (limits.cgroups->cpu() ? ", an equal share of the CPU against the other labs"
                                        : "") +
                 "; everything in it is killed when the lab ends"});
    else
        layers.push_back({"cgroup", false, cgroups_why});
    return layers;
}

}  // namespace grading
