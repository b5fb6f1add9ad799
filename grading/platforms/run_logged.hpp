// A child process of `course autograde` (the build, course grade) whose
// output goes to a log, and to our stdout too when asked.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace grading {

// Runs `argv` (its first word looked up in PATH) with no stdin and its
// stdout and stderr written to `log`, and also to our stdout when `echo`.
// Returns its status as the shell would report it; 127 when it cannot start.
int run_logged(const std::vector<std::string>& argv, const std::filesystem::path& log, bool echo);

}  // namespace grading
