#include "grading/platforms/run_logged.hpp"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "framework/error.hpp"

namespace grading {

namespace {

// What the shell's $? says of a child: its exit status, or 128 + the signal.
int shell_status(int wait_status) {
    if (WIFEXITED(wait_status)) return WEXITSTATUS(wait_status);
    if (WIFSIGNALED(wait_status)) return 128 + WTERMSIG(wait_status);
    return 255;
}

// Writes all of `bytes` to `fd`; false when it cannot.
bool write_all(int fd, const char* bytes, size_t size) {
    while (size > 0) {
        const ssize_t n = write(fd, bytes, size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return false;
        bytes += n;
        size -= static_cast<size_t>(n);
    }
    return true;
}

// Copies everything readable from `from` to `log` and to our stdout, like
// tee: a log that cannot be written does not stop the copy to stdout.
void tee(int from, int log) {
    char buf[65536];
    bool log_ok = true;
    for (;;) {
        const ssize_t n = read(from, buf, sizeof buf);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return;
        log_ok = log_ok && write_all(log, buf, static_cast<size_t>(n));
        std::fwrite(buf, 1, static_cast<size_t>(n), stdout);
        std::fflush(stdout);
    }
}

}  // namespace

int run_logged(const std::vector<std::string>& argv, const std::filesystem::path& log, bool echo) {
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    const int log_fd = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0600);
    const int devnull = open("/dev/null", O_RDONLY | O_CLOEXEC);
    int fds[2] = {-1, -1};
    if (log_fd < 0 || devnull < 0 || (echo && pipe2(fds, O_CLOEXEC) != 0))
        throw fw::Error("cannot set up the log '" + log.string() + "': " + std::strerror(errno));
    const int out = echo ? fds[1] : log_fd;
    std::fflush(stdout);
    const pid_t pid = fork();
    if (pid == 0) {
        if (dup2(devnull, 0) >= 0 && dup2(out, 1) >= 0 && dup2(out, 2) >= 0)
            execvp(args[0], args.data());
        std::fprintf(stderr, "cannot run %s: %s\n", args[0], std::strerror(errno));
        _exit(127);
    }
    if (echo) close(fds[1]);
    if (pid > 0 && echo) tee(fds[0], log_fd);
    if (echo) close(fds[0]);
    close(devnull);
    close(log_fd);
    if (pid < 0) throw fw::Error(std::string("cannot fork: ") + std::strerror(errno));
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    return shell_status(status);
}

}  // namespace grading
