// Checks (docs/contract.md, Checks): read from each lab's data file, validated before
// any child runs, turned into the job a `lab grade-child` carries out, and
// judged from its raw outputs by course alone.
//
// Check fields (every check: "kind", "points"; render checks may give
// "size": [w, h], default 512 x 512, the same for all checks of a checkpoint):
//   image  "tolerance" (0-255, default 8), "radius" (default 1: 3x3),
//          "max_fail_fraction" (default 0.001), against reference/CHECKPOINT.png
//   probe  "at": [x, y] window pixel (origin bottom-left) or "ndc": [x, y];
//          "color": [r, g, b(, a)] in 0..1 with "tolerance" (default 0.01), or
//          "depth": d in 0..1 with "tolerance" (default 1e-5)
//   stat   "stat": a dotted path into the frame's stats ("lab_stats.total_bytes");
//          "equals" (integers exactly; numbers within "tolerance" if given),
//          or "min" and/or "max"
//   unit   "function" (a reference in grading/units/), "random" (default 100)
//          fresh argument lists, "edge": [[args...], ...], "tolerance"
//          (default the reference's)
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/checkpoints.hpp"
#include "framework/image.hpp"
#include "grading/child.hpp"
#include "grading/results.hpp"

namespace grading {

// A lab as course sees it: its folder and data file, never its code.
struct LabData {
    std::string id;    // the data file's "lab", e.g. "pipeline"
    std::string dir;   // its folder under labs/, e.g. "00_pipeline"
    std::string root;  // the repository (source_root())
    fw::CheckpointFile file;

    // "labs/00_pipeline/reference/NAME.png", relative to root (for messages).
    std::string reference(const std::string& checkpoint) const;
    std::string reference_dir() const;  // absolute
};

// Every labs/*/checkpoints.json under root, in folder order (grade.cpp).
std::vector<LabData> discover_labs(const std::string& root);
// The named labs, all when `names` is empty; throws fw::UsageError listing the labs.
std::vector<LabData> select_labs(const std::vector<LabData>& all,
                                 const std::vector<std::string>& names);
// --lab, or `lab` beside course; throws fw::UsageError naming the path when missing.
std::string resolve_lab_binary(const std::string& given);

// Throws fw::UsageError naming the file, the checkpoint, the check and the field.
void validate_checks(const LabData& lab);

struct RenderPlan {
    std::string checkpoint;
    int width = 512, height = 512;
};
struct UnitCase {
    std::string id;  // key in units.json
    nlohmann::json args;
    bool edge = false;
};
struct UnitPlan {
    std::string checkpoint;
    size_t check = 0;  // index in the checkpoint's checks
    std::vector<UnitCase> cases;
};
// What one child is asked to do (job) and what course keeps to judge it.
struct LabPlan {
    nlohmann::json job;
    std::vector<RenderPlan> renders;
    std::vector<UnitPlan> units;
    unsigned seed = 0;
};
enum class PlanFor {
    Grading,   // every checkpoint with a render check, every unit check
    Blessing,  // only checkpoints with an image check; no units
};
LabPlan plan_lab(const LabData& lab, unsigned seed, PlanFor what);

// NAME.pam as the child wrote it: a regular file within its size limit, a
// PAM of the planned size; else false and why.
bool read_rendered(const ChildOutputs& outputs, const RenderPlan& render, fw::Image& image,
                   std::string& why);

// "shader error in shaders/04_geometry/explode.geom" when the child reports
// programs that failed to build (child.json's "shader_errors"); else empty.
std::string shader_error_status(const ChildOutputs& outputs);

// Every check of every checkpoint, from the child's raw outputs. Images for
// the report go to out_dir/<lab>/<checkpoint>[.expected|.diff].png. The
// checkpoints are judged on up to `threads` threads; the results come in the
// checkpoints' order whatever the number.
std::vector<CheckResult> judge_lab(const LabData& lab, const LabPlan& plan,
                                   const ChildOutputs& outputs, const std::string& out_dir,
                                   int threads = 1);

}  // namespace grading
