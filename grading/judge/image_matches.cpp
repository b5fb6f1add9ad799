#include "grading/judge/image_matches.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <vector>

#include "framework/error.hpp"
#include "framework/text.hpp"

namespace grading {

namespace {

constexpr int kGrid = 16;
// Two images whose block averages differ by more than this (0-255) somewhere
// cannot pass a comparison at a tolerance of a few levels with 0.1% of
// pixels failing; the full comparison runs only below it.
constexpr float kSummaryGap = 24.0f;

bool close_summaries(const ReferenceImages::Summary& a, const ReferenceImages::Summary& b) {
    if (a.width != b.width || a.height != b.height || a.cells.size() != b.cells.size())
        return false;
    for (size_t i = 0; i < a.cells.size(); ++i)
        if (std::fabs(a.cells[i] - b.cells[i]) > kSummaryGap) return false;
    return true;
}

bool has_image_check(const LabData& lab, size_t k) {
    for (const Check& check : lab.checks.at(k))
        if (check.kind == CheckKind::Image) return true;
    return false;
}

}  // namespace

ReferenceImages::Summary ReferenceImages::summarise(const fw::Image& image) {
    Summary s;
    s.width = image.width;
    s.height = image.height;
    s.cells.assign(static_cast<size_t>(kGrid * kGrid * 3), 0.0f);
    std::vector<int> counts(kGrid * kGrid, 0);
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const int cell = (y * kGrid / std::max(1, image.height)) * kGrid +
                             x * kGrid / std::max(1, image.width);
            const fw::Rgba8& p = image.at(x, y);
            s.cells[cell * 3 + 0] += p.r;
            s.cells[cell * 3 + 1] += p.g;
            s.cells[cell * 3 + 2] += p.b;
            ++counts[cell];
        }
    for (int cell = 0; cell < kGrid * kGrid; ++cell)
        for (int c = 0; c < 3; ++c)
            if (counts[cell]) s.cells[cell * 3 + c] /= static_cast<float>(counts[cell]);
    return s;
}

const ReferenceImages::Entry& ReferenceImages::entry(const std::string& relative) {
    {
        std::lock_guard<std::mutex> lock(mutex_);
        auto found = entries_.find(relative);
        if (found != entries_.end()) return *found->second;
    }
    // Decoded outside the lock, so threads decode different images at once;
    // two threads may decode the same one, and the first stored wins.
    auto made = std::make_unique<Entry>();
    const std::string path = lab_.root + "/" + relative;
    if (std::filesystem::exists(path)) {
        try {
            made->image = std::make_unique<fw::Image>(fw::read_png(path));
            made->summary = summarise(*made->image);
        } catch (const fw::Error&) {
            made->image.reset();  // the check of its own checkpoint says why
        }
    }
    std::lock_guard<std::mutex> lock(mutex_);
    return *entries_.emplace(relative, std::move(made)).first->second;
}

const fw::Image* ReferenceImages::get(const std::string& checkpoint) {
    return entry(lab_.reference(checkpoint)).image.get();
}

bool ReferenceImages::matches(const std::string& relative, const fw::Image& frame,
                              const Summary& mine, const fw::CompareOptions& options) {
    const Entry& e = entry(relative);
    fw::CompareOptions verdict_only = options;
    verdict_only.difference = false;
    // The comparison runs both ways (fw::compare_images), so a frame that
    // lacks the other's thin lines does not match it: a name rests on frames
    // that are alike, not on one that fits inside the other.
    return e.image && close_summaries(mine, e.summary) &&
           fw::compare_images(frame, *e.image, verdict_only).passed;
}

namespace {

// The first other checkpoint with an image check whose reference `frame`
// matches; "" when none.
std::string matching_checkpoint(const LabData& lab, const fw::Checkpoint& checkpoint,
                                const fw::Image& frame, const ReferenceImages::Summary& mine,
                                const fw::CompareOptions& options, ReferenceImages& references) {
    const std::vector<fw::Checkpoint>& all = lab.file.checkpoints;
    for (size_t k = 0; k < all.size(); ++k) {
        const fw::Checkpoint& other = all[k];
        if (other.name != checkpoint.name && has_image_check(lab, k) &&
            references.matches(lab.reference(other.name), frame, mine, options))
            return other.name;
    }
    return "";
}

std::string checkpoint_sentence(const LabData& lab, const fw::Checkpoint& checkpoint,
                                const fw::Image& frame, const ReferenceImages::Summary& mine,
                                const fw::CompareOptions& options, ReferenceImages& references) {
    const std::string other =
        matching_checkpoint(lab, checkpoint, frame, mine, options, references);
    return other.empty() ? "" : checkpoint_match_sentence(lab, checkpoint, other);
}

const MistakeFrame* mistake_frame(const LabData& lab, const fw::Checkpoint& checkpoint,
                                  const fw::Image& frame, const ReferenceImages::Summary& mine,
                                  const fw::CompareOptions& options, ReferenceImages& references) {
    const auto known = lab.mistake_frames.find(checkpoint.name);
    if (known == lab.mistake_frames.end()) return nullptr;
    for (const MistakeFrame& m : known->second)
        if (references.matches(mistake_frames_dir(lab.dir) + "/" + m.image, frame, mine, options))
            return &m;
    return nullptr;
}

std::string mistake_sentence(const LabData& lab, const fw::Checkpoint& checkpoint,
                             const fw::Image& frame, const ReferenceImages::Summary& mine,
                             const fw::CompareOptions& options, ReferenceImages& references) {
    const MistakeFrame* m = mistake_frame(lab, checkpoint, frame, mine, options, references);
    return m ? known_mistake_sentence(*m) : "";
}

}  // namespace

FrameMatches failed_frame_matches(const LabData& lab, const fw::Checkpoint& checkpoint,
                                  const fw::Image& frame, const fw::CompareOptions& options,
                                  ReferenceImages& references) {
    const ReferenceImages::Summary mine = ReferenceImages::summarise(frame);
    FrameMatches out;
    out.mistake = mistake_frame(lab, checkpoint, frame, mine, options, references);
    out.checkpoint = matching_checkpoint(lab, checkpoint, frame, mine, options, references);
    return out;
}

std::string matching_checkpoint_sentence(const LabData& lab, const fw::Checkpoint& checkpoint,
                                         const fw::Image& frame, const fw::CompareOptions& options,
                                         ReferenceImages& references) {
    return checkpoint_sentence(lab, checkpoint, frame, ReferenceImages::summarise(frame), options,
                               references);
}

std::string known_mistake_frame_sentence(const LabData& lab, const fw::Checkpoint& checkpoint,
                                         const fw::Image& frame, const fw::CompareOptions& options,
                                         ReferenceImages& references) {
    return mistake_sentence(lab, checkpoint, frame, ReferenceImages::summarise(frame), options,
                            references);
}

std::string failed_frame_diagnosis(const LabData& lab, const fw::Checkpoint& checkpoint,
                                   const fw::Image& frame, const fw::CompareOptions& options,
                                   ReferenceImages& references) {
    const ReferenceImages::Summary mine = ReferenceImages::summarise(frame);
    std::vector<std::string> sentences;
    for (const std::string& s :
         {mistake_sentence(lab, checkpoint, frame, mine, options, references),
          checkpoint_sentence(lab, checkpoint, frame, mine, options, references)})
        if (!s.empty()) sentences.push_back(s);
    return fw::join(sentences, "\n");
}

}  // namespace grading
