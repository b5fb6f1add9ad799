// The cgroup layer of isolation.hpp.
#include <fcntl.h>
#include <net/if.h>
#include <sched.h>
#include <signal.h>
#include <sys/ioctl.h>
#include <sys/mount.h>
#include <sys/prctl.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <thread>

#include "framework/error.hpp"
#include "grading/sandbox/isolation.hpp"

namespace fs = std::filesystem;

namespace grading {

namespace {

bool write_file(const std::string& path, const std::string& text) {
    std::ofstream out(path);
    out << text;
    out.flush();
    return static_cast<bool>(out);
}

std::string read_file(const std::string& path) {
    std::ifstream in(path);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

// The mount point of a cgroup hierarchy: v2's ("cgroup2"), or v1's with
// `controller` among its options. Empty when there is none.
std::string cgroup_mount(const std::string& type, const std::string& controller) {
    std::ifstream mounts("/proc/self/mounts");
    for (std::string line; std::getline(mounts, line);) {
        std::istringstream f(line);
        std::string device, dir, fstype, options;
        f >> device >> dir >> fstype >> options;
        if (fstype != type) continue;
        if (controller.empty()) return dir;
        std::istringstream opts(options);
        for (std::string o; std::getline(opts, o, ',');)
            if (o == controller) return dir;
    }
    return "";
}

// The value after `key ` in a flat keyed file (memory.events, oom_control).
long keyed_value(const std::string& text, const std::string& key) {
    std::istringstream in(text);
    for (std::string k; in >> k;) {
        long v = 0;
        in >> v;
        if (k == key) return v;
    }
    return 0;
}

std::atomic<unsigned> g_next_lab{0};

}  // namespace

namespace {

// "course-<PID namespace>-": the start of the cgroups' names made by a course
// of this PID namespace. A PID means nothing outside its namespace, and
// courses of several namespaces (containers without cgroup namespaces, a
// chroot beside its host) can share one hierarchy; the namespace's inode
// number tells them apart on one kernel.
std::string own_prefix() {
    struct stat ns = {};
    const unsigned long long inode =
        stat("/proc/self/ns/pid", &ns) == 0 ? static_cast<unsigned long long>(ns.st_ino) : 0;
    return "course-" + std::to_string(inode) + "-";
}

// Removes what a killed course of this PID namespace left in `top`: the
// (empty) cgroups of a course-NS-PID whose process is gone. A cgroup that
// still holds a process cannot be removed, so nothing running is touched;
// another namespace's cgroups are never looked at, since its PIDs cannot be
// checked from here.
void remove_stale(const std::string& top, const std::string& prefix) {
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(top, ec)) {
        const std::string name = e.path().filename().string();
        if (name.rfind(prefix, 0) != 0 || !e.is_directory(ec)) continue;
        char* end = nullptr;
        const long pid = std::strtol(name.c_str() + prefix.size(), &end, 10);
        if (pid <= 0 || *end != '\0') continue;
        if (kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;
        for (const auto& lab : fs::directory_iterator(e.path(), ec))
            if (lab.is_directory(ec)) rmdir(lab.path().c_str());
        rmdir(e.path().c_str());
    }
}

}  // namespace

std::unique_ptr<CgroupRoot> CgroupRoot::make(std::string& why) {
    const std::string prefix = own_prefix();
    const std::string name = prefix + std::to_string(getpid());
    std::unique_ptr<CgroupRoot> root(new CgroupRoot);
    std::error_code ec;
    // v2, with the memory and pids controllers (and cpu, where there is one)
    // handed down to course's directory (the root cgroup may hold processes
    // and controllers alike).
    if (const std::string v2 = cgroup_mount("cgroup2", ""); !v2.empty()) {
        const std::string controllers = read_file(v2 + "/cgroup.controllers");
        if (controllers.find("memory") != std::string::npos &&
            controllers.find("pids") != std::string::npos) {
            remove_stale(v2, prefix);
            const std::string dir = v2 + "/" + name;
            for (const bool cpu : {true, false}) {
                if (cpu && controllers.find("cpu") == std::string::npos) continue;
                const std::string wanted = cpu ? "+memory +pids +cpu" : "+memory +pids";
                if (write_file(v2 + "/cgroup.subtree_control", wanted) &&
                    (fs::is_directory(dir) || fs::create_directory(dir, ec)) &&
                    write_file(dir + "/cgroup.subtree_control", wanted)) {
                    root->version_ = 2;
                    root->cpu_ = cpu;
                    root->dirs_ = {dir};
                    return root;
                }
            }
            fs::remove(dir, ec);
            why = "cannot make a cgroup under " + v2 + " (" +
                  (ec ? ec.message() : std::string(std::strerror(errno))) + ")";
            return nullptr;
        }
    }
    const std::string memory = cgroup_mount("cgroup", "memory");
    const std::string pids = cgroup_mount("cgroup", "pids");
    if (memory.empty() || pids.empty()) {
        why = "no cgroup hierarchy with the memory and pids controllers is mounted";
        return nullptr;
    }
    for (const std::string& top : {memory, pids}) {
        remove_stale(top, prefix);
        const std::string dir = top + "/" + name;
        if (!fs::create_directory(dir, ec)) {
            why = "cannot make " + dir + " (" + ec.message() + ")";
            return nullptr;  // ~CgroupRoot removes what was made
        }
        root->dirs_.push_back(dir);
    }
    // The cpu hierarchy where it is separate and writable: an equal share per lab.
    if (const std::string cpu = cgroup_mount("cgroup", "cpu"); !cpu.empty() && cpu != memory) {
        remove_stale(cpu, prefix);
        const std::string dir = cpu + "/" + name;
        if (fs::create_directory(dir, ec)) {
            root->dirs_.push_back(dir);
            root->cpu_ = true;
        }
    }
    root->version_ = 1;
    return root;
}

std::unique_ptr<CgroupRoot> CgroupRoot::open(std::string& why) {
    std::unique_ptr<CgroupRoot> root = make(why);
    if (!root) return nullptr;
    // Tried once the way each lab uses it: made, joined by a process, emptied
    // and removed. Where any step fails the layer is off, not every lab.
    try {
        LabCgroup probe(*root, std::uint64_t{64} << 20, 16);
        const pid_t pid = fork();
        if (pid < 0) throw fw::Error(std::string("fork: ") + std::strerror(errno));
        if (pid == 0) {
            for (const int fd : probe.join_fds())
                if (write(fd, "0", 1) != 1) _exit(1);
            _exit(0);
        }
        int status = 0;
        while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
        }
        if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
            throw fw::Error("a process cannot join a cgroup made in " + root->dirs_[0]);
    } catch (const fw::Error& e) {
        why = e.what();
        return nullptr;
    }
    return root;
}

CgroupRoot::~CgroupRoot() {
    for (const std::string& dir : dirs_) rmdir(dir.c_str());
}

std::string CgroupRoot::describe() const {
    return version_ == 2 ? "cgroup v2"
                         : std::string("cgroup v1 (memory, pids") + (cpu_ ? ", cpu)" : ")");
}

LabCgroup::LabCgroup(const CgroupRoot& root, std::uint64_t memory_cap, int processes_cap)
    : version_(root.version_) {
    const std::string name = "lab-" + std::to_string(g_next_lab++);
    auto fail = [&](const std::string& what) {
        const std::string e = std::strerror(errno);
        remove();
        return fw::Error("cannot make the lab's cgroup: " + what + ": " + e);
    };
    for (const std::string& top : root.dirs_) {
        const std::string dir = top + "/" + name;
        if (mkdir(dir.c_str(), 0755) != 0) throw fail("mkdir " + dir);
        dirs_.push_back(dir);
    }
    const std::string memory = std::to_string(memory_cap);
    const std::string processes = std::to_string(processes_cap);
    bool ok = true;
    if (version_ == 2) {
        ok = write_file(dirs_[0] + "/memory.max", memory) &&
             write_file(dirs_[0] + "/pids.max", processes);
        // No swap either, where the kernel accounts it.
        if (ok && fs::exists(dirs_[0] + "/memory.swap.max"))
            ok = write_file(dirs_[0] + "/memory.swap.max", "0");
        procs_ = dirs_[0] + "/cgroup.procs";
    } else {
        ok = write_file(dirs_[0] + "/memory.limit_in_bytes", memory) &&
             write_file(dirs_[1] + "/pids.max", processes);
        // Swap counted too where the kernel accounts it (memsw).
        if (ok && fs::exists(dirs_[0] + "/memory.memsw.limit_in_bytes"))
            ok = write_file(dirs_[0] + "/memory.memsw.limit_in_bytes", memory);
        procs_ = dirs_[1] + "/cgroup.procs";
    }
    if (!ok) throw fail("cannot set the limits in " + dirs_[0]);
    for (const std::string& dir : dirs_) {
        const int fd = ::open((dir + "/cgroup.procs").c_str(), O_WRONLY | O_CLOEXEC);
        if (fd < 0) throw fail("open " + dir + "/cgroup.procs");
        join_fds_.push_back(fd);
    }
}

int LabCgroup::kill_all() {
    // Counted before the kill: a killed process may already be a zombie, or
    // reaped, by the time it is looked at again.
    int left = 0;
    {
        std::istringstream procs(read_file(procs_));
        for (long pid; procs >> pid;) ++left;
    }
    if (version_ == 2 && fs::exists(dirs_[0] + "/cgroup.kill"))
        write_file(dirs_[0] + "/cgroup.kill", "1");
    // Killed processes leave the cgroup once reaped (their parents are in
    // it, or are course, which reaps its strays): give them a moment.
    for (int round = 0; round < 100; ++round) {
        std::istringstream procs(read_file(procs_));
        bool any = false;
        for (long pid; procs >> pid;) {
            any = true;
            kill(static_cast<pid_t>(pid), SIGKILL);
            waitpid(static_cast<pid_t>(pid), nullptr, WNOHANG);
        }
        if (!any) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return left;
}

long LabCgroup::oom_kills() const {
    if (version_ == 2) return keyed_value(read_file(dirs_[0] + "/memory.events"), "oom_kill");
    const long kills = keyed_value(read_file(dirs_[0] + "/memory.oom_control"), "oom_kill");
    return kills;
}

LabCgroup::~LabCgroup() { remove(); }

void LabCgroup::remove() {
    for (int fd : join_fds_) close(fd);
    join_fds_.clear();
    if (!procs_.empty()) kill_all();
    for (auto dir = dirs_.rbegin(); dir != dirs_.rend(); ++dir)
        for (int attempt = 0; attempt < 50 && rmdir(dir->c_str()) != 0 && errno == EBUSY; ++attempt)
            std::this_thread::sleep_for(std::chrono::milliseconds(10));
    dirs_.clear();
}

}  // namespace grading
