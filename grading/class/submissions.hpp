// The submissions of a class, as `course grade-class SUBMISSIONS` finds them
// (docs/contract.md, `course grade-class`), and their files, unpacked:
// - Gradescope's "Export Submissions" folder: its submission_metadata.yml
//   names each submission folder's students (yaml-cpp);
// - a folder of git repositories (GitHub Classroom's `gh classroom clone
//   student-repos`): each graded at its last commit before the deadline
//   (libgit2);
// - a folder with one folder or archive (.zip, .tar.gz, .tgz, .tar) per
//   student, named by the student (libarchive).
#pragma once

#include <cstdint>
#include <ctime>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace grading::cls {

struct Student {
    std::string name, email, sid;
};

enum class SubmissionKind { Folder, Archive, Git };

struct Submission {
    // The folder of its reports under OUT/students/: the student's folder or
    // archive name (without the extension), or Gradescope's submission folder.
    std::string key;
    std::filesystem::path path;  // its folder, archive or repository
    SubmissionKind kind = SubmissionKind::Folder;
    std::vector<Student> students;  // from Gradescope's metadata; else none
    // When it was submitted (Gradescope's :created_at), where known.
    std::optional<std::time_t> submitted;
};

// Every submission under `dir`, sorted by key. Throws fw::UsageError when
// `dir` is no folder, or its submission_metadata.yml cannot be read (the
// file and the line); an entry that is none of the kinds above (a stray
// file) is left out and named in `skipped`.
std::vector<Submission> find_submissions(const std::filesystem::path& dir,
                                         std::vector<std::string>& skipped);

// Caps on what one submission may unpack to: an archive or a repository
// over them is refused with the reason, never unpacked in part.
struct UnpackLimits {
    std::uint64_t bytes = 64ull << 20;
    std::uint64_t files = 20000;
};

// What unpack() made of one submission.
struct Unpacked {
    bool ok = false;
    std::string error;   // why not, a sentence for the student's row
    std::string commit;  // git: the commit graded (its full id)
    // git: the commits after the deadline, left out (the submission is late
    // when there are any); Gradescope: 1 when it came after the deadline.
    int late_commits = 0;
};

// Writes the submission's files under `dest` (made, empty): a folder's
// regular files, an archive's (no absolute paths, no `..`, no links), a
// repository's tree at its last commit before `deadline` (none: its HEAD).
Unpacked unpack(const Submission& s, const std::filesystem::path& dest,
                std::optional<std::time_t> deadline, const UnpackLimits& limits = {});

// What identifies the files unpack() would write for `s`, found without
// writing them: the hash of a folder's files, of an archive's bytes, or git's
// commit. `u` says what unpack() would of its commit and lateness. "" when
// that cannot be said without unpacking (then unpack it: it may refuse).
std::string source_key(const Submission& s, std::optional<std::time_t> deadline, Unpacked& u,
                       const UnpackLimits& limits = {});

// "2026-12-04T23:59" or "2026-12-04 23:59:00", in UTC, or with a zone
// ("+01:00", "Z"); throws fw::UsageError saying what it expects.
std::time_t parse_time(const std::string& text);

}  // namespace grading::cls
