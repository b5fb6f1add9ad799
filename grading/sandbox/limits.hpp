// What every layer of the sandbox is configured by (docs/contract.md, `course`,
// Sandbox): a child's limits, the user it runs as, and the layers as
// the reports list them. The run room (run/child.hpp) applies them to a child.
#pragma once

#include <sys/types.h>

#include <cstdint>
#include <string>
#include <vector>

namespace grading {

constexpr std::uint64_t kMiB = 1024 * 1024;

class CgroupRoot;  // isolation.hpp

struct ChildLimits {
    double timeout_seconds = 60.0;            // wall clock; then the whole group is killed
    std::uint64_t output_cap = 8 * kMiB;      // stdout + stderr together
    std::uint64_t log_kept = 64 * 1024;       // the tail of stdout + stderr kept for the report
    std::uint64_t file_cap = 64 * kMiB;       // RLIMIT_FSIZE: bytes per file it writes
    std::uint64_t work_dir_cap = 256 * kMiB;  // all files in its work directory
    std::uint64_t memory_cap = 8192 * kMiB;   // RLIMIT_AS (not under AddressSanitizer)
    int open_files = 256;                     // RLIMIT_NOFILE
    // The privileged layers (isolation.hpp), where course found them usable:
    // new namespaces for each child, and a cgroup with these two limits.
    bool namespaces = false;
    const CgroupRoot* cgroups = nullptr;
    std::uint64_t resident_cap = 2048 * kMiB;  // the cgroup's memory limit
    int processes_cap = 1024;                  // the cgroup's pids.max
};

// The user a child runs as (--run-as), resolved before any child starts.
struct RunAsUser {
    std::string name;
    uid_t uid = 0;
    gid_t gid = 0;
    std::vector<gid_t> groups;  // supplementary groups, as initgroups would set them
};

// "8 MiB": a byte count in whole MiB, for messages about limits.
std::string mib_text(std::uint64_t bytes);

struct SandboxLayer {
    std::string name;  // "seccomp filter", "namespaces", ...
    bool active = false;
    std::string detail;  // what it does, or why it is not used
    // Whether --sandbox strict needs it: every layer but --run-as, which is
    // the operator's choice, not the machine's.
    bool required_by_strict = true;
};

}  // namespace grading
