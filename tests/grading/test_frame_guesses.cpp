// Guesses from a matching frame weighed against the evidence
// (grading/diagnosis/frame_guesses.hpp): for each kind of evidence (unit checks,
// the state diff, file isolation, the records for another checkpoint's
// frame), a guess it lets through and one it must rule out. The lab is a copy
// of lab 1's data with one known mistake's frame for `trs`; the results are
// built by hand, as judge_lab leaves them.
#include <filesystem>
#include <map>
#include <string>
#include <vector>

#include "framework/image.hpp"
#include "grading/diagnosis/frame_guesses.hpp"
#include "grading/diagnosis/known_mistakes.hpp"
#include "grading/judge/checks.hpp"
#include "tests/support/test_support.hpp"

namespace {

namespace fs = std::filesystem;
using grading::CheckKind;
using grading::CheckResult;
using grading::FrameIsolation;
using grading::FrameIsolations;
using grading::KnownMistake;

const std::string kNamed = "Your frame is the one a known mistake draws (transforms-late)";
const std::string kStateLine = "Draw 1 of scene `trs`: glUniformMatrix4fv's u_model is [1,0,0,0].";

// Lab 1's data under a new root, with `mistake` as the one known mistake
// whose frame (black) is trs.1.png.
grading::LabData lab_with(const KnownMistake& mistake) {
    const fs::path root = fs::path(fw::test::out_dir()) / "frame-guesses";
    const fs::path lab_dir = root / "labs" / "01_transforms";
    fs::remove_all(root);
    fs::create_directories(lab_dir / "reference" / "mistakes");
    const fs::path source = fs::path(fw::test::source_dir()) / "labs" / "01_transforms";
    fs::copy_file(source / "checkpoints.json", lab_dir / "checkpoints.json");
    for (const char* name : {"trs.png", "srt.png"})
        fs::copy_file(source / "reference" / name, lab_dir / "reference" / name);
    const fs::path folder = lab_dir / "reference" / "mistakes";
    fw::write_png((folder / "trs.1.png").string(), fw::Image(8, 8, fw::Rgba8{0, 0, 0, 255}));
    fw::test::write_text((folder / "trs.json").string(),
                         grading::mistake_frames_text({{"trs.1.png", {mistake}}}));
    std::vector<grading::LabData> labs = grading::discover_labs(root.string());
    REQUIRE(labs.size() == 1);
    grading::parse_checks(labs[0]);
    return labs[0];
}

KnownMistake late(std::string file, std::vector<std::string> units, std::string state) {
    return {"transforms-late", "multiplies on the wrong side", std::move(file), std::move(units),
            std::move(state)};
}

CheckResult failed_image(const std::string& mistake_image, const std::string& checkpoint) {
    CheckResult r;
    r.lab = "transforms";
    r.checkpoint = "trs";
    r.kind = CheckKind::Image;
    r.title = "image vs reference";
    r.output = "Expected: ...\nObserved: 5000 of 262144 pixels differ";
    r.guess.mistake_image = mistake_image;
    r.guess.checkpoint = checkpoint;
    return r;
}

CheckResult unit(const std::string& function, bool passed) {
    CheckResult r;
    r.lab = "transforms";
    r.checkpoint = "translate";
    r.kind = CheckKind::Unit;
    r.title = "unit " + function + " (101 cases)";
    r.passed = passed;
    return r;
}

// What the image check says once the guesses are weighed (its output; its
// diagnosis says the same lines).
std::string said(const grading::LabData& lab, std::vector<CheckResult> results,
                 const FrameIsolations* isolations = nullptr) {
    grading::say_frame_guesses(lab, results, isolations);
    for (const std::string& line : results[0].guess.lines)
        CHECK(results[0].diagnosis.find(line) != std::string::npos);
    return results[0].output;
}

}  // namespace

TEST_CASE("frame guesses: a unit check that the known mistake fails passes here, so it is not") {
    const grading::LabData lab =
        lab_with(late("labs/01_transforms/transforms_math.cpp", {"translate"}, ""));
    // translate() fails here too: the unit checks agree, it is named.
    std::string out = said(lab, {failed_image("trs.1.png", ""), unit("translate", false)});
    CHECK(out.find(kNamed) != std::string::npos);
    // translate() passes here: ruled out, and said as what it is.
    out = said(lab, {failed_image("trs.1.png", ""), unit("translate", true)});
    CHECK(out.find(kNamed) == std::string::npos);
    CHECK(out.find("The frame also matches a known mistake (transforms-late), but your "
                   "`translate()` passes its unit check, which transforms-late fails, so it is "
                   "not transforms-late.") != std::string::npos);
    // Another function's unit check that passes says nothing of this mistake;
    // one that fails, which the mistake passes, rules it out.
    out = said(lab,
               {failed_image("trs.1.png", ""), unit("translate", false), unit("rotate_z", true)});
    CHECK(out.find(kNamed) != std::string::npos);
    out = said(lab,
               {failed_image("trs.1.png", ""), unit("translate", false), unit("rotate_z", false)});
    CHECK(out.find(kNamed) == std::string::npos);
    CHECK(out.find("but your `rotate_z()` fails its unit check, which transforms-late passes") !=
          std::string::npos);
}

TEST_CASE("frame guesses: the state diff must say of the student what it says of the mistake") {
    // A mistake whose records agree with the solution's.
    grading::LabData lab = lab_with(late("labs/01_transforms/transforms_math.cpp", {}, ""));
    CheckResult agree = failed_image("trs.1.png", "");
    agree.guess.state_compared = true;
    CHECK(said(lab, {agree}).find(kNamed) != std::string::npos);
    CheckResult differs = agree;
    differs.guess.state = kStateLine;
    std::string out = said(lab, {differs});
    CHECK(out.find(kNamed) == std::string::npos);
    CHECK(out.find("but the state diff names a state of your draws that transforms-late leaves "
                   "as the solution has it, so it is not transforms-late.") != std::string::npos);
    // Records not compared (the checkpoint has none): the state says nothing.
    CheckResult uncompared = differs;
    uncompared.guess.state_compared = false;
    CHECK(said(lab, {uncompared}).find(kNamed) != std::string::npos);

    // A state mistake: the same sentence names it; none, or another, rules it out.
    lab = lab_with(late("labs/01_transforms/transforms.cpp", {}, kStateLine));
    CHECK(said(lab, {differs}).find(kNamed) != std::string::npos);
    out = said(lab, {agree});
    CHECK(out.find("but your draws are told the state the solution's are, and those of "
                   "transforms-late are not") != std::string::npos);
    CheckResult other = differs;
    other.guess.state = "Draw 2 of scene `trs`: GL_DEPTH_TEST is not enabled (glEnable).";
    out = said(lab, {other});
    CHECK(out.find(kNamed) == std::string::npos);
    CHECK(out.find("but the state diff names another state of your draws than that of "
                   "transforms-late") != std::string::npos);
}

TEST_CASE("frame guesses: file isolation must point at the mistake's own file") {
    grading::LabData lab = lab_with(late("shaders/01_transforms/transforms.vert", {}, ""));
    FrameIsolations found;
    // Its own file puts the frame right: named.
    found["trs"] = FrameIsolation{{"01_transforms/transforms.vert", "01_transforms/flat.frag"},
                                  "01_transforms/transforms.vert"};
    CHECK(said(lab, {failed_image("trs.1.png", "")}, &found).find(kNamed) != std::string::npos);
    // Another file does.
    found["trs"].puts_right = "01_transforms/flat.frag";
    std::string out = said(lab, {failed_image("trs.1.png", "")}, &found);
    CHECK(out.find(kNamed) == std::string::npos);
    CHECK(out.find("but the frame is right with the course's `flat.frag` in place of yours, and "
                   "transforms-late is in shaders/01_transforms/transforms.vert") !=
          std::string::npos);
    // None does, though its own file was replaced.
    found["trs"].puts_right = "";
    out = said(lab, {failed_image("trs.1.png", "")}, &found);
    CHECK(out.find("but your frame stays wrong with the course's `transforms.vert` in place of "
                   "yours, and transforms-late is in it") != std::string::npos);
    // Isolation at another checkpoint says nothing of this one.
    FrameIsolations elsewhere;
    elsewhere["srt"] = FrameIsolation{{"01_transforms/transforms.vert"}, ""};
    CHECK(said(lab, {failed_image("trs.1.png", "")}, &elsewhere).find(kNamed) != std::string::npos);
    // A mistake in C++: a shader that puts the frame right rules it out.
    lab = lab_with(late("labs/01_transforms/transforms_math.cpp", {}, ""));
    found["trs"] =
        FrameIsolation{{"01_transforms/transforms.vert"}, "01_transforms/transforms.vert"};
    CHECK(said(lab, {failed_image("trs.1.png", "")}, &found).find(kNamed) == std::string::npos);
    found["trs"].puts_right = "";
    CHECK(said(lab, {failed_image("trs.1.png", "")}, &found).find(kNamed) != std::string::npos);
}

TEST_CASE("frame guesses: another checkpoint's frame, where the draws are that checkpoint's") {
    const grading::LabData lab = lab_with(late("", {}, ""));
    const std::string treats = "Your frame is the one checkpoint srt expects";
    CheckResult r = failed_image("", "srt");
    r.guess.record_is_checkpoints = 1;
    CHECK(said(lab, {r}).find(treats) != std::string::npos);
    r.guess.record_is_checkpoints = -1;
    CHECK(said(lab, {r}).find(treats) == std::string::npos);
    // The records cannot tell: said only where no unit check fails.
    r.guess.record_is_checkpoints = 0;
    CHECK(said(lab, {r, unit("translate", true)}).find(treats) != std::string::npos);
    CHECK(said(lab, {r, unit("translate", false)}).find(treats) == std::string::npos);
}

TEST_CASE("frame guesses: said last, once, however often weighed") {
    const grading::LabData lab = lab_with(late("shaders/01_transforms/transforms.vert", {}, ""));
    std::vector<CheckResult> results = {failed_image("trs.1.png", "")};
    grading::say_frame_guesses(lab, results, nullptr);
    const std::string isolation =
        "The frame is right with the course's `transforms.vert` in place of yours: the mistake is "
        "in shaders/01_transforms/transforms.vert.";
    results[0].output += "\n" + isolation;
    results[0].diagnosis += "\n" + isolation;
    FrameIsolations found;
    found["trs"] =
        FrameIsolation{{"01_transforms/transforms.vert"}, "01_transforms/transforms.vert"};
    grading::say_frame_guesses(lab, results, &found);
    const std::string& out = results[0].output;
    CHECK(out.find(kNamed) != std::string::npos);
    CHECK(out.find(kNamed) == out.rfind(kNamed));   // once
    CHECK(out.find(isolation) < out.find(kNamed));  // the evidence first
    CHECK(results[0].diagnosis.rfind(isolation, 0) == 0);
}
