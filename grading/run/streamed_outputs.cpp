// The outputs a child sends on its output descriptor instead of files
// (child.hpp: StreamedOutputs), taken apart with the suspicion due to
// anything a submission produced.
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>

#include "grading/run/child.hpp"

namespace grading {

namespace {

constexpr size_t kHeaderMax = 4096;
constexpr size_t kReadChunk = 64 * 1024;
constexpr std::uint64_t kRecordMin = 4096;

// Whether the child may send PATH: DIR/NAME or DIR/I/NAME, NAME a plain
// file name.
bool valid_path(const std::string& dir, const std::string& path) {
    if (path.compare(0, dir.size() + 1, dir + "/") != 0) return false;
    std::string rest = path.substr(dir.size() + 1);
    const size_t slash = rest.find('/');
    if (slash != std::string::npos) {
        if (slash == 0 || rest.find_first_not_of("0123456789") != slash) return false;
        rest.erase(0, slash + 1);
    }
    return !rest.empty() && rest.size() <= 255 && rest != "." && rest != ".." &&
           rest.find('/') == std::string::npos && rest.find('\0') == std::string::npos;
}

}  // namespace

bool StreamedOutputs::header(const ChildLimits& limits, std::string& why) {
    const size_t nl = pending_.find('\n');
    const std::string line = pending_.substr(0, nl);
    pending_.erase(0, nl + 1);
    auto refuse = [&](const std::string& what) {
        why = "sent " + what + " on its output descriptor";
        return false;
    };
    const size_t space = line.find(' ', 7);
    if (line.compare(0, 7, "OUTPUT ") != 0 || space == std::string::npos || space == 7 ||
        space - 7 > 19 || line.find_first_not_of("0123456789", 7) != space)
        return refuse("something that is not an output record (a line \"OUTPUT SIZE PATH\")");
    const std::uint64_t size = std::stoull(line.substr(7, space - 7));
    const std::string path = line.substr(space + 1);
    if (!valid_path(dir_, path))
        return refuse("an output outside its work directory ('" + path.substr(0, 200) + "')");
    if (size > limits.file_cap)
        return refuse("an output of " + std::to_string(size) + " bytes, '" + path + "': over the " +
                      mib_text(limits.file_cap) + " limit per file");
    // At least a file system's block each, so that empty records are not free.
    received_ += std::max<std::uint64_t>(size, kRecordMin);
    if (lab_bytes() > limits.work_dir_cap) {
        why = "sent more than " + mib_text(limits.work_dir_cap) +
              " of outputs on its output descriptor, the limit of its work directory";
        return false;
    }
    body_path_ = path;
    body_ = &files_[path];
    body_->assign(static_cast<size_t>(size), '\0');
    got_ = std::min(pending_.size(), body_->size());
    std::memcpy(body_->data(), pending_.data(), got_);
    pending_.erase(0, got_);
    if (got_ == body_->size()) completed();  // complete already
    return true;
}

void StreamedOutputs::completed() {
    if (done_) done_(body_path_, *body_);
    body_ = nullptr;
}

bool StreamedOutputs::read(int fd, const ChildLimits& limits, bool all, std::string& why) {
    if (fill(fd, limits, all, why)) return true;
    // The child is stopped: nothing more is read, and what it sent stays.
    eof_ = true;
    if (body_) files_.erase(body_path_);
    body_ = nullptr;
    return false;
}

bool StreamedOutputs::fill(int fd, const ChildLimits& limits, bool all, std::string& why) {
    size_t budget = 16 * kMiB;
    while (!eof_ && (all || budget > 0)) {
        if (!body_ && pending_.find('\n') != std::string::npos) {
            if (!header(limits, why)) return false;
            continue;
        }
        if (!body_ && pending_.size() > kHeaderMax) {
            why =
                "sent something that is not an output record on its output descriptor (no "
                "end of line in " +
                std::to_string(kHeaderMax) + " bytes)";
            return false;
        }
        // A body is read straight into its string; anything else in chunks.
        char chunk[kReadChunk];
        char* into = body_ ? body_->data() + got_ : chunk;
        const size_t want = body_ ? body_->size() - got_ : sizeof chunk;
        const ssize_t n = ::read(fd, into, want);
        if (n < 0 && errno == EINTR) continue;
        if (n < 0) return true;  // empty for now (EAGAIN), or gone: its end comes next
        if (n == 0) {
            eof_ = true;
            // A record cut short: as if that file was never written.
            if (body_) files_.erase(body_path_);
            body_ = nullptr;
            return true;
        }
        budget -= std::min(budget, static_cast<size_t>(n));
        if (!body_) {
            pending_.append(chunk, static_cast<size_t>(n));
        } else if ((got_ += static_cast<size_t>(n)) == body_->size()) {
            completed();
        }
    }
    return true;
}

std::map<std::string, std::string> StreamedOutputs::take(const std::string& sub) {
    std::map<std::string, std::string> taken;
    const std::string prefix = sub + "/";
    for (auto it = files_.lower_bound(prefix);
         it != files_.end() && it->first.compare(0, prefix.size(), prefix) == 0;) {
        const std::string name = it->first.substr(prefix.size());
        // Not a record still being filled (body_ is one only until it is
        // complete), nor one of a lab folder below.
        if (name.find('/') != std::string::npos || &it->second == body_) {
            ++it;
            continue;
        }
        taken.emplace(name, std::move(it->second));
        it = files_.erase(it);
    }
    return taken;
}

}  // namespace grading
