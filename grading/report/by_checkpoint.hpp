// The results of a lab grouped by checkpoint, as a student reads them: one
// entry per checkpoint with its checks inside, failures first, and small
// pictures of the frame, the reference and their difference. Gradescope's
// results.json, PrairieLearn's results.json, junit.xml and index.html are
// all written from these entries.
#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "grading/results/results.hpp"

namespace grading {

struct CheckpointResult {
    std::string checkpoint;
    Visibility visibility = Visibility::Visible;  // that of its checks
    std::vector<const CheckResult*> checks;       // failures first, then in the file's order
    double score = 0.0, max_score = 0.0;
    bool passed = true;
    // Relative to the output directory; empty where there is none: the frame
    // the checks read, and from its image check the reference and the
    // difference image.
    std::string rendered, expected, difference;
    bool image_failed = false;  // an image check of this checkpoint failed
};

// The checkpoints of `lab` in the order of its checkpoints file.
std::vector<CheckpointResult> by_checkpoint(const LabResult& lab);

// What a check reports: its output and, when it failed and the lab's child
// did not finish normally (a crash, a timeout, a shader error), why.
std::string check_output(const LabResult& lab, const CheckResult& check);

// The checkpoint as plain text: a line per check ("FAIL image vs reference,
// 0/2 points") followed by its output, indented; failures first.
std::string checkpoint_text(const LabResult& lab, const CheckpointResult& cp);

// Why a failed check failed, in one line: for an image check its largest
// kind of difference ("41,410 pixels: expected blue ..."), else its Observed
// line, or the first line of an output that has neither.
std::string check_failure(const LabResult& lab, const CheckResult& check);

// The first thing that went wrong in a checkpoint, in one line: the failed
// check's title and its Observed line (or its first line); empty when it passed.
std::string checkpoint_failure(const LabResult& lab, const CheckpointResult& cp);

// Small pictures (PNG or JPEG, whichever is smaller) for reports that must stay small
// (results.json: under 1 MB for the whole course), as data: URIs, at most `max_side` pixels on a
// side; never more than `budget` bytes of URIs in all: a checkpoint gets all of its pictures or
// none, and once one checkpoint's do not fit, later checkpoints get none either.
class Thumbnails {
public:
    Thumbnails(std::string out_dir, size_t budget, int max_side = 160);
    // Starts handing out pictures again with a new budget; the pictures
    // already made are kept, so a report written again with less room
    // (within_limit) decodes and encodes nothing twice.
    void restart(size_t budget);
    struct Picture {
        std::string label;  // rendered | expected | difference
        std::string uri;    // data:image/png;base64,... or data:image/jpeg;base64,...
    };
    // The pictures a failed checkpoint shows: its frame, the reference and,
    // when its image check failed, the difference. Empty when the checkpoint
    // passed, has no pictures, or they do not fit in what is left of the
    // budget (`left_out` is then set).
    std::vector<Picture> for_checkpoint(const CheckpointResult& cp, bool* left_out = nullptr);
    // How many checkpoints got no pictures because the budget was spent.
    size_t skipped() const { return skipped_; }
    size_t used() const { return used_; }

private:
    std::string uri(const std::string& relative, bool difference);
    std::string make_uri(const std::string& relative, bool difference);
    std::string out_dir_;
    std::map<std::string, std::string> made_;  // uri() by file and kind
    size_t budget_, used_ = 0, skipped_ = 0;
    int max_side_;
};

// results.json, in Gradescope's format and in PrairieLearn's, stays under 1 MB
// (PrairieLearn's limit, and a page a browser shows quickly).
constexpr size_t kResultsLimit = 900 * 1024;

// What `write()` returns with the largest budget for `thumbnails`' pictures
// (bytes of data: URIs) that keeps it within `limit` bytes: the text comes
// first, whatever it takes (written with a budget of 0), the pictures get
// what is left of `limit`, and less when the tables around them overshoot.
// When the text alone left no picture out, it is all there is, and it is
// not written again.
std::string within_limit(size_t limit, Thumbnails& thumbnails,
                         const std::function<std::string()>& write);

// The lab's number from its folder-free id ("03_shading" -> "3"), else
// `index`: Gradescope orders tests by number.
std::string lab_number(const LabResult& lab, size_t index);

// Standard base64 (RFC 4648, with padding).
std::string base64(const std::string& bytes);

}  // namespace grading
