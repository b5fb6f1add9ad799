#include "grading/run/job_gate.hpp"

#include <fcntl.h>
#include <sys/socket.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string_view>

#include "framework/error.hpp"

namespace grading {

JobGate::JobGate(const std::vector<std::string>& lab_dirs, const RunAsUser* user)
    : texts_(lab_dirs.size()), given_(lab_dirs.size(), 0), user_(user) {
    // A socket, not a pipe: a byte sent to a child that has ended fails
    // with EPIPE (MSG_NOSIGNAL) instead of killing course with SIGPIPE.
    if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds_) != 0)
        throw fw::Error(std::string("socketpair for the job gate: ") + std::strerror(errno));
    for (const std::string& dir : lab_dirs) {
        const int fd = open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_NOFOLLOW | O_CLOEXEC);
        if (fd < 0) {
            const int e = errno;
            close_all();
            throw fw::Error("cannot open '" + dir + "' in the work directory: " + std::strerror(e));
        }
        dirs_.push_back(fd);
    }
}

JobGate::~JobGate() { close_all(); }

void JobGate::close_all() {
    for (const int fd : dirs_) close(fd);
    dirs_.clear();
    for (int& fd : fds_)
        if (fd >= 0) close(fd), fd = -1;
}

bool JobGate::write_job(size_t i) {
    // O_EXCL and O_NOFOLLOW: a file or link the child put at the path first
    // is never written through; the job is then not written at all.
    const int fd =
        openat(dirs_[i], "JOB.json", O_WRONLY | O_CREAT | O_EXCL | O_NOFOLLOW | O_CLOEXEC, 0600);
    if (fd < 0) return false;
    bool ok = !user_ || fchown(fd, user_->uid, user_->gid) == 0;
    for (const std::string_view part : {std::string_view(texts_[i]), std::string_view("\n")})
        for (size_t at = 0; ok && at < part.size();) {
            const ssize_t n = write(fd, part.data() + at, part.size() - at);
            if (n < 0 && errno == EINTR) continue;
            ok = n > 0;
            if (ok) at += static_cast<size_t>(n);
        }
    return close(fd) == 0 && ok;
}

void JobGate::give(size_t i, std::string text) {
    const std::lock_guard<std::mutex> lock(mutex_);
    texts_.at(i) = std::move(text);
    given_[i] = 1;
    while (!ended_ && next_ < given_.size() && given_[next_]) {
        if (!write_job(next_) || send(fds_[0], "j", 1, MSG_NOSIGNAL) != 1) {
            ended_ = true;
            shutdown(fds_[0], SHUT_WR);
            break;
        }
        ++next_;
    }
}

void JobGate::end() {
    const std::lock_guard<std::mutex> lock(mutex_);
    ended_ = true;
    shutdown(fds_[0], SHUT_WR);
}

void JobGate::sync() { const std::lock_guard<std::mutex> lock(mutex_); }

std::vector<std::string> JobGate::texts() {
    const std::lock_guard<std::mutex> lock(mutex_);
    return texts_;
}

}  // namespace grading
