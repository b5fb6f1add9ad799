// A checkpoint's frame as judge.cpp reads it: each output of the child read
// once for all the checkpoint's checks, and its PNG for the report.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "framework/error.hpp"
#include "grading/judge/checks.hpp"
#include "grading/judge/judge_buffer.hpp"
#include "grading/judge/judge_portable.hpp"
#include "grading/judge/report_files.hpp"

namespace grading {

// One checkpoint's frame, each output read once for all its checks.
class Frame {
public:
    // The frame's PNG goes into the report folder `out_dir` (none when it is
    // empty: a verdict only). A name it left there shared with the
    // reference's copy (a hard link) is dropped first, so that copying the
    // reference again writes that file in place.
    Frame(const ChildOutputs& outputs, const RenderPlan& plan, const std::string& lab,
          const std::string& out_dir)
        : outputs_(outputs), plan_(plan), out_dir_(out_dir) {
        const std::string name = lab + "/" + plan.checkpoint + ".png";
        if (!out_dir.empty()) unshare_report_file(out_dir + "/" + name);
        has_color_ = read_rendered(outputs, plan, color_, color_why_);
        if (has_color_) rendered_ = name;
    }
    const std::string& rendered() const { return rendered_; }

    // An image check found the frame pixel for pixel equal to the reference
    // whose copy in the report is `path`: publish() makes the frame's PNG a
    // second name of that file instead of encoding the frame.
    void same_pixels_as(const std::string& path) { same_as_ = path; }

    // The one PNG of the frame, for the reports, once its checks are done
    // (on the grading worker's thread, so --jobs spreads the encoding).
    void publish() const {
        if (!has_color_) return;
        const std::string to = out_dir_ + "/" + rendered_;
        same_as_.empty() ? write_report_png(to, color_) : link_in_report(same_as_, to);
    }

    const fw::Image* color(std::string& why) const {
        why = "no image: " + color_why_;
        return has_color_ ? &color_ : nullptr;
    }

    const fw::DepthImage* depth(std::string& why) {
        if (!depth_) {
            depth_.emplace();
            const std::string name = plan_.checkpoint + ".pfm";
            std::string bytes;
            const std::uint64_t limit = std::uint64_t(plan_.width) * plan_.height * 4 + 1024;
            if (!outputs_.read(name, limit, bytes, depth_why_)) {
                depth_.reset();
                depth_why_ = "no depth: " + depth_why_;
                depth_failed_ = true;
            } else {
                try {
                    // From the bytes read (and size-checked) above, never from
                    // the file again (rendered.cpp says why).
                    *depth_ = fw::decode_pfm(std::move(bytes), name);
                    if (depth_->width != plan_.width || depth_->height != plan_.height)
                        throw fw::Error(name + " is " + std::to_string(depth_->width) + "x" +
                                        std::to_string(depth_->height) + ", not the frame's size");
                } catch (const fw::Error& e) {
                    depth_.reset();
                    depth_why_ = "no depth: " + std::string(e.what());
                    depth_failed_ = true;
                }
            }
        }
        why = depth_why_;
        return depth_failed_ ? nullptr : &*depth_;
    }

    const nlohmann::json* stats(std::string& why) {
        if (!stats_tried_) {
            stats_tried_ = true;
            const std::string name = plan_.checkpoint + ".stats.json";
            std::string bytes;
            if (!outputs_.read(name, 1 * kMiB, bytes, stats_why_)) {
                stats_why_ = "no stats: " + stats_why_;
            } else {
                stats_ = nlohmann::json::parse(bytes, nullptr, /*allow_exceptions=*/false);
                if (!stats_.is_object()) stats_why_ = "no stats: " + name + " is not a JSON object";
            }
        }
        why = stats_why_;
        return stats_.is_object() ? &stats_ : nullptr;
    }

    const std::vector<fw::LabBuffer>* buffers(std::string& why) {
        if (!buffers_tried_) {
            buffers_tried_ = true;
            has_buffers_ = read_buffers(outputs_, plan_.checkpoint, buffers_, buffers_why_);
        }
        why = buffers_why_;
        return has_buffers_ ? &buffers_ : nullptr;
    }

    const std::vector<UsageFinding>* usage(std::string& why) {
        if (!usage_tried_) {
            usage_tried_ = true;
            has_usage_ = read_usage(outputs_, plan_.checkpoint, usage_, usage_why_);
        }
        why = usage_why_;
        return has_usage_ ? &usage_ : nullptr;
    }

private:
    const ChildOutputs& outputs_;
    RenderPlan plan_;
    std::string out_dir_;
    bool has_color_ = false;
    fw::Image color_;
    std::string color_why_, rendered_, same_as_;
    std::optional<fw::DepthImage> depth_;
    bool depth_failed_ = false;
    std::string depth_why_;
    bool stats_tried_ = false;
    nlohmann::json stats_;
    std::string stats_why_;
    bool buffers_tried_ = false, has_buffers_ = false;
    std::vector<fw::LabBuffer> buffers_;
    std::string buffers_why_;
    bool usage_tried_ = false, has_usage_ = false;
    std::vector<UsageFinding> usage_;
    std::string usage_why_;
};

}  // namespace grading
