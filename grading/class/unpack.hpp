// The three ways a submission's files reach grade-class (submissions.hpp,
// unpack()): each writes only regular files under `dest`, each within
// `limits`, and says why when it refuses.
#pragma once

#include <filesystem>
#include <optional>
#include <string>

#include "grading/class/submissions.hpp"

namespace grading::cls {

// A folder's regular files (links and anything else left out).
Unpacked copy_folder(const std::filesystem::path& from, const std::filesystem::path& dest,
                     const UnpackLimits& limits);

// The content hash of what copy_folder would copy from `from` (each regular
// file's path and hash), without copying; none where copy_folder would
// refuse it or a file cannot be read.
std::optional<std::string> folder_key(const std::filesystem::path& from,
                                      const UnpackLimits& limits);

// A .zip or .tar(.gz) through libarchive: entries with an absolute path or a
// `..` refuse the archive; links and devices are left out.
Unpacked extract_archive(const std::filesystem::path& archive, const std::filesystem::path& dest,
                         const UnpackLimits& limits);

// A git repository through libgit2: the tree of the newest commit of HEAD's
// history whose commit time is at or before `deadline` (HEAD itself when
// none is given); Unpacked::commit names it, late_commits counts the newer
// ones. Links and submodules are left out.
Unpacked checkout_before(const std::filesystem::path& repository, const std::filesystem::path& dest,
                         std::optional<std::time_t> deadline, const UnpackLimits& limits);

// The commit checkout_before would take, and the late commits, without
// writing its tree (Unpacked::ok false where checkout_before refuses it for
// its history).
Unpacked commit_before(const std::filesystem::path& repository,
                       std::optional<std::time_t> deadline);

}  // namespace grading::cls
