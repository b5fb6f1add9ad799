// Frames of mistakes the course knows. The mistake suite (tests/mistakes/)
// applies each realistic mistake to the solution and grades it; with
// MISTAKES_RECORD=1 it keeps every frame that fails its image check, per
// checkpoint, in labs/NN_name/reference/mistakes/:
//
//   CHECKPOINT.json  {"frames": [{"image": "CHECKPOINT.1.png",
//                     "mistakes": [{"id": "pipeline-depth-greater",
//                                   "why": "thinks a larger depth is nearer the eye"}]}]}
//   CHECKPOINT.1.png ...
//
// (several mistakes that draw the same frame share its entry). A student's
// frame that fails its image check but matches one of these (each passes
// the comparison with the other) is named: "Your frame is the one a known
// mistake draws (ID): the frame of code that WHY. Another mistake can draw
// the same frame: check whether your code does this." The frame is the only
// evidence, so the sentence names the misconception, never a file.
#pragma once

#include <map>
#include <string>
#include <vector>

namespace grading {

struct KnownMistake {
    std::string id;   // the mistake suite's id
    std::string why;  // the misconception, a verb phrase: "thinks a larger depth is ..."
};
struct MistakeFrame {
    std::string image;  // a PNG beside the checkpoint's file
    std::vector<KnownMistake> mistakes;
};
// Checkpoint name -> its known mistakes' frames.
using MistakeFrames = std::map<std::string, std::vector<MistakeFrame>>;

// "labs/NN_name/reference/mistakes", relative to the repository.
std::string mistake_frames_dir(const std::string& lab_dir);

// Every CHECKPOINT.json of the folder (none when it does not exist). Throws
// fw::UsageError naming the file for one that is not valid, names a
// checkpoint not in `checkpoints`, or names an image that is missing.
MistakeFrames read_mistake_frames(const std::string& root, const std::string& lab_dir,
                                  const std::vector<std::string>& checkpoints);

// The file's text for one checkpoint's frames (read_mistake_frames reads it back).
std::string mistake_frames_text(const std::vector<MistakeFrame>& frames);

// "Your frame is the one a known mistake draws (ID): the frame of code that
// WHY. Another mistake can draw the same frame: check whether your code does
// this." (with "or of" between several).
std::string known_mistake_sentence(const MistakeFrame& frame);

}  // namespace grading
