// A `buffer` check (docs/contract.md, Checks): what the lab's shaders wrote
// into a buffer (NAME.buffers.json, framework/lab_buffers.hpp) against
// course's reference, computed from the checkpoint's params
// (grading/units/buffer_reference.hpp). Parsed when checkpoints.json is read,
// judged from the child's file, which is read as hostile input: size-limited,
// and every malformation a sentence in the check's output.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "framework/lab.hpp"
#include "grading/judge/checks.hpp"
#include "grading/results/results.hpp"

namespace grading {

class CheckWhere;

// The largest NAME.buffers.json course reads.
constexpr std::uint64_t kBuffersFileLimit = 4 * kMiB;

// "buffer", "reference", "tolerance" of a check; the reference called on the
// checkpoint's params as written, and each of its mistakes. Where course has
// no compiled reference of that name, what `recorded` holds for the check
// (the lab's cases.json, cases.hpp; null when none). Throws fw::UsageError
// (CheckWhere::fail) for a missing or wrong field, an unknown reference, a
// param the reference needs that the checkpoint lacks, or a reference that
// cannot take the params.
BufferCheck parse_buffer(const CheckWhere& w, const LabData& lab, const fw::Checkpoint& cp,
                         const BufferCheck* recorded = nullptr);

// The checkpoint's NAME.buffers.json; false and why (missing, too large, not
// a buffers file) when it cannot be read.
bool read_buffers(const ChildOutputs& outputs, const std::string& checkpoint,
                  std::vector<fw::LabBuffer>& buffers, std::string& why);

// The check against `buffers` (null when they could not be read: `why`).
// `starting`, when not empty, says that a part the checkpoint needs still has
// its starting code (grading/diagnosis/starting_code.hpp): a failing check says
// it in place of a known mistake, which such a buffer is no evidence of.
void judge_buffer(const BufferCheck& check, const std::vector<fw::LabBuffer>* buffers,
                  const std::string& why, CheckResult& r, const std::string& starting = "");

}  // namespace grading
