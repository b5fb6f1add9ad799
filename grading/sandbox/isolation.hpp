// The sandbox's privileged layers (docs/contract.md, `course`,
// Sandbox), used where course runs as root with CAP_SYS_ADMIN (a staff
// machine, CI), and reported as missing elsewhere (Gradescope's container):
//   - namespaces: each lab's child starts new PID, network (loopback only),
//     mount and IPC namespaces. The lab runs under a small init (PID 1 of
//     its namespace) on a /proc of its own, so it sees no process of course
//     or of another lab, and when the lab ends the init ends, which kills
//     everything left in the namespace;
//   - a cgroup per child (v2, or v1's memory and pids controllers) with a
//     memory limit and a process limit, and with the cpu controller where
//     there is one, so that labs graded at once share the CPU equally; when
//     the lab ends every process in it is killed, and an out-of-memory kill
//     is reported as such.
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace grading {

// Where course makes its cgroups: one directory per course run, removed at
// its end, holding one cgroup per lab child.
class CgroupRoot {
public:
    // Null and `why` when no cgroup can be made here.
    static std::unique_ptr<CgroupRoot> open(std::string& why);
    ~CgroupRoot();
    CgroupRoot(const CgroupRoot&) = delete;
    CgroupRoot& operator=(const CgroupRoot&) = delete;

    int version() const { return version_; }
    // Whether each lab's cgroup also has the cpu controller: sibling cgroups
    // share the CPU equally, however many threads each runs.
    bool cpu() const { return cpu_; }
    // "cgroup v1 (memory, pids, cpu)" or "cgroup v2".
    std::string describe() const;

private:
    friend class LabCgroup;
    CgroupRoot() = default;
    static std::unique_ptr<CgroupRoot> make(std::string& why);
    int version_ = 2;
    bool cpu_ = false;
    // v2: one directory; v1: the memory, the pids and (cpu_) the cpu
    // hierarchy's.
    std::vector<std::string> dirs_;
};

// One child's cgroup, made before it forks. The child joins it by writing
// "0" into each of join_fds() (descriptors opened here, close-on-exec).
class LabCgroup {
public:
    LabCgroup(const CgroupRoot& root, std::uint64_t memory_cap, int processes_cap);
    ~LabCgroup();  // kills what is left, removes the directories
    LabCgroup(const LabCgroup&) = delete;
    LabCgroup& operator=(const LabCgroup&) = delete;

    const std::vector<int>& join_fds() const { return join_fds_; }
    // Kills every process in the cgroup and waits (briefly) until it is
    // empty. Returns how many were in it when called.
    int kill_all();
    // How many times the kernel killed a process of it for memory.
    long oom_kills() const;

private:
    void remove();
    std::vector<std::string> dirs_;  // as in CgroupRoot
    std::string procs_;              // the cgroup.procs that lists every process
    std::vector<int> join_fds_;
    int version_ = 2;
};

// Whether this process may give a child new PID, network, mount and IPC
// namespaces (tried once, in a throwaway child); `why` says why not.
bool namespaces_usable(std::string& why);

// In the forked lab child, as root, before it switches user: enters the
// namespaces and splits in three. The process course forked stays outside
// and ends as the lab ends (the same exit code or signal); the namespace's
// init (PID 1) mounts a /proc of its own, raises loopback and waits for the
// lab; only the lab's process returns from this call, the init its parent.
// Async-signal-safe; a failure calls `fail`, which must not return.
void enter_namespaces(void (*fail)(const char*)) noexcept;

}  // namespace grading
