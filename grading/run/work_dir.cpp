// WorkDir (child.hpp): a child's private working directory, and the bytes in it.
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "framework/error.hpp"
#include "grading/run/child.hpp"

namespace grading {

namespace fs = std::filesystem;

WorkDir::WorkDir(const RunAsUser* user) {
    const char* tmp = std::getenv("TMPDIR");
    std::string pattern = std::string(tmp && *tmp ? tmp : "/tmp") + "/course-XXXXXX";
    std::vector<char> name(pattern.begin(), pattern.end());
    name.push_back('\0');
    if (!mkdtemp(name.data()))  // mode 0700
        throw fw::Error("cannot create a work directory '" + pattern +
                        "': " + std::strerror(errno) + "; set TMPDIR to a writable directory");
    path_ = name.data();
    user_ = user;
}

void WorkDir::hand_over() {
    if (!user_) return;
    auto give = [this](const std::string& path) {
        if (lchown(path.c_str(), user_->uid, user_->gid) != 0)
            throw fw::Error("cannot give '" + path + "' in the work directory to user '" +
                            user_->name + "': " + std::strerror(errno));
    };
    give(path_);
    // Nothing of the user's is in it yet: these are course's own files.
    for (const fs::directory_entry& e : fs::recursive_directory_iterator(path_))
        give(e.path().string());
}

std::uint64_t directory_bytes(const std::string& dir) {
    std::uint64_t total = 0;
    std::error_code ec;
    for (fs::recursive_directory_iterator
             it(dir, fs::directory_options::skip_permission_denied, ec),
         end;
         !ec && it != end; it.increment(ec)) {
        struct stat st;
        if (lstat(it->path().c_str(), &st) == 0 && S_ISREG(st.st_mode))
            total += static_cast<std::uint64_t>(st.st_size);
    }
    return total;
}

WorkDir::~WorkDir() {
    std::error_code ec;
    // Take the directory back first, so that nothing left of the user's can
    // write into it while it is removed; remove_all does not follow links.
    if (user_ && chown(path_.c_str(), 0, 0) == 0) chmod(path_.c_str(), 0700);
    fs::remove_all(path_, ec);
}

}  // namespace grading
