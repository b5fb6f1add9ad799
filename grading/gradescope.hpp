// The autograder's side of `course gradescope` (gradescope.cpp). The folder
// itself is written by gradescope_command() (commands.hpp); its scripts
// (grading/gradescope/) call back into `course` for what a shell script
// cannot do well.
#pragma once

#include <string>

namespace grading {

// `course not-graded --reason TEXT [--log FILE] --out DIR`: the reports of a
// run in which no lab could be graded (the submission does not build, or
// `course grade` itself failed): every check of every lab, failed with
// `reason`, so results.json still lists every test with its points. The
// overall output is `reason` and the last 200 lines of `log_file`.
int not_graded_command(const std::string& reason, const std::string& log_file,
                       const std::string& out_dir);

}  // namespace grading
