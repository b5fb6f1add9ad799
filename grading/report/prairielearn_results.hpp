// PrairieLearn's external grader (docs/contract.md, `course prairielearn`):
// its results.json, written from the same per-checkpoint model as
// Gradescope's (by_checkpoint.hpp), and the folder a course puts in its
// PrairieLearn repository.
#pragma once

#include <string>

#include "grading/results/results.hpp"

namespace grading {

// results.json in PrairieLearn's format (docs/contract.md, PrairieLearn's
// results.json): "gradable" true, "score" in [0, 1], the lab table as
// "message", the logs of labs whose child failed as "output", and one test
// per checkpoint with its points, what failed, its checks and small pictures
// (read from `out_dir`) within kResultsLimit. A hidden checkpoint shows its
// name and points only.
std::string prairielearn_results_json(const GradeRun& run, const std::string& out_dir);

// results.json for a submission that was not graded (it does not build, or
// the grader failed): "gradable" false, so that PrairieLearn counts neither
// points nor an attempt; `reason` as the message and the format error, `log`
// (the compiler's message, say) as the output, no tests.
std::string prairielearn_not_gradable_json(const std::string& reason, const std::string& log);

}  // namespace grading
