// Frames of mistakes the course knows. The mistake suite (tests/mistakes/)
// applies each realistic mistake to the solution and grades it; with
// MISTAKES_RECORD=1 it keeps every frame that fails its image check, per
// checkpoint, in labs/NN_name/reference/mistakes/:
//
//   CHECKPOINT.json  {"frames": [{"image": "CHECKPOINT.1.png",
//                     "mistakes": [{"id": "pipeline-depth-greater",
//                                   "why": "thinks a larger depth is nearer the eye",
//                                   "file": "labs/00_pipeline/pipeline.cpp",
//                                   "units": [], "state": "Draw 1 of ..."}]}]}
//   CHECKPOINT.1.png ...
//
// (several mistakes that draw the same frame share its entry), each with its
// signature: the file it lives in, the functions whose unit checks it fails
// and what the state diff says of it at that checkpoint. A student's frame
// that fails its image check but matches one of these (each passes the
// comparison with the other) is named, where the evidence of the student's
// own grading agrees with the signature (frame_guesses.hpp): "Your frame is
// the one a known mistake draws (ID): the frame of code that WHY. Another
// mistake can draw the same frame: check whether your code does this."
#pragma once

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace grading {

struct KnownMistake {
    std::string id;   // the mistake suite's id
    std::string why;  // the misconception, a verb phrase: "thinks a larger depth is ..."
    // Its signature, the evidence a student's frame must agree with before
    // it is named (frame_guesses.hpp); each is absent from an older file:
    std::string file;                               // the repository file it lives in
    std::optional<std::vector<std::string>> units;  // the lab's unit checks it fails, by function
    std::optional<std::string> state;  // the state diff's sentence at the checkpoint ("": none)
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
// The same for some of a frame's mistakes (those the evidence agrees with).
std::string known_mistake_sentence(const std::vector<KnownMistake>& mistakes);

}  // namespace grading
