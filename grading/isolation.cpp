#include "grading/isolation.hpp"

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

namespace fs = std::filesystem;

namespace grading {

namespace {

constexpr int kNamespaces = CLONE_NEWPID | CLONE_NEWNET | CLONE_NEWNS | CLONE_NEWIPC;

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

// Removes what a killed course left in `top`: the (empty) cgroups of a
// course-PID whose process is gone. A cgroup that still holds a process
// cannot be removed, so nothing running is touched.
void remove_stale(const std::string& top) {
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(top, ec)) {
        const std::string name = e.path().filename().string();
        if (name.rfind("course-", 0) != 0 || !e.is_directory(ec)) continue;
        const long pid = std::strtol(name.c_str() + 7, nullptr, 10);
        if (pid <= 0 || kill(static_cast<pid_t>(pid), 0) == 0 || errno != ESRCH) continue;
        for (const auto& lab : fs::directory_iterator(e.path(), ec))
            if (lab.is_directory(ec)) rmdir(lab.path().c_str());
        rmdir(e.path().c_str());
    }
}

}  // namespace

std::unique_ptr<CgroupRoot> CgroupRoot::make(std::string& why) {
    const std::string name = "course-" + std::to_string(getpid());
    std::unique_ptr<CgroupRoot> root(new CgroupRoot);
    std::error_code ec;
    // v2, with the memory and pids controllers (and cpu, where there is one)
    // handed down to course's directory (the root cgroup may hold processes
    // and controllers alike).
    if (const std::string v2 = cgroup_mount("cgroup2", ""); !v2.empty()) {
        const std::string controllers = read_file(v2 + "/cgroup.controllers");
        if (controllers.find("memory") != std::string::npos &&
            controllers.find("pids") != std::string::npos) {
            remove_stale(v2);
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
        remove_stale(top);
        const std::string dir = top + "/" + name;
        if (!fs::create_directory(dir, ec)) {
            why = "cannot make " + dir + " (" + ec.message() + ")";
            return nullptr;  // ~CgroupRoot removes what was made
        }
        root->dirs_.push_back(dir);
    }
    // The cpu hierarchy where it is separate and writable: an equal share per lab.
    if (const std::string cpu = cgroup_mount("cgroup", "cpu"); !cpu.empty() && cpu != memory) {
        remove_stale(cpu);
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
    int killed = 0;
    if (version_ == 2 && fs::exists(dirs_[0] + "/cgroup.kill"))
        write_file(dirs_[0] + "/cgroup.kill", "1");
    // Killed processes leave the cgroup once reaped (their parents are in
    // it, or are course, which reaps its strays): give them a moment.
    for (int round = 0; round < 100; ++round) {
        std::istringstream procs(read_file(procs_));
        bool any = false;
        for (long pid; procs >> pid;) {
            any = true;
            if (kill(static_cast<pid_t>(pid), SIGKILL) == 0) ++killed;
            waitpid(static_cast<pid_t>(pid), nullptr, WNOHANG);
        }
        if (!any) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return killed;
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

namespace {

// Where the probe's child says which step failed.
int g_probe_fd = -1;

void probe_fail(const char* what) {
    const int e = errno;
    const ssize_t ignored = write(g_probe_fd, what, std::strlen(what));
    (void)ignored;
    _exit(e == 0 ? 1 : e);
}

}  // namespace

bool namespaces_usable(std::string& why) {
    // The whole set-up, as a lab child goes through it, in a throwaway child
    // whose "lab" exits at once.
    int fds[2];
    if (pipe2(fds, O_CLOEXEC) != 0) {
        why = std::string("pipe: ") + std::strerror(errno);
        return false;
    }
    const pid_t pid = fork();
    if (pid < 0) {
        why = std::string("fork: ") + std::strerror(errno);
        close(fds[0]);
        close(fds[1]);
        return false;
    }
    if (pid == 0) {
        close(fds[0]);
        g_probe_fd = fds[1];
        enter_namespaces(probe_fail);
        _exit(0);
    }
    close(fds[1]);
    char what[256] = {};
    const ssize_t n = read(fds[0], what, sizeof what - 1);
    close(fds[0]);
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return true;
    const std::string step = n > 0 ? std::string(what, static_cast<size_t>(n)) : "the set-up";
    why = step + ": " +
          (WIFEXITED(status) ? std::strerror(WEXITSTATUS(status)) : std::string("killed")) +
          " (new namespaces need root with CAP_SYS_ADMIN)";
    return false;
}

namespace {

// Ends this process the way `status` (from waitpid) says another ended.
[[noreturn]] void end_like(int status) {
    if (WIFSIGNALED(status)) {
        const int sig = WTERMSIG(status);
        struct sigaction dfl {};
        dfl.sa_handler = SIG_DFL;
        sigaction(sig, &dfl, nullptr);
        sigset_t one;
        sigemptyset(&one);
        sigaddset(&one, sig);
        sigprocmask(SIG_UNBLOCK, &one, nullptr);
        kill(getpid(), sig);
        _exit(128 + sig);
    }
    _exit(WIFEXITED(status) ? WEXITSTATUS(status) : 125);
}

void loopback_up() {
    const int fd = socket(AF_INET, SOCK_DGRAM | SOCK_CLOEXEC, 0);
    if (fd < 0) return;
    ifreq ifr{};
    std::strncpy(ifr.ifr_name, "lo", IFNAMSIZ - 1);
    if (ioctl(fd, SIOCGIFFLAGS, &ifr) == 0) {
        ifr.ifr_flags = static_cast<short>(ifr.ifr_flags | IFF_UP | IFF_RUNNING);
        ioctl(fd, SIOCSIFFLAGS, &ifr);
    }
    close(fd);
}

}  // namespace

void enter_namespaces(void (*fail)(const char*)) noexcept {
    if (unshare(kNamespaces) != 0) fail("unshare (PID, network, mount and IPC namespaces)");
    // The lab's status, from the init to the process course waits for.
    int status_pipe[2];
    if (pipe2(status_pipe, O_CLOEXEC) != 0) fail("pipe");
    const pid_t init = fork();
    if (init < 0) fail("fork of the namespace's init");
    if (init > 0) {
        // Outside: course's child. It ends as the lab ended.
        close(status_pipe[1]);
        prctl(PR_SET_DUMPABLE, 0);
        int status = 0;
        while (waitpid(init, &status, 0) < 0 && errno == EINTR) {
        }
        int lab_status = 0;
        if (read(status_pipe[0], &lab_status, sizeof lab_status) == sizeof lab_status)
            status = lab_status;
        end_like(status);
    }
    // PID 1 of the new namespace: a copy of course, so not to be read by
    // the lab (not dumpable: its /proc files are root's alone), and named
    // for what it is.
    close(status_pipe[0]);
    if (prctl(PR_SET_PDEATHSIG, SIGKILL) != 0 || prctl(PR_SET_DUMPABLE, 0) != 0 ||
        prctl(PR_SET_NAME, "lab-init") != 0)
        fail("prctl");
    // Nothing mounted here reaches course's namespace. In a chroot "/" may
    // be no mount point: then /proc's mount, the only one changed, is enough.
    if (mount(nullptr, "/", nullptr, MS_REC | MS_PRIVATE, nullptr) != 0 &&
        mount(nullptr, "/proc", nullptr, MS_REC | MS_PRIVATE, nullptr) != 0)
        fail("making the mounts private");
    if (mount("proc", "/proc", "proc", MS_NOSUID | MS_NODEV | MS_NOEXEC, nullptr) != 0)
        fail("mounting the namespace's /proc");
    loopback_up();
    const pid_t lab = fork();
    if (lab < 0) fail("fork of the lab in its namespace");
    if (lab > 0) {
        // The init: reaps whatever ends until the lab has; then it ends,
        // and the kernel kills everything left in the namespace.
        int status = 0;
        for (;;) {
            int s = 0;
            const pid_t done = wait(&s);
            if (done == lab) {
                status = s;
                break;
            }
            if (done < 0 && errno != EINTR) break;
        }
        const ssize_t ignored = write(status_pipe[1], &status, sizeof status);
        (void)ignored;
        _exit(0);
    }
    close(status_pipe[1]);
}

}  // namespace grading
