// Guesses from a matching frame, weighed against the evidence. A failed image
// check's frame may be the frame of a mistake the course knows
// (known_mistakes.hpp) or another checkpoint's expected frame (the judge
// matches it: grading/judge/image_matches.hpp); either is only a guess, since
// other code can draw the same pixels. What this submission's grading measured
// at that checkpoint is evidence: its unit checks, the state diff of its
// records (state_diff.hpp) and which file's replacement puts the frame right
// (file_isolation.hpp). A guess is said only where that evidence agrees:
//
// - a known mistake, where each of its signature's parts that can be
//   compared agrees: the unit checks that fail here are those it fails (one
//   of them passing here, or another failing, rules it out), the state diff
//   here says what it says of the
//   mistake (nothing, or the same sentence), and the file that holds it is
//   the one file whose replacement puts the frame right (a replacement of
//   another file doing so, or of its own file not doing so, rules it out).
//   One ruled out is said as what it is: "The frame also matches a known
//   mistake (ID), but REASON, so it is not ID."
// - another checkpoint's frame ("your code most likely treats P as Q"),
//   where the student's draws are that checkpoint's reference draws and the
//   two checkpoints' draws differ (the parameters are then what explains
//   the frame); where the records cannot tell, only when no unit check of
//   the lab fails (which would be the likelier cause).
//
// The lines come last in the check's output and diagnosis, after the
// evidence itself (docs/contract.md, "Guesses from a frame").
#pragma once

#include <map>
#include <set>
#include <string>
#include <vector>

#include "framework/checkpoints.hpp"
#include "grading/diagnosis/known_mistakes.hpp"
#include "grading/diagnosis/lab_files.hpp"
#include "grading/results/results.hpp"

namespace grading {

// What file isolation found at a checkpoint: the student's shader files it
// replaced, by their path under shaders/ ("07_framebuffer_ops/solid.frag"),
// and the one whose replacement put the frame right ("" when none did, or
// more than one).
struct FrameIsolation {
    std::set<std::string> replaced;
    std::string puts_right;
};
using FrameIsolations = std::map<std::string, FrameIsolation>;  // by checkpoint

// Says, under each failed image check of `results` (one lab's, judge_lab's)
// that holds a guess, what the evidence supports, in place of the lines it
// said before (a second call, with `isolations`, weighs what file isolation
// found too). `isolations` may be null.
void say_frame_guesses(const LabFiles& lab, std::vector<CheckResult>& results,
                       const FrameIsolations* isolations);

// "Your frame is the one checkpoint OTHER expects (P there, here Q): your
// code most likely treats P Q as there." for a frame of `checkpoint` that is
// the expected frame of checkpoint `other`, with the parameters in which
// the two differ; "" when the lab has no checkpoint `other`.
std::string checkpoint_match_sentence(const LabFiles& lab, const fw::Checkpoint& checkpoint,
                                      const std::string& other);

// Why `mistake` is ruled out by the evidence of `guess` (its state diff),
// the unit checks of the lab that pass and fail (`unit_passes`, by
// function) and file isolation (null when it did not run); "" when nothing
// rules it out.
std::string ruled_out(const KnownMistake& mistake, const CheckResult::FrameGuess& guess,
                      const std::map<std::string, bool>& unit_passes,
                      const FrameIsolation* isolation);

}  // namespace grading
