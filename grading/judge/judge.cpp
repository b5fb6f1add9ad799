// Judging a lab's checks from what its child wrote. Only raw outputs count:
// pixels, depth values, stats numbers, buffers and unit results; whatever else the
// child claims (its stats' "params", extra fields) is ignored; child.json
// gives only the status line of a lab whose programs failed to build.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <map>
#include <optional>
#include <set>
#include <vector>

#include "framework/error.hpp"
#include "framework/text.hpp"
#include "grading/diagnosis/diagnosis.hpp"
#include "grading/judge/checks.hpp"
#include "grading/judge/frame.hpp"
#include "grading/judge/image_matches.hpp"
#include "grading/judge/judge_buffer.hpp"
#include "grading/judge/judge_portable.hpp"
#include "grading/judge/judge_source.hpp"
#include "grading/judge/judge_unit.hpp"
#include "grading/judge/judge_values.hpp"
#include "grading/run/parallel.hpp"

namespace grading {

namespace {

using nlohmann::json;
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// A failed frame that matches one the course knows is a guess, said once
// the evidence is in (say_frame_guesses); a part at its starting code is
// said in its place.
void note_matches(const LabData& lab, const fw::Checkpoint& cp, const fw::Image& image,
                  const fw::CompareOptions& opt, ReferenceImages& references,
                  const std::string& starting, CheckResult& r) {
    if (!starting.empty()) {
        r.diagnosis = starting;
        return;
    }
    const FrameMatches m = failed_frame_matches(lab, cp, image, opt, references);
    r.guess.mistake_image = m.mistake ? m.mistake->image : "";
    r.guess.checkpoint = m.checkpoint;
}

// `starting`: the sentence that a part the checkpoint needs still has its
// starting code (grading/diagnosis/starting_code.hpp), said in place of the
// frame's matches, which a missing part's frame is no evidence of.
void judge_image(const LabData& lab, const fw::Checkpoint& cp, const ImageCheck& check,
                 Frame& frame, const std::string& out_dir, ReferenceImages& references,
                 const std::string& starting, CheckResult& r) {
    r.title = "image vs reference";
    const fw::CompareOptions opt = check.options();
    const std::string side = std::to_string(2 * opt.radius + 1),
                      within = " is within " + std::to_string(opt.tolerance) + "/255";
    const std::string expected =
        "Expected: " + lab.reference(cp.name) + "; a pixel passes when a reference pixel in its " +
        side + "x" + side + " neighbourhood" + within +
        " on every channel, and the reference's pixel there has a rendered pixel in its " + side +
        "x" + side + " neighbourhood that" + within + "; at most " +
        num(opt.max_failed_fraction * 100) + "% of pixels may fail\n";
    std::string why;
    const fw::Image* image = frame.color(why);
    r.rendered = frame.rendered();
    if (!image) return verdict(r, false, expected + "Observed: " + why);
    const std::string ref_path = lab.root + "/" + lab.reference(cp.name);
    if (!std::filesystem::exists(ref_path))
        return verdict(r, false,
                       "missing reference " + lab.reference(cp.name) + "; run course bless");
    fw::Image reference;
    try {
        reference = fw::read_png(ref_path);
    } catch (const fw::Error& e) {
        return verdict(r, false, std::string(e.what()) + "; run course bless to write it again");
    }
    fw::CompareOptions verdict_only = opt;
    verdict_only.difference = false;
    fw::CompareResult c = fw::compare_images(*image, reference, verdict_only);
    // No report folder: the verdict alone (frame_checks_pass).
    if (out_dir.empty()) return verdict(r, c.passed, expected);
    r.expected = lab.id + "/" + cp.name + ".expected.png";
    copy_into_report(ref_path, out_dir + "/" + r.expected);  // not encoded again
    if (image->width == reference.width && image->height == reference.height &&
        std::memcmp(image->pixels.data(), reference.pixels.data(),
                    image->pixels.size() * sizeof(fw::Rgba8)) == 0)
        frame.same_pixels_as(out_dir + "/" + r.expected);
    // Where no pixel is beyond the tolerance, the difference image would be
    // the rendered frame in grey: none is written.
    if (!c.size_mismatch && c.failed_pixels > 0) {
        r.difference = lab.id + "/" + cp.name + ".diff.png";
        write_report_png(out_dir + "/" + r.difference,
                         fw::compare_images(*image, reference, opt).difference);
    }
    std::string where = c.passed ? "" : describe_difference(*image, reference, c);
    if (!c.passed && !c.size_mismatch) note_matches(lab, cp, *image, opt, references, starting, r);
    verdict(r, c.passed,
            expected + "Observed: " + c.summary() + (where.empty() ? "" : "\n" + where) +
                (r.diagnosis.empty() ? "" : "\n" + r.diagnosis));
}

// A buffer check, against the frame's buffers file.
void judge_frame_buffer(const BufferCheck& check, Frame& frame, const std::string& starting,
                        CheckResult& r) {
    std::string why;
    const std::vector<fw::LabBuffer>* buffers = frame.buffers(why);
    judge_buffer(check, buffers, why, r, starting);
}

// A portable check, against the frame's record of its GL usage.
void judge_frame_usage(Frame& frame, CheckResult& r) {
    std::string why, render_why;
    const std::vector<UsageFinding>* findings = frame.usage(why);
    const bool rendered = frame.color(render_why) != nullptr;
    r.rendered = frame.rendered();
    judge_portable(findings, why, rendered, render_why, r);
}

// units.json as the child wrote it, when the plan has unit cases; else (or
// when it cannot be read) null, and why in `why`. Parsed already where
// `early` parsed these bytes while the child rendered.
json read_units(const LabPlan& plan, const ChildOutputs& outputs, EarlyUnits* early,
                std::string& why) {
    json units;
    if (plan.units.empty()) return units;
    std::string storage;
    std::string_view bytes;
    if (outputs.read_view("units.json", kUnitsJsonMax, bytes, storage, why)) {
        std::optional<json> parsed = early ? early->take(bytes) : std::nullopt;
        units =
            parsed ? std::move(*parsed) : json::parse(bytes, nullptr, /*allow_exceptions=*/false);
        if (!units.is_object()) why = "units.json is not a JSON object";
    }
    return units;
}

// What a lab's checkpoints need from the lab's outputs as a whole.
struct LabInputs {
    const LabData& lab;
    const LabPlan& plan;
    const ChildOutputs& outputs;
    const std::string& out_dir;
    json units;
    std::string units_why;
    ReferenceImages references;  // other checkpoints' images, for a failed frame
};

// Check `i` of checkpoint `k`, on its frame (null when it renders none);
// `starting` as judge_image's.
void judge_check(LabInputs& in, size_t k, size_t i, const RenderPlan* render, Frame* frame,
                 const std::string& starting, CheckResult& result) {
    const fw::Checkpoint& cp = in.lab.file.checkpoints[k];
    const Check& check = in.lab.checks.at(k)[i];
    result.lab = in.lab.id;
    result.checkpoint = cp.name;
    result.kind = check.kind;
    result.visibility = in.lab.visibility.at(k);
    result.max_score = check.points;
    std::string own;
    switch (check.kind) {
        case CheckKind::Image:
            judge_image(in.lab, cp, check.as<ImageCheck>(), *frame, in.out_dir, in.references,
                        starting, result);
            break;
        case CheckKind::Probe:
            judge_probe(check.as<ProbeCheck>(), *render, *frame, result);
            break;
        case CheckKind::Stat:
            judge_stat(check.as<StatCheck>(), *frame, result);
            break;
        case CheckKind::Forbidden:
            judge_forbidden(in.lab, check.as<ForbiddenCheck>(), in.outputs.status(), result);
            break;
        case CheckKind::Buffer:
            judge_frame_buffer(check.as<BufferCheck>(), *frame, starting, result);
            break;
        case CheckKind::Portable:
            judge_frame_usage(*frame, result);
            break;
        case CheckKind::State:
            judge_state(in.lab, cp, in.outputs, result);
            break;
        case CheckKind::Unit:
            // A unit check's results are evidence of its own function: only
            // that function's starting code is said in place of its mistakes.
            if (!starting.empty())
                own = starting_code_sentence(in.lab.root, in.lab.sources, in.lab.parts, cp.parts,
                                             check.as<UnitCheck>().function);
            for (const UnitPlan& u : in.plan.units)
                if (u.checkpoint == cp.name && u.check == i)
                    judge_unit(in.lab, check.as<UnitCheck>(), u, in.plan.seed,
                               in.units.is_object() ? &in.units : nullptr, in.units_why, result,
                               own);
            break;
    }
}

// What this grading wrote into the lab's folder (its frames, and its
// checks' expected and difference images) stays; what an earlier one left
// there beside it goes.
void keep_written(const std::string& dir, const std::vector<std::string>& rendered,
                  const std::vector<CheckResult>& results) {
    std::set<std::string> written;
    auto keep = [&](const std::string& path) {
        if (!path.empty()) written.insert(fs::path(path).filename().string());
    };
    for (const std::string& path : rendered) keep(path);
    for (const CheckResult& c : results) {
        keep(c.expected);
        keep(c.difference);
    }
    keep_only(dir, written);
}

}  // namespace

bool frame_checks_pass(const LabData& lab, const LabPlan& plan, const std::string& checkpoint,
                       const ChildOutputs& outputs) {
    LabInputs in{lab, plan, outputs, "", json(), "", ReferenceImages(lab)};
    const auto render =
        std::find_if(plan.renders.begin(), plan.renders.end(),
                     [&](const RenderPlan& r) { return r.checkpoint == checkpoint; });
    const auto& checkpoints = lab.file.checkpoints;
    const auto k = static_cast<size_t>(
        std::find_if(checkpoints.begin(), checkpoints.end(),
                     [&](const fw::Checkpoint& cp) { return cp.name == checkpoint; }) -
        checkpoints.begin());
    if (render == plan.renders.end() || k == checkpoints.size()) return false;
    Frame frame(outputs, *render, lab.id, "");
    for (size_t i = 0; i < lab.checks.at(k).size(); ++i) {
        // The frame's own checks: a state check reads no frame.
        if (!lab.checks[k][i].renders() || lab.checks[k][i].kind == CheckKind::State) continue;
        CheckResult result;
        judge_check(in, k, i, &*render, &frame, "", result);
        if (!result.passed) return false;
    }
    return true;
}

namespace {

// One checkpoint judged: its checks' results, the name of its frame's image
// for the report (where it rendered), and the time each part took.
struct CheckpointJudged {
    std::vector<CheckResult> checks;
    std::string rendered;
    LabTime time;
};

void judge_checkpoint(LabInputs& in, size_t k, const RenderPlan* render, bool records,
                      CheckpointJudged& out) {
    const LabData& lab = in.lab;
    const fw::Checkpoint& checkpoint = lab.file.checkpoints[k];
    const Clock::time_point start = Clock::now();
    std::optional<Frame> frame;
    if (render) frame.emplace(in.outputs, *render, lab.id, in.out_dir);
    const std::string starting =
        starting_code_sentence(lab.root, lab.sources, lab.parts, checkpoint.parts);
    for (size_t i = 0; i < lab.checks.at(k).size(); ++i) {
        // A copy without the course's records (a student's) leaves its
        // state checks to the autograder (state_checks_left_out).
        if (!records && lab.checks[k][i].kind == CheckKind::State) continue;
        const Clock::time_point check_start = Clock::now();
        CheckResult result;
        judge_check(in, k, i, render, frame ? &*frame : nullptr, starting, result);
        if (lab.checks[k][i].kind == CheckKind::Unit) out.time.judge_units += since(check_start);
        out.checks.push_back(std::move(result));
    }
    say_starting_code(starting, out.checks);
    if (frame) {
        add_state_diff(lab, checkpoint, in.outputs, out.checks);
        const Clock::time_point publish_start = Clock::now();
        frame->publish();
        out.rendered = frame->rendered();
        out.time.report += since(publish_start);
    }
    // The rest: the frame read, the other checks, the state's difference.
    out.time.judge_frames = since(start) - out.time.judge_units - out.time.report;
}

}  // namespace

std::vector<CheckResult> judge_lab(const LabData& lab, const LabPlan& plan,
                                   const ChildOutputs& outputs, const std::string& out_dir,
                                   int threads, LabTime* time, EarlyUnits* early) {
    std::map<std::string, const RenderPlan*> renders;
    for (const RenderPlan& r : plan.renders) renders[r.checkpoint] = &r;
    LabInputs in{lab, plan, outputs, out_dir, json(), "", ReferenceImages(lab)};
    const Clock::time_point start = Clock::now();
    in.units = read_units(plan, outputs, early, in.units_why);
    const double read_seconds = since(start);
    // Each checkpoint's frame is decoded, compared and encoded for the
    // report on its own: the checkpoints go to `threads` threads.
    const std::vector<fw::Checkpoint>& checkpoints = lab.file.checkpoints;
    std::vector<CheckpointJudged> judged(checkpoints.size());
    const bool records = has_reference_records(lab);
    parallel_for(checkpoints.size(), threads, [&](size_t k) {
        const auto r = renders.find(checkpoints[k].name);
        judge_checkpoint(in, k, r == renders.end() ? nullptr : r->second, records, judged[k]);
    });
    std::vector<CheckResult> results;
    std::vector<std::string> rendered;
    for (CheckpointJudged& j : judged) {
        for (CheckResult& c : j.checks) results.push_back(std::move(c));
        rendered.push_back(j.rendered);
        if (!time) continue;
        time->judge_units += j.time.judge_units;
        time->judge_frames += j.time.judge_frames;
        time->report += j.time.report;
    }
    if (time) time->judge_units += read_seconds;
    say_frame_guesses(lab, results, nullptr);
    keep_written(out_dir + "/" + lab.id, rendered, results);
    return results;
}

}  // namespace grading
