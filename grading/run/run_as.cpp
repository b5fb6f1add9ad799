// --run-as: the user a child runs as, looked up once, and the switch to it
// (grading/run/run_as.hpp).
#include "grading/run/run_as.hpp"

#include <grp.h>
#include <pwd.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <vector>

#include "framework/error.hpp"
#include "grading/run/child.hpp"

namespace grading {

void switch_user(const RunAsUser& user, void (*fail)(const char*)) noexcept {
    // Groups first: after setuid the process may no longer change them.
    if (setgroups(user.groups.size(), user.groups.data()) != 0) fail("setgroups");
    if (setgid(user.gid) != 0) fail("setgid");
    if (setuid(user.uid) != 0) fail("setuid");
    if (getuid() != user.uid || geteuid() != user.uid || getegid() != user.gid)
        fail("setuid check");
}

RunAsUser lookup_user(const std::string& name) {
    if (geteuid() != 0)
        throw fw::UsageError(
            "--run-as " + name + " needs root, but course runs as uid " +
            std::to_string(geteuid()) +
            ": run course as root, or leave out --run-as to run the child as yourself");
    struct passwd pw, *found = nullptr;
    std::vector<char> buf(16384);
    if (getpwnam_r(name.c_str(), &pw, buf.data(), buf.size(), &found) != 0 || !found)
        throw fw::UsageError("--run-as: no user '" + name +
                             "' on this machine; name an existing unprivileged user, e.g. nobody");
    if (pw.pw_uid == 0)
        throw fw::UsageError("--run-as " + name +
                             ": that user is root, which would give the child "
                             "root's rights; name an unprivileged user, e.g. nobody");
    RunAsUser user{name, pw.pw_uid, pw.pw_gid, {}};
    int count = 64;
    user.groups.resize(static_cast<size_t>(count));
    while (getgrouplist(name.c_str(), pw.pw_gid, user.groups.data(), &count) < 0)
        user.groups.resize(static_cast<size_t>(count));
    user.groups.resize(static_cast<size_t>(count));
    return user;
}

bool user_can_access(const RunAsUser& user, const std::string& path, int mode) {
    pid_t pid = fork();
    if (pid < 0)
        throw fw::Error(std::string("cannot fork to test access: ") + std::strerror(errno));
    if (pid == 0) {
        switch_user(user, [](const char*) { _exit(126); });
        _exit(access(path.c_str(), mode) == 0 ? 0 : 1);
    }
    int status = 0;
    while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) > 1)
        throw fw::Error("cannot test what user '" + user.name + "' may do with '" + path +
                        "': switching to that user failed");
    return WEXITSTATUS(status) == 0;
}

}  // namespace grading
