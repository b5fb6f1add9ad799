// The autograder's side of `course gradescope`. The folder itself is written
// by gradescope_command() (commands.hpp); its run_autograder
// (grading/gradescope/) is a shim that calls `course autograde` for each
// submission.
#pragma once

#include <string>

namespace grading {

// `course autograde [--root DIR] [--user USER] [--timeout SEC]` (autograde.cpp):
// grades the submission in ROOT/submission with the autograder folder in
// ROOT/source and writes ROOT/results/results.json, complete whatever the
// submission does; exits 0 unless its own arguments are wrong.
struct AutogradeOptions {
    std::string root = "/autograder";  // holds source/, submission/ and results/
    std::string user = "student";      // builds and runs the submission (when root)
    std::string timeout = "60";        // seconds each lab may run; passed on to `course grade`
};
int autograde_command(const AutogradeOptions& options);

// The reports of a run in which no lab could be graded (the submission does
// not build, or `course grade` itself failed), written into `out_dir`: every
// check of every lab, failed with `reason`, so results.json still lists every
// test with its points. The overall output is `reason` and the last 200 lines
// of `log_file` ("": none). Returns 1, the exit status of a failed grading.
int not_graded_command(const std::string& reason, const std::string& log_file,
                       const std::string& out_dir);

// The last `lines` lines of the file at `path`, taken from at most its last
// MiB; throws fw::Error when it cannot be read.
std::string log_tail(const std::string& path, int lines);

}  // namespace grading
