// The frames the mistake suite keeps for the grader: with MISTAKES_RECORD=1,
// every frame of a mistake that fails a visible checkpoint's image check
// (at most kFramesPerMistake per mistake, in the sheet's order) goes to
// labs/NN_name/reference/mistakes/ (grading/diagnosis/known_mistakes.hpp), where
// `course grade` names a student's frame that matches one.
#pragma once

#include <cstddef>
#include <filesystem>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "grading/judge/checks.hpp"

namespace mistake_frames {

namespace fs = std::filesystem;

constexpr size_t kFramesPerMistake = 2;

class Recorder {
public:
    // The labs of `source`; frames wait in `scratch` until write().
    Recorder(const fs::path& source, fs::path scratch);

    // Keeps the failing frames of the graded lab `lab_dir` (NN_name) that
    // `course grade --out out` wrote (out/LAB/CHECKPOINT.png); a frame that
    // matches one already kept for the checkpoint joins its entry. `m`
    // carries its signature's file and unit checks; `states` the state
    // diff's sentence per checkpoint (none: its records agree), which the
    // kept frame's entry gets. Returns how many frames it kept or joined.
    size_t add(const std::string& lab_dir, const fs::path& out, const grading::KnownMistake& m,
               const std::map<std::string, std::string>& states);

    // Replaces labs/NN_name/reference/mistakes/ of `source` for each of
    // `labs` with the frames kept (none: the folder is removed). Returns
    // the number of images written.
    size_t write(const fs::path& source, const std::set<std::string>& labs) const;

private:
    struct Kept {
        fs::path png;  // in scratch
        grading::MistakeFrame frame;
    };
    const grading::LabData& lab(const std::string& dir) const;

    std::vector<grading::LabData> labs_;
    fs::path scratch_;
    // lab dir -> checkpoint -> frames
    std::map<std::string, std::map<std::string, std::vector<Kept>>> kept_;
};

}  // namespace mistake_frames
