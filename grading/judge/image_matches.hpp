// A failed frame recognised: when a checkpoint's frame fails its image check
// but passes another checkpoint's (the same comparison, against that
// checkpoint's reference), the student's code most likely does for this
// checkpoint what it should do for the other one: lab 1's `trs` drawn in the
// order of `srt`, a camera that ignores `fov`. The report says so in one
// sentence, with the parameters in which the two checkpoints differ. A frame
// that matches the frame of a mistake the course knows
// (grading/diagnosis/known_mistakes.hpp) is named too. Frames match when they
// pass the comparison, which runs both ways. The matching is here, beside
// the image check whose comparison it runs again; the sentences, and the
// weighing of a match against the evidence, are the diagnosis's
// (grading/diagnosis/frame_guesses.hpp).
#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "framework/checkpoints.hpp"
#include "framework/image.hpp"
#include "grading/diagnosis/diagnosis.hpp"
#include "grading/judge/checks.hpp"

namespace grading {

// A lab's reference images, each decoded once however many checks read it,
// from any thread. Also keeps a coarse summary of each (block averages) that
// rules most pairs out without a full comparison.
class ReferenceImages {
public:
    explicit ReferenceImages(const LabData& lab) : lab_(lab) {}
    // The checkpoint's reference, or null when it has none (a student's copy
    // has no reference of a hidden checkpoint) or it cannot be read.
    const fw::Image* get(const std::string& checkpoint);

    // Block averages of an image: a 16 x 16 grid, each cell's mean per
    // channel (0-255).
    struct Summary {
        int width = 0, height = 0;
        std::vector<float> cells;
    };
    static Summary summarise(const fw::Image& image);

    // Whether `frame` (its summary `mine`) and the image at `relative` (a
    // path in the repository: a checkpoint's reference, a known mistake's
    // frame) pass a comparison under `options`, which runs both ways; false
    // when that image is missing or unreadable. The summaries rule most
    // pairs out.
    bool matches(const std::string& relative, const fw::Image& frame, const Summary& mine,
                 const fw::CompareOptions& options);

private:
    struct Entry {
        std::unique_ptr<fw::Image> image;  // null when missing or unreadable
        Summary summary;
    };
    const Entry& entry(const std::string& relative);  // by its path in the repository

    const LabData& lab_;
    std::mutex mutex_;
    std::map<std::string, std::unique_ptr<Entry>> entries_;
};

// What a frame of `checkpoint` that fails its own reference matches under
// `options`: the frame of a mistake the course knows (null when none), and
// the first other checkpoint of the lab with an image check whose reference
// it matches ("" when none). Guesses, which grading/diagnosis/frame_guesses.hpp weighs
// against the evidence before anything is said.
struct FrameMatches {
    const MistakeFrame* mistake = nullptr;
    std::string checkpoint;
};
FrameMatches failed_frame_matches(const LabData& lab, const fw::Checkpoint& checkpoint,
                                  const fw::Image& frame, const fw::CompareOptions& options,
                                  ReferenceImages& references);

// The sentence for a frame of `checkpoint` that fails its own reference
// under `options`: the first other checkpoint of the lab with an image check
// whose reference the frame matches under the same options, named with the
// parameters in which the two differ; empty when none matches.
std::string matching_checkpoint_sentence(const LabData& lab, const fw::Checkpoint& checkpoint,
                                         const fw::Image& frame, const fw::CompareOptions& options,
                                         ReferenceImages& references);

// The sentence for a frame of `checkpoint` that fails its own reference but
// matches, under `options`, the frame of a mistake the course knows
// (known_mistake_sentence); empty when none matches.
std::string known_mistake_frame_sentence(const LabData& lab, const fw::Checkpoint& checkpoint,
                                         const fw::Image& frame, const fw::CompareOptions& options,
                                         ReferenceImages& references);

// What a judge prints under a failed image check: the known mistake's
// sentence first (it says what the code does), then the other checkpoint's
// (which parameters it mixes up), a line each; empty when neither matches.
std::string failed_frame_diagnosis(const LabData& lab, const fw::Checkpoint& checkpoint,
                                   const fw::Image& frame, const fw::CompareOptions& options,
                                   ReferenceImages& references);

}  // namespace grading
