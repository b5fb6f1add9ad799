#include "tests/mistakes/mistake_frames.hpp"

#include <stdexcept>

#include "framework/image.hpp"
#include "tests/support/test_support.hpp"

namespace mistake_frames {

namespace {

// The first image check of checkpoint k, or null.
const grading::ImageCheck* image_check(const grading::LabData& lab, size_t k) {
    for (const grading::Check& c : lab.checks.at(k))
        if (c.kind == grading::CheckKind::Image) return &c.as<grading::ImageCheck>();
    return nullptr;
}

}  // namespace

Recorder::Recorder(const fs::path& source, fs::path scratch)
    : labs_(grading::discover_labs(source.string())), scratch_(std::move(scratch)) {
    for (grading::LabData& l : labs_) grading::parse_checks(l);
    fs::remove_all(scratch_);
    fs::create_directories(scratch_);
}

const grading::LabData& Recorder::lab(const std::string& dir) const {
    for (const grading::LabData& l : labs_)
        if (l.dir == dir) return l;
    throw std::runtime_error("no lab " + dir);
}

size_t Recorder::add(const std::string& lab_dir, const fs::path& out,
                     const grading::KnownMistake& signature,
                     const std::map<std::string, std::string>& states) {
    const grading::LabData& l = lab(lab_dir);
    size_t kept = 0;
    for (size_t k = 0; k < l.file.checkpoints.size() && kept < kFramesPerMistake; ++k) {
        const fw::Checkpoint& cp = l.file.checkpoints[k];
        const grading::ImageCheck* check = image_check(l, k);
        const fs::path png = out / l.id / (cp.name + ".png");
        if (cp.visibility != "visible" || !check || !fs::exists(png)) continue;
        const fw::Image frame = fw::read_png(png.string());
        const fw::CompareOptions options = check->options();
        const fw::Image reference = fw::read_png(l.root + "/" + l.reference(cp.name));
        if (fw::compare_images(frame, reference, options).passed) continue;
        ++kept;
        grading::KnownMistake m = signature;
        const auto state = states.find(cp.name);
        m.state = state == states.end() ? "" : state->second;
        std::vector<Kept>& frames = kept_[lab_dir][cp.name];
        bool joined = false;
        for (Kept& f : frames)
            if (!joined &&
                fw::compare_images(frame, fw::read_png(f.png.string()), options).passed) {
                f.frame.mistakes.push_back(m);
                joined = true;
            }
        if (joined) continue;
        const std::string image = cp.name + "." + std::to_string(frames.size() + 1) + ".png";
        fs::create_directories(scratch_ / lab_dir);
        fs::copy_file(png, scratch_ / lab_dir / image, fs::copy_options::overwrite_existing);
        frames.push_back({scratch_ / lab_dir / image, {image, {m}}});
    }
    return kept;
}

size_t Recorder::write(const fs::path& source, const std::set<std::string>& labs) const {
    size_t images = 0;
    for (const std::string& dir : labs) {
        const fs::path folder = source / grading::mistake_frames_dir(dir);
        fs::remove_all(folder);
        const auto lab = kept_.find(dir);
        if (lab == kept_.end()) continue;
        fs::create_directories(folder);
        for (const auto& [checkpoint, frames] : lab->second) {
            std::vector<grading::MistakeFrame> list;
            for (const Kept& f : frames) {
                fs::copy_file(f.png, folder / f.frame.image);
                list.push_back(f.frame);
                ++images;
            }
            fw::test::write_text(folder / (checkpoint + ".json"),
                                 grading::mistake_frames_text(list));
        }
    }
    return images;
}

}  // namespace mistake_frames
