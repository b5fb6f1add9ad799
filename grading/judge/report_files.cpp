#include "grading/judge/report_files.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

#include "framework/error.hpp"

namespace grading {

namespace fs = std::filesystem;

void unshare_report_file(const std::string& path) {
    struct stat st;
    if (lstat(path.c_str(), &st) != 0) return;  // not there: written anew
    if (S_ISREG(st.st_mode) && st.st_nlink == 1) return;
    // A second name of a file, or no plain file at all: the name goes.
    std::error_code ec;
    fs::remove_all(path, ec);
    if (ec) throw fw::Error("cannot replace '" + path + "' in the report: " + ec.message());
}

void copy_into_report(const std::string& from, const std::string& to) {
    unshare_report_file(to);
    std::error_code ec;
    fs::copy_file(from, to, fs::copy_options::overwrite_existing, ec);
    if (ec) throw fw::Error("cannot copy " + from + " into the report: " + ec.message());
}

void write_report_png(const std::string& to, const fw::Image& image) {
    unshare_report_file(to);
    fw::write_png(to, image);
}

void link_in_report(const std::string& existing, const std::string& to) {
    // The frame's name from a grading before (Frame drops it where it was
    // already a second name): link() makes no name that exists.
    std::error_code ec;
    fs::remove_all(to, ec);
    if (ec) throw fw::Error("cannot replace '" + to + "' in the report: " + ec.message());
    if (link(existing.c_str(), to.c_str()) == 0) return;
    const int link_errno = errno;
    // EPERM, EXDEV, ENOTSUP, EMLINK: a filesystem (or a mount) without hard
    // links for this file; the same bytes as a copy.
    if (link_errno != EPERM && link_errno != EXDEV && link_errno != EOPNOTSUPP &&
        link_errno != EMLINK)
        throw fw::Error("cannot write '" + to + "' in the report: " + std::strerror(link_errno));
    copy_into_report(existing, to);
}

void keep_only(const std::string& dir, const std::set<std::string>& names) {
    std::error_code ec;
    if (!fs::is_directory(fs::symlink_status(dir, ec))) return;
    for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
        if (names.count(entry.path().filename().string())) continue;
        fs::remove_all(entry.path(), ec);
        if (ec)
            throw fw::Error("cannot remove '" + entry.path().string() +
                            "', left in the report by an earlier grading: " + ec.message());
    }
}

}  // namespace grading
