// The state diff: for a checkpoint that failed a check, the student's record
// of what each draw was told (framework/trace/record.hpp, NAME.record.json from
// the child) against the solution's, kept by `course bless` beside the
// reference image (labs/NN_name/reference/CHECKPOINT.record.json). It names
// the first draw, dispatch, clear or read-back whose live state differs, in
// GL's terms (the call and its argument) and, where the lab has them, in the
// sheet's (labs/NN_name/grading/state_words.json); or says that the draws
// come in another order when they are the reference's, permuted. A record
// holds only live state and compares values, never calls, so what cannot
// change a result is never named (docs/contract.md, "The record and the state diff").
// The state check (grading/judge/state_check.cpp) gives its points where this
// sentence is empty, and says it where not.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/checkpoints.hpp"
#include "grading/diagnosis/lab_files.hpp"
#include "grading/results/results.hpp"
#include "grading/run/child.hpp"

namespace grading {

// Whether `j` is a record of this version (record.hpp).
bool valid_record(const nlohmann::json& j);
// The record in the file at `path`: a discarded value where it is not JSON.
nlohmann::json read_record(const std::string& path);

// labs/NN_name/reference/CHECKPOINT.record.json, relative to the root.
std::string reference_record(const LabFiles& lab, const std::string& checkpoint);
// Whether the checkpoint has a reference record: grading then asks the
// child for the student's ("record": true).
bool has_reference_record(const LabFiles& lab, const std::string& checkpoint);

// Throws fw::UsageError naming the first reference record of the lab that is
// not a record of this version (course grade checks them before grading;
// course bless writes them again).
void check_reference_records(const LabFiles& lab);

// Writes the solution's record of `checkpoint` (the child's
// NAME.record.json) as its reference; throws fw::Error when it is not a
// record of this version or cannot be written.
void write_reference_record(const LabFiles& lab, const std::string& checkpoint,
                            const std::string& text);

// The sentence that names the first difference between `student` and
// `reference` (records as record.hpp writes them), or "" when they agree.
// `words`: the lab's state_words.json (null when it has none); `visible`:
// the checkpoint is visible, so the reference's own value is not shown.
std::string state_difference(const nlohmann::json& student, const nlohmann::json& reference,
                             const fw::Checkpoint& checkpoint, const nlohmann::json& words,
                             bool visible);

// For a checkpoint with a failed check and a reference record: reads both
// records and the lab's words, and adds the sentence to the diagnosis (and
// output) of its first failed check that reads the frame, unless a failed
// state check of the checkpoint says it. Nothing when the records agree or
// cannot be read. Either way, the checks that hold a guess from their frame
// (CheckResult::FrameGuess) get the records' evidence.
void add_state_diff(const LabFiles& lab, const fw::Checkpoint& checkpoint,
                    const ChildOutputs& outputs, std::vector<CheckResult>& results);

}  // namespace grading
