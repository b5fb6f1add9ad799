// Reading back what a `lab` grade-child left in its work directory
// (child.hpp: ChildOutputs), with limits: links, special files
// and anything over its size limit are refused; and how a child ended, in words.
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <vector>

#include "framework/error.hpp"
#include "grading/run/child.hpp"

namespace grading {

ChildOutputs::ChildOutputs(std::string dir, const ChildRun& run, const ChildLimits& limits,
                           std::map<std::string, std::string> streamed)
    : dir_(std::move(dir)), run_(run), streamed_(std::move(streamed)) {
    std::uint64_t total = directory_bytes(dir_);
    for (const auto& [name, bytes] : streamed_) total += bytes.size();
    if (total > limits.work_dir_cap)
        too_large_ = "output too large: the child left " + std::to_string(total) +
                     " bytes in its work directory, more than the " +
                     mib_text(limits.work_dir_cap) + " limit";
}

std::string ChildOutputs::missing_reason(const std::string& name) const {
    if (!run_.ok()) return "the child " + run_.status.text() + " before writing " + name;
    const std::string error_file = name.substr(0, name.find('.')) + ".error.txt";
    std::string text, why;
    if (error_file != name && read(error_file, 64 * 1024, text, why)) {
        while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
        return "the lab could not produce " + name + ": " + text;
    }
    return "the child exited normally without writing " + name;
}

bool ChildOutputs::read(const std::string& name, std::uint64_t limit, std::string& bytes,
                        std::string& why) const {
    std::string_view view;
    if (!read_view(name, limit, view, bytes, why)) return false;
    if (view.data() != bytes.data()) bytes.assign(view);
    return true;
}

bool ChildOutputs::read_view(const std::string& name, std::uint64_t limit, std::string_view& bytes,
                             std::string& storage, std::string& why) const {
    if (!too_large_.empty()) {
        why = too_large_;
        return false;
    }
    // What the child sent for this name stands for its file.
    if (const auto sent = streamed_.find(name); sent != streamed_.end()) {
        if (sent->second.size() > limit) {
            why = "output too large: " + name + " is " + std::to_string(sent->second.size()) +
                  " bytes, more than the limit of " + std::to_string(limit);
            return false;
        }
        bytes = sent->second;
        return true;
    }
    if (!read_file(name, limit, storage, why)) return false;
    bytes = storage;
    return true;
}

bool ChildOutputs::read_file(const std::string& name, std::uint64_t limit, std::string& bytes,
                             std::string& why) const {
    const std::string file = dir_ + "/" + name;
    struct stat st;
    if (lstat(file.c_str(), &st) != 0) {
        why = errno == ENOENT ? missing_reason(name) : name + ": " + std::strerror(errno);
        return false;
    }
    // A link could point at a reference image or any file course may read.
    if (!S_ISREG(st.st_mode) || st.st_nlink != 1) {
        why = name + " is not a regular file with one link; refused";
        return false;
    }
    if (static_cast<std::uint64_t>(st.st_size) > limit) {
        why = "output too large: " + name + " is " + std::to_string(st.st_size) +
              " bytes, more than the limit of " + std::to_string(limit);
        return false;
    }
    int fd = open(file.c_str(), O_RDONLY | O_NOFOLLOW | O_NONBLOCK | O_CLOEXEC);
    if (fd < 0) {
        why = "cannot read " + name + ": " + std::strerror(errno);
        return false;
    }
    // Read straight into `bytes`: room for the size lstat saw (within the
    // limit) and one byte more to see the file grow, widened while it does.
    bytes.resize(static_cast<size_t>(st.st_size) + 1);
    size_t got = 0;
    for (;;) {
        if (got == bytes.size()) {
            if (got > limit) break;
            bytes.resize(std::min<std::uint64_t>(limit + 1, 2 * std::uint64_t(got) + 4096));
        }
        const ssize_t n = ::read(fd, &bytes[got], bytes.size() - got);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        got += static_cast<size_t>(n);
    }
    close(fd);
    bytes.resize(got);
    if (bytes.size() > limit) {
        why = "output too large: " + name + " grew past " + std::to_string(limit) + " bytes";
        return false;
    }
    return true;
}

std::string signal_status(int signal) {
    const char* abbrev = sigabbrev_np(signal);
    return "crashed (signal " + std::to_string(signal) + ", " +
           (abbrev ? "SIG" + std::string(abbrev) : std::string("unknown")) + ")";
}

std::string indented_tail(const std::string& log, int lines) {
    std::vector<std::string> all;
    for (size_t pos = 0; pos < log.size();) {
        size_t nl = std::min(log.find('\n', pos), log.size());
        all.push_back(log.substr(pos, nl - pos));
        pos = nl + 1;
    }
    std::string out;
    for (size_t i = all.size() > size_t(lines) ? all.size() - size_t(lines) : 0; i < all.size();
         ++i)
        out += "    | " + (all[i].size() > 200 ? all[i].substr(0, 200) + "..." : all[i]) + "\n";
    return out;
}

}  // namespace grading
