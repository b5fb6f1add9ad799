// Which submitted file stands for each file students edit, for `course
// autograde` (autograde.cpp): the submission's own, by path or by file name,
// else the student version; never the solution.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace grading {

// Whether `a` and `b` are regular files with the same bytes (cmp -s).
bool same_contents(const std::filesystem::path& a, const std::filesystem::path& b);

// Overwrites `to` in place (its mode and owner stay; its time changes).
bool copy_contents(const std::filesystem::path& from, const std::filesystem::path& to);

// The non-empty lines of the autograder's student_files.txt; throws
// fw::Error saying how to write it again when it cannot be read.
std::vector<std::string> read_lines(const std::filesystem::path& path);

// Which file stands for one student file, and how the log describes it.
struct Chosen {
    std::filesystem::path from;
    std::string how;
};

// Picks the submitted files: each file students edit is taken from the
// submission at the same path, else from the one file of that name anywhere
// in the submission (uploads may be flat), else from the student version;
// never the solution. Links that leave the submission, and anything but
// regular files, are not taken.
class SubmittedFiles {
public:
    SubmittedFiles(const std::filesystem::path& submission, const std::filesystem::path& versions,
                   const std::vector<std::string>& files);
    Chosen choose(const std::string& rel) const;

private:
    // Whether `path` leads to a regular file inside the submission.
    bool inside(const std::filesystem::path& path) const;

    std::filesystem::path submission_;
    std::string real_;  // "" when there is no submission folder
    std::filesystem::path versions_;
    std::map<std::string, int> names_;  // file name -> how many student files have it
};

}  // namespace grading
