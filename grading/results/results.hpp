// What `course grade` found: one CheckResult per check of every checkpoint of
// every lab. The reports (summary.txt, results.json, junit.xml, index.html)
// are all written from this one structure.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "grading/sandbox/limits.hpp"

namespace grading {

// The kinds of check (docs/contract.md, Checks), and a checkpoint's
// visibility; their names are those of checkpoints.json and the reports.
enum class CheckKind { Image, Probe, Stat, Unit, Forbidden, Buffer, Portable, State };
enum class Visibility { Visible, Hidden };
// "image", "probe", "stat", "unit", "forbidden", "buffer", "portable", "state"
const char* name_of(CheckKind kind);
const char* name_of(Visibility visibility);  // "visible", "hidden"
// "visible" or "hidden" (fw::Checkpoint::visibility, checked when the file
// was read); throws fw::Error for anything else.
Visibility visibility_named(const std::string& name);

struct CheckResult {
    std::string lab;
    std::string checkpoint;
    CheckKind kind = CheckKind::Image;
    std::string title;  // e.g. "probe (256, 256) colour", "image vs reference"
    Visibility visibility = Visibility::Visible;
    double score = 0.0;
    double max_score = 0.0;
    bool passed = false;
    // Expected / observed, thresholds and measured figures, or why the check
    // could not run (the child crashed, timed out, wrote no image...).
    std::string output;
    // For the terminal (`course grade`'s failed checks), both also in
    // `output`: what most likely went wrong, a sentence a line (a unit
    // check's named mistakes, a NaN it returned), and a unit check's first
    // failing case as the report lays it out. Empty where there is none.
    std::string diagnosis, first_case;
    // Images for the HTML report, relative to the output directory; empty
    // where the check has none.
    std::string rendered, expected, difference;
    // A failed image check's frame as the course knows it, before and after
    // the evidence is weighed (grading/diagnosis/frame_guesses.hpp).
    struct FrameGuess {
        // The known mistakes' frame it matches (its image under
        // reference/mistakes/) and the other checkpoint whose expected frame
        // it is; "" where none.
        std::string mistake_image, checkpoint;
        // The state diff at this checkpoint: whether both records were there
        // to compare, and its sentence ("" where they agree).
        bool state_compared = false;
        std::string state;
        // For `checkpoint`: 1 when the student's record is that checkpoint's
        // reference record and the two checkpoints' records differ (the
        // parameters explain the draws), -1 when it is not, 0 when the
        // records cannot tell.
        int record_is_checkpoints = 0;
        // The lines said for them, in `output` and `diagnosis`.
        std::vector<std::string> lines;
    } guess;
};

// How a lab's child ended as a whole: it ran, or why it did not ("crashed
// (signal 11, SIGSEGV)", "timed out after 60 s", "exit status 1", "output
// unreadable: ...", "shader error in ...").
class LabStatus {
public:
    LabStatus() = default;  // it ran
    static LabStatus failed(std::string why);
    bool ok() const { return why_.empty(); }
    // "ok", or why it failed: what the reports print.
    const std::string& text() const;

private:
    std::string why_;
};

// A sum of points without the float residue of adding tenths (3.9 + 2 is
// 5.9, not 5.8999999999999995): rounded to a millionth.
double rounded_points(double sum);

// Where a lab's grading time went, in seconds (`course grade --verbose`
// prints it; no report holds it): its child's work, as its child.json says,
// and course's own. Each is wall time; course's judging sums its threads'.
struct LabTime {
    double plan = 0.0;  // course: the job, with the unit checks' random cases
    // The child: the unit calls, the context and the lab's init, the renders,
    // and within them the per-draw record and the checks of GL usage.
    double child_units = 0.0, child_start = 0.0, child_render = 0.0;
    double child_record = 0.0, child_usage = 0.0;
    double judge_units = 0.0;   // course: the unit checks against the references
    double judge_frames = 0.0;  // course: every other check
    double report = 0.0;        // course: the frames' images for the report
};

// A picture of the report page (index.html): the PNG as a data: URI and its
// shape ("W / H"); or, when it could not be read, why.
struct PageImage {
    std::string uri, aspect, why;
};

struct LabResult {
    std::string lab;
    LabStatus status;
    std::string log;  // the last part of the child's stdout and stderr
    double seconds = 0.0;
    std::vector<CheckResult> checks;
    // The hidden checkpoints this copy of the course does not have (a
    // student's copy: `course release` left them out), and their points.
    int hidden_left_out = 0;
    double hidden_points_left_out = 0.0;
    // Its state checks that a copy without the solution's records (a
    // student's) does not judge, and their points: the autograder judges them.
    int state_left_out = 0;
    double state_points_left_out = 0.0;
    // Its child's Mesa did not find its cache's key in --shader-cache
    // (seed_key_missed): said once on stderr, in no report.
    bool shader_cache_missed = false;
    LabTime time;
    // The page's pictures of this lab's checks, by their path in the report
    // folder, read while the child went on with the next lab
    // (report::read_page_images); the page reads any other itself.
    std::map<std::string, PageImage> page_images;

    double score() const;
    double max_score() const;
    bool passed() const;  // every check passed
};

struct GradeRun {
    std::vector<LabResult> labs;
    std::string backend;  // as asked: auto, osmesa, egl
    // The seed of the unit checks' random cases and where it came from
    // (grading/judge/course_seed.hpp), for summary.txt.
    unsigned seed = 0;
    std::string seed_from;
    double seconds = 0.0;
    // Seconds of CPU until the labs were judged (user and system): course's
    // own, all its threads (judging, the report's images), and its
    // children's (the labs' children, with whatever they started); negative
    // when not measured.
    double course_cpu_seconds = -1.0;
    double children_cpu_seconds = -1.0;
    // The sandbox's layers, active or not (grading/sandbox/sandbox.hpp), for
    // summary.txt, index.html and results.json.
    std::vector<SandboxLayer> sandbox;

    double score() const;
    double max_score() const;
    bool passed() const;
    // The labs' hidden checkpoints left out of this copy, and their points.
    struct LeftOut {
        int checkpoints = 0;
        double points = 0.0;
    };
    LeftOut hidden_left_out() const;
    // The labs' state checks left out of this copy (`checkpoints`: the
    // number of checks), and their points.
    LeftOut state_left_out() const;
};

}  // namespace grading
