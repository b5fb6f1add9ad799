// The `course` subcommands (docs/contract.md, `course`). Each returns the process exit
// status: 0 success (for grade: every check passed), 1 a check failed,
// 2 a usage or set-up error.
#pragma once

#include <string>
#include <vector>

#include "grading/report/reports.hpp"

namespace grading {

struct GradeOptions {
    std::vector<std::string> labs;  // empty: every lab with a labs/NN_name/checkpoints.json
    std::string lab_binary;         // --lab PATH; default: `lab` beside `course`
    std::string out = "build/grade";
    std::string backend;  // empty: $LAB_BACKEND or auto, decided by the child
    int jobs = 1;
    double timeout_seconds = 60.0;
    std::string run_as;  // --run-as USER (root only)
    // --format: what results.json holds, gradescope, prairielearn or
    // github-classroom; --results: where it goes (empty: into `out`).
    ResultsFormat format = ResultsFormat::Gradescope;
    std::string results;
    // --hidden-as: the visibility of a hidden checkpoint's test in
    // Gradescope's results.json (after_due_date, after_published or hidden).
    HiddenAs hidden_as = HiddenAs::AfterDueDate;
    bool progress = true;  // a line per lab as it finishes
    // --verbose: the sandbox's layers in a line after the total (summary.txt
    // and index.html have them always).
    bool verbose = false;
    // --shader-cache: a shader cache made by `course warm-cache`; each
    // child starts from its own copy. Empty: the driver's default.
    std::string shader_cache;
    // --sandbox: auto uses every layer the machine allows; strict refuses to
    // grade when namespaces or cgroups are missing.
    enum class Sandbox { Auto, Strict } sandbox = Sandbox::Auto;
    // --memory: the cgroup's memory limit per lab, in MiB (where there is one).
    int memory_mib = 2048;
    // --not-built FILE (`course autograde`): a JSON object from a lab's
    // folder to what the compiler said of its C++, which did not compile;
    // no child runs such a lab, and every check of it fails.
    std::string not_built;
};
int grade_command(const GradeOptions& options);

struct BlessOptions {
    std::vector<std::string> labs;  // empty: all
    std::string lab_binary;
    std::string backend;  // as for grade: empty is $LAB_BACKEND or auto (EGL, then OSMesa)
};
int bless_command(const BlessOptions& options);

// `course warm-cache`: renders every graded frame of the labs through the
// same children as grade, with Mesa's shader cache in `dir`, so that a later
// `course grade --shader-cache DIR` starts warm.
struct WarmCacheOptions {
    std::vector<std::string> labs;  // empty: all
    std::string lab_binary;
    std::string backend;
    std::string dir;
};
int warm_cache_command(const WarmCacheOptions& options);

// `course cases LAB`: records the lab's unit cases (grading/judge/cases.hpp)
// into `out` (empty: the lab's own cases.json, in labs/NN_name/grading/).
struct CasesOptions {
    std::string lab;
    std::string out;
    unsigned seed = 1;
    int max_random = 50;
};
int cases_command(const CasesOptions& options);

}  // namespace grading
