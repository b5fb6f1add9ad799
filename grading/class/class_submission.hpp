// One submission of grade-class (grade_class.hpp): unpacked, its student
// files taken as the autograders take them, `lab` built, and each lab graded
// by `course grade` into DIR/students/KEY/LAB/, or taken from there when
// nothing it depends on changed.
#pragma once

#include <atomic>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "grading/class/build_lab.hpp"
#include "grading/class/submissions.hpp"

namespace grading::cls {

// What every submission is graded with.
struct ClassContext {
    std::filesystem::path root;      // the course's repository
    std::filesystem::path out;       // DIR
    std::filesystem::path versions;  // the student versions of the files (DIR/.class/...)
    std::string course, lab;         // the executables
    std::vector<std::pair<std::string, std::string>> labs;  // id, folder (NN_name)
    std::vector<std::string> files;                         // the student files of those labs
    // Per lab id: the hash of what its grade depends on besides the
    // submission (course, lab, the lab's checkpoints, references, options).
    std::map<std::string, std::string> course_hash;
    // The hash of what choosing a submission's files depends on besides the
    // submission: course, the student files and their starting versions.
    std::string take_hash;
    std::optional<std::time_t> deadline;
    std::string timeout, backend;
    const LabBuilder* builder = nullptr;
    const std::atomic<bool>* stop = nullptr;  // Ctrl-C: start nothing more
};

struct LabGrade {
    // "graded"; "not built"; "not graded"; else what stopped its child, as
    // the lab's report says it ("timed out after 60 s").
    std::string status = "graded";
    double score = 0, max_score = 0;
    std::string reason;    // why not graded
    bool resumed = false;  // taken from an earlier run
};

struct ClassRow {
    Submission submission;
    std::string graded;       // the commit graded, else the hash of the files taken
    int late = 0;             // commits after the deadline (git), 1 late (Gradescope)
    std::string error;        // it could not be unpacked
    std::string first_error;  // the compiler's first error, when it did not build
    std::vector<std::string> missing, extra;  // student files it lacks; files it has beyond them
    std::map<std::string, LabGrade> labs;     // by lab id
    double build_cpu = 0, seconds = 0;
    bool interrupted = false;
    bool graded_any() const;  // a lab was graded in this run (not resumed)
    bool failed() const;      // not unpacked, not built, or a lab not graded
};

ClassRow grade_submission(const ClassContext& context, const Submission& submission);

}  // namespace grading::cls
