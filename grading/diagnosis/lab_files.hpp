// A lab as the diagnosis reads it: where its files are, its checkpoints file,
// and what the course keeps beside them to explain a failed check. The
// judge's LabData (grading/judge/checks.hpp) is one, with the checks parsed
// besides: the diagnosis reads no check, so that it stays below the judge.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/checkpoints.hpp"
#include "grading/diagnosis/known_mistakes.hpp"
#include "grading/diagnosis/starting_code.hpp"

namespace grading {

struct LabFiles {
    std::string id;       // the data file's "lab", e.g. "pipeline"
    std::string dir;      // its folder under labs/, e.g. "00_pipeline"
    std::string root;     // the repository (source_root())
    std::string sources;  // the student's source files (sources_root(root))
    fw::CheckpointFile file;
    // The frames of mistakes the course knows, per checkpoint (known_mistakes.hpp).
    MistakeFrames mistake_frames;
    // Where the sheet's parts are written (the file's "parts", starting_code.hpp).
    std::vector<PartPlace> parts;
    // The sheet's words for the state diff (state_words.hpp), checked; null
    // when the lab has none.
    nlohmann::json state_words;
};

// Reads from the lab's folder what the diagnosis rests on, into
// lab.mistake_frames, lab.parts (checked against the staff tree, with their
// starting hashes where the lab has a starting file) and lab.state_words;
// throws fw::UsageError naming the file.
void read_diagnosis_files(LabFiles& lab);

}  // namespace grading
