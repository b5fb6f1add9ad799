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
//   forbidden  "files": student files (relative to the repository), "names":
//          what they may not use (e.g. "glm::translate"), "rule": the sheet's
//          sentence that forbids it; passes when no name occurs in their code
//          (comments and string literals do not count)
//   buffer "buffer": a fw::LabBuffer's name, "reference": a buffer reference of
//          the lab (grading/units/buffer_reference.hpp), "tolerance" (absolute,
//          per float, default 1e-4); passes when the buffer holds the
//          reference's elements, each float within the tolerance
//   portable  no fields; passes when the child found no GL usage that the GL
//          4.3 specification leaves undefined or forbids (framework/trace/usage.hpp)
#pragma once

#include <array>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "framework/checkpoints.hpp"
#include "framework/image.hpp"
#include "grading/diagnosis/diagnosis.hpp"
#include "grading/judge/early_units.hpp"
#include "grading/results/results.hpp"
#include "grading/run/child.hpp"
#include "grading/run/repository.hpp"
#include "grading/units/buffer_reference.hpp"

namespace grading {

// A check as checkpoints.json gives it, parsed once (parse_checks), each
// default written here and nowhere else.
struct ImageCheck {
    int tolerance = 8;  // 0-255
    int radius = 1;     // 1: a 3x3 neighbourhood
    double max_fail_fraction = 0.001;
    fw::CompareOptions options() const {
        fw::CompareOptions o;
        o.tolerance = tolerance;
        o.radius = radius;
        o.max_failed_fraction = max_fail_fraction;
        return o;
    }
};
// A probe's tolerance when its check gives none: a colour's per channel, a depth's.
constexpr double kColorTolerance = 0.01, kDepthTolerance = 1e-5;
struct ProbeCheck {
    std::optional<std::array<int, 2>> at;  // a window pixel, origin bottom-left; else "ndc"
    std::array<double, 2> ndc{};
    std::vector<double> color;  // r, g, b(, a) in 0..1; empty for a depth probe
    double depth = 0.0;
    double tolerance = kColorTolerance;  // per channel; a depth probe's is kDepthTolerance
    bool reads_depth() const { return color.empty(); }
};
struct StatCheck {
    std::string stat;  // a dotted path into the frame's stats
    std::optional<nlohmann::json> equals;
    std::optional<double> tolerance;  // only with a numeric "equals"
    std::optional<double> min, max;
};
struct UnitCheck {
    std::string function;
    int random = 100;  // fresh argument lists
    std::vector<nlohmann::json> edge;
    std::optional<double> tolerance;  // default: the reference's
    // The random argument lists recorded in the lab's cases.json,
    // where its reference is a recorded one (cases.hpp): the plan takes
    // these instead of drawing `random` fresh ones.
    std::optional<std::vector<nlohmann::json>> recorded;
};
struct ForbiddenCheck {
    std::vector<std::string> files;  // relative to the repository
    std::vector<std::string> names;  // e.g. "glm::translate", "matrix_transform"
    std::string rule;                // the sheet's sentence
};

// A buffer check's expectation and its reference's known mistakes, computed
// by course from the checkpoint's params when the file is read.
constexpr double kBufferTolerance = 1e-4;
struct KnownBufferMistake {
    std::string id, sentence;  // BufferMistake's
    BufferExpectation values;
};
struct BufferCheck {
    std::string buffer;                   // the fw::LabBuffer's name
    std::string reference;                // a BufferReference's name
    double tolerance = kBufferTolerance;  // absolute, per float
    std::string element, verb;            // the reference's words: "particle", "is at"
    BufferExpectation expected;
    std::vector<KnownBufferMistake> mistakes;
};

// A portable check has nothing to set: what it reads is the render's record
// of its GL usage (NAME.usage.json).
struct PortableCheck {};

// A state check has nothing to set either: it compares the render's record
// of what each draw was told (NAME.record.json) with the solution's, which
// `course bless` keeps with the checkpoint's image
// (grading/diagnosis/state_diff.hpp), so a state the sheet fixes is checked
// even where today's frames agree.
struct StateCheck {};

struct Check {
    CheckKind kind = CheckKind::Image;
    double points = 0.0;
    std::variant<ImageCheck, ProbeCheck, StatCheck, UnitCheck, ForbiddenCheck, BufferCheck,
                 PortableCheck, StateCheck>
        spec;
    template <class T>
    const T& as() const {
        return std::get<T>(spec);
    }
    bool renders() const { return kind != CheckKind::Unit && kind != CheckKind::Forbidden; }
};

// A lab as course sees it: its folder and data file, never its code. What
// the diagnosis reads of it too (its folders, its checkpoints file, the
// known mistakes' frames, the parts' places, the state words) is the
// diagnosis's LabFiles (grading/diagnosis/lab_files.hpp).
struct LabData : LabFiles {
    // Each checkpoint's checks and its visibility, parsed (parse_checks), in
    // the file's order.
    std::vector<std::vector<Check>> checks;
    std::vector<Visibility> visibility;

    // "labs/00_pipeline/reference/NAME.png", relative to root (for messages).
    std::string reference(const std::string& checkpoint) const;
    std::string reference_dir() const;  // absolute
};

// Every labs/*/checkpoints.json under root, in folder order (labs.cpp).
std::vector<LabData> discover_labs(const std::string& root);
// The named labs, all when `names` is empty; throws fw::UsageError listing the labs.
std::vector<LabData> select_labs(const std::vector<LabData>& all,
                                 const std::vector<std::string>& names);

// Parses every check of the lab into lab.checks and each checkpoint's
// visibility into lab.visibility, after loading the lab's
// recorded unit cases where it has them (cases.json, cases.hpp), and then
// reads what the diagnosis rests on (read_diagnosis_files: the known
// mistakes' frames, the places of the sheet's parts, the state words);
// throws fw::UsageError naming the file, the checkpoint, the check and the
// field.
void parse_checks(LabData& lab);

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

// Where the child's time went, from its child.json's "seconds" (left as it
// is where the file or a field is missing): the child_* fields of `time`.
void child_seconds(const ChildOutputs& outputs, LabTime& time);

// Whether every check of `checkpoint` that judges its frame (image, probe,
// stat, buffer, portable) passes on the frame in `outputs`, judged as
// judge_lab judges it, writing no report file; false for a checkpoint the
// plan renders no frame of. File isolation asks it of the frames it renders
// again (grading/diagnosis/file_isolation.hpp).
bool frame_checks_pass(const LabData& lab, const LabPlan& plan, const std::string& checkpoint,
                       const ChildOutputs& outputs);

// A `state` check (StateCheck) of checkpoint `cp` into `r` (its points and
// visibility set): passes where the child's record of the draws and the
// reference record agree, else says the state diff's sentence
// (state_difference); fails, saying to bless, without the checkpoint's
// reference record (state_check.cpp).
void judge_state(const LabData& lab, const fw::Checkpoint& cp, const ChildOutputs& outputs,
                 CheckResult& r);

// Whether the lab's reference folder holds the course's records of the
// solution's draws (a student's copy holds none:
// grading/diagnosis/state_diff.hpp).
bool has_reference_records(const LabData& lab);

// The state checks that a copy without those records leaves out (judge_lab
// does not judge them: the autograder does), and their points.
struct StateLeftOut {
    int checks = 0;
    double points = 0.0;
};
StateLeftOut state_checks_left_out(const LabData& lab);

// Every check of every checkpoint, from the child's raw outputs. Images for
// the report go to out_dir/<lab>/<checkpoint>[.expected|.diff].png. The
// checkpoints are judged on up to `threads` threads; the results come in the
// checkpoints' order whatever the number. Where `time` is given, the
// judging's time goes into its judge_units, judge_frames and report.
// `early`, where given, may hold units.json parsed already (early_units.hpp).
std::vector<CheckResult> judge_lab(const LabData& lab, const LabPlan& plan,
                                   const ChildOutputs& outputs, const std::string& out_dir,
                                   int threads = 1, LabTime* time = nullptr,
                                   EarlyUnits* early = nullptr);

}  // namespace grading
