// The namespace layer of isolation.hpp.
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

constexpr int kNamespaces = CLONE_NEWPID | CLONE_NEWNET | CLONE_NEWNS | CLONE_NEWIPC;

}  // namespace

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
        struct sigaction dfl = {};
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
