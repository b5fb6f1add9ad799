// GitHub Classroom's results.json (docs/contract.md, GitHub Classroom's
// results.json): the result of one runner as GitHub Classroom's autograding
// reporter reads it, from the per-checkpoint model the other results.json
// formats are written from (by_checkpoint.hpp). The workflow that
// `course release --github-classroom` writes passes it to the reporter,
// base64-encoded, in an environment variable.
#pragma once

#include <cstddef>
#include <string>

#include "grading/results/results.hpp"

namespace grading {

// Its most bytes: its base64 text must fit one environment variable, and
// Linux takes at most 128 KiB in one.
constexpr std::size_t kGitHubClassroomLimit = 64 * 1024;

// {"version": 1, "status": "pass"|"fail"|"error", "max_score", "tests"}: one
// test per checkpoint, with its points (the reporter adds up the tests'
// scores), its status, why it failed in a line (a hidden checkpoint: that its
// checks are not shown) and the command that checks its lab. The run's
// status is "pass" only when every check passed, "error" when a lab's child
// did not finish normally, else "fail". Within kGitHubClassroomLimit: the
// names and messages are cut to their share when they would not fit.
std::string github_classroom_results_json(const GradeRun& run);

}  // namespace grading
