#include "grading/run/parallel.hpp"

#include <sched.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <fstream>
#include <string>

namespace grading {

namespace {

// The CPU quota of this process's cgroup in cores (quota / period), or 0
// when there is none or it cannot be read. cgroup v2: cpu.max ("max 100000"
// or "50000 100000"); v1: cpu.cfs_quota_us (-1 for none) and
// cpu.cfs_period_us. The cgroup's own folder is tried first (from
// /proc/self/cgroup), then the root of the mount, which is the container's
// cgroup inside a container.
double cgroup_cpu_quota() {
    std::ifstream self("/proc/self/cgroup");
    std::string line, v2_path, v1_path;
    while (std::getline(self, line)) {
        const size_t a = line.find(':'), b = line.find(':', a + 1);
        if (a == std::string::npos || b == std::string::npos) continue;
        const std::string controllers = line.substr(a + 1, b - a - 1), path = line.substr(b + 1);
        if (line.compare(0, a, "0") == 0 && controllers.empty()) v2_path = path;
        if ((controllers + ",").find("cpu,") != std::string::npos) v1_path = path;
    }
    auto cores = [](double quota, double period) {
        return quota > 0 && period > 0 ? quota / period : 0.0;
    };
    for (const std::string& dir : {"/sys/fs/cgroup" + v2_path, std::string("/sys/fs/cgroup")}) {
        std::ifstream max(dir + "/cpu.max");
        std::string quota;
        double period = 0;
        if (max >> quota >> period) return quota == "max" ? 0.0 : cores(std::stod(quota), period);
    }
    for (const char* mount : {"/sys/fs/cgroup/cpu", "/sys/fs/cgroup/cpu,cpuacct"})
        for (const std::string& dir : {mount + v1_path, std::string(mount)}) {
            std::ifstream quota_file(dir + "/cpu.cfs_quota_us"),
                period_file(dir + "/cpu.cfs_period_us");
            double quota = 0, period = 0;
            if (quota_file >> quota && period_file >> period) return cores(quota, period);
        }
    return 0.0;
}

}  // namespace

unsigned affinity_cpus() {
    cpu_set_t set;
    if (sched_getaffinity(0, sizeof set, &set) == 0 && CPU_COUNT(&set) > 0)
        return static_cast<unsigned>(CPU_COUNT(&set));
    return 1;
}

unsigned usable_cores() {
    unsigned cores = affinity_cpus();
    double quota = 0;
    try {
        quota = cgroup_cpu_quota();
    } catch (const std::exception&) {
        quota = 0;  // a quota that does not parse limits nothing
    }
    if (quota > 0) cores = std::min(cores, static_cast<unsigned>(std::ceil(quota)));
    return std::max(1u, cores);
}

int judging_threads(int labs_in_flight) {
    return std::clamp(static_cast<int>(usable_cores()) / std::max(1, labs_in_flight), 1, 8);
}

}  // namespace grading
