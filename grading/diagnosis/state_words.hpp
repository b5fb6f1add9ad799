// The words of the state diff (state_diff.hpp) for a field of a record's
// event, given by its path ({"blend", "dst_rgb"}, {"textures", "0",
// "wrap_t"}): GL's, the call that sets it and its argument, and the sheet's,
// from the lab's labs/NN_name/grading/state_words.json (docs/contract.md,
// "The record and the state diff").
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/checkpoints.hpp"

namespace grading {

// The lab's labs/NN_name/grading/state_words.json under `root`, checked:
// null when the lab has none. Throws fw::UsageError naming the file and the
// entry for one that is not {"version": 1, "words": [{"field", "text",
// "when" (optional)}]} with non-empty strings, whose "when" is not an object
// of parameters the lab's checkpoints set, or that is not valid JSON.
nlohmann::json read_state_words(const std::string& root, const std::string& lab_dir,
                                const fw::CheckpointFile& file);

// GL's words for the field at `path` of an event that calls `call`
// ("glBlendFunc's destination factor"); the path itself where GL has none.
std::string gl_words(const std::vector<std::string>& path, const std::string& call);

// The sheet's sentence for the field at `path` in checkpoint `cp`: the entry
// of `words` (a state_words.json) with the longest field that is a prefix of
// the path, and then the most "when" params, all equal to the checkpoint's;
// "" when none applies.
std::string sheet_words(const nlohmann::json& words, const std::vector<std::string>& path,
                        const fw::Checkpoint& cp);

}  // namespace grading
