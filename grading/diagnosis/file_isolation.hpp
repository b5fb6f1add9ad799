// Which file is wrong: a checkpoint whose frame fails is rendered again with
// one of the student's shader files replaced by the course's own, for each
// such file of the lab in turn. Where exactly one replacement makes every
// check of the checkpoint's frame pass, the failed checks say so: "The frame
// is right with the course's `silhouette.geom` in place of yours: the mistake
// is in shaders/10_advanced_geometry/silhouette.geom." (docs/contract.md,
// Which file is wrong).
#pragma once

#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "grading/diagnosis/lab_files.hpp"
#include "grading/results/results.hpp"
#include "grading/run/child.hpp"
#include "grading/sandbox/limits.hpp"

namespace grading {

// The children that render the replaced frames, as the lab's own child ran.
struct ChildSpawn {
    std::string lab_binary, backend;
    ChildLimits limits;
    const RunAsUser* user = nullptr;
    ShaderCache cache;
};

// Where an autograder keeps the course's own text of the student's shader
// files, under LAB_ROOT (lab.root), when LAB_ROOT's shaders/ holds the
// student's: solution_shaders/NN_name/FILE for shaders/NN_name/FILE. Only
// course reads it: `course autograde` keeps it from the --run-as user.
constexpr const char* kSolutionShaders = "solution_shaders";

// The student's shader files of `lab` and the course's text of each, by
// their path under shaders/ ("07_framebuffer_ops/cutout.frag"): the files of
// a shader stage (.vert .tesc .tese .geom .frag .comp) with a solution block
// in LAB_ROOT's solution_shaders/NN_name/ where LAB_ROOT has a
// solution_shaders/ folder, else in its shaders/NN_name/. None in a
// student's copy, which has no solution.
std::map<std::string, std::string> student_shaders(const LabFiles& lab);

// "The frame is right with the course's `NAME` in place of yours: the
// mistake is in shaders/FILE." for `file` under shaders/.
std::string file_isolation_sentence(const std::string& file);

// Whether every check of a checkpoint's frame (image, probe, stat, buffer
// and portable) passes on the frame a child wrote: the judge's verdict
// (grading/judge/checks.hpp, frame_checks_pass), which the caller gives, since
// the diagnosis judges nothing itself.
using FrameVerdict =
    std::function<bool(const std::string& checkpoint, const ChildOutputs& outputs)>;

// For `lab`, graded into `checks` (judge_lab's results) by a child that ran
// `job` (the plan's job, which `lab grade-child` reads) to its end: the
// checkpoints with a failed image, probe, buffer or portable check are
// rendered again, by one more child, once with the student's files as they
// are and once for each file of student_shaders() with the course's text in
// its place. A checkpoint whose frame fails again as it is, and passes with
// exactly one file replaced (`frame_passes`), gets the sentence once, under
// its first such failed check (`output` and `diagnosis`). Nothing runs where
// no such check failed or the lab has no student shader.
void isolate_shader_mistakes(const LabFiles& lab, const nlohmann::json& job,
                             const FrameVerdict& frame_passes, std::vector<CheckResult>& checks,
                             const ChildSpawn& spawn);

}  // namespace grading
