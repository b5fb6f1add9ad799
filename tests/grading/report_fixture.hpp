// What the report tests (test_reports, test_prairielearn_results,
// test_github_classroom) build their runs by hand from: a check result, the
// three small PNG files of an image check, and the lab whose child crashed;
// and a results.json's test by name.
#pragma once

#include <cstdint>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <vector>

#include "framework/image.hpp"
#include "grading/report/reports.hpp"
#include "tests/support/browser.hpp"
#include "tests/support/test_support.hpp"

namespace report_fixture {

const std::string kCrash = "crashed (signal 11, SIGSEGV)";

inline grading::CheckResult check(const std::string& lab, const std::string& checkpoint,
                                  const std::string& kind, const std::string& title, double score,
                                  double max_score, bool passed, const std::string& output,
                                  const std::string& visibility = "visible") {
    grading::CheckResult c;
    c.lab = lab, c.checkpoint = checkpoint, c.title = title;
    for (grading::CheckKind k :
         {grading::CheckKind::Image, grading::CheckKind::Probe, grading::CheckKind::Stat,
          grading::CheckKind::Unit, grading::CheckKind::Forbidden, grading::CheckKind::Buffer,
          grading::CheckKind::Portable})
        if (kind == grading::name_of(k)) c.kind = k;
    c.visibility = grading::visibility_named(visibility);
    c.score = score, c.max_score = max_score, c.passed = passed;
    c.output = output;
    return c;
}

// Writes dir/00_pipeline/triangle{,.expected,.diff}.png (4 x 3, one magenta
// pixel each) and returns their paths relative to dir.
inline std::vector<std::string> write_triangle_pngs(const std::string& dir) {
    std::filesystem::create_directories(dir + "/00_pipeline");
    std::vector<std::string> pngs;
    const char* names[] = {"triangle.png", "triangle.expected.png", "triangle.diff.png"};
    for (int i = 0; i < 3; ++i) {
        fw::Image img(4, 3, {static_cast<std::uint8_t>(80 * i), 200, 30, 255});
        img.at(1, 2) = {255, 0, 255, 255};
        pngs.push_back(std::string("00_pipeline/") + names[i]);
        fw::write_png(dir + "/" + pngs.back(), img);
    }
    return pngs;
}

// Lab 01 whose child crashed (kCrash): rotate's image 0/5 (its frame never
// written) and stat 0/2.
inline grading::LabResult crashed_transforms() {
    grading::LabResult transforms;
    transforms.lab = "01_transforms";
    transforms.status = grading::LabStatus::failed(kCrash);
    transforms.log = "Segmentation fault <core dumped> & more";
    transforms.seconds = 0.4;
    grading::CheckResult rotate = check("01_transforms", "rotate", "image", "image vs reference", 0,
                                        5, false, "the lab wrote no image");
    rotate.rendered = "01_transforms/rotate.png";  // never written: the child crashed
    transforms.checks.push_back(rotate);
    transforms.checks.push_back(
        check("01_transforms", "rotate", "stat", "primitives_generated == 2", 0, 2, false, ""));
    return transforms;
}

// `labs` labs of `checkpoints` failed checkpoints each (an image check with three
// 512 x 512 pictures of noise, which no encoder shrinks much, and a probe
// printing `output`), the pictures written once under dir/noise/.
inline grading::GradeRun large_run(const std::string& dir, int labs, int checkpoints,
                                   const std::string& output) {
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir + "/noise");
    std::mt19937 random(7);
    for (const char* name : {"frame", "expected", "diff"}) {
        fw::Image img(512, 512, {0, 0, 0, 255});
        for (int y = 0; y < 512; ++y)
            for (int x = 0; x < 512; ++x)
                img.at(x, y) = {static_cast<std::uint8_t>(random()),
                                static_cast<std::uint8_t>(random()),
                                static_cast<std::uint8_t>(random()), 255};
        fw::write_png(dir + "/noise/" + name + ".png", img);
    }
    grading::GradeRun run;
    for (int l = 0; l < labs; ++l) {
        grading::LabResult lab;
        lab.lab = "0" + std::to_string(l) + "_lab";
        for (int c = 0; c < checkpoints; ++c) {
            const std::string cp = "checkpoint_" + std::to_string(c);
            grading::CheckResult image =
                check(lab.lab, cp, "image", "image vs reference", 0, 2, false,
                      "Observed: 262144 of 262144 pixels (100%) differ by more than 8/255");
            image.rendered = "noise/frame.png", image.expected = "noise/expected.png";
            image.difference = "noise/diff.png";
            lab.checks.push_back(image);
            lab.checks.push_back(
                check(lab.lab, cp, "probe", "probe (256, 256) colour", 0, 1, false, output));
        }
        run.labs.push_back(lab);
    }
    return run;
}

// The test of a results.json (any of its formats) with this name; a failed
// check when there is none.
inline const nlohmann::json& test_named(const nlohmann::json& results, const std::string& name) {
    for (const nlohmann::json& t : results["tests"])
        if (t.value("name", "") == name) return t;
    FAIL("no test " << name);
    static const nlohmann::json none;
    return none;
}

// The independent base64 decoder (tests/support/browser.hpp) reads the
// pictures back.
using fw::test::base64_decode;

}  // namespace report_fixture
