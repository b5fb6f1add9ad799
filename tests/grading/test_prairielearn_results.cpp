// PrairieLearn's results.json (docs/contract.md, PrairieLearn's results.json),
// written by `course grade --format prairielearn` for runs built by hand: a
// failed checkpoint with real PNG files, a hidden one that passed and a
// hidden one that failed, and a lab whose child crashed; then a large failing
// run with big pictures, and one with huge outputs, which must stay under
// 1 MB. Expected numbers come from the fixture's own constants.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/image.hpp"
#include "grading/report/by_checkpoint.hpp"
#include "grading/report/prairielearn_results.hpp"
#include "grading/report/reports.hpp"
#include "tests/grading/prairielearn_support.hpp"
#include "tests/grading/report_fixture.hpp"
#include "tests/support/test_support.hpp"

namespace {

namespace fs = std::filesystem;
using grading::CheckResult;
using grading::GradeRun;
using grading::LabResult;
using nlohmann::json;
using prairielearn_test::check_schema;
using prairielearn_test::Picture;
using report_fixture::base64_decode;
using report_fixture::check;
using report_fixture::crashed_transforms;
using report_fixture::kCrash;
using report_fixture::large_run;
using report_fixture::test_named;
using report_fixture::write_triangle_pngs;

const grading::ResultsFile kPrairieLearn{grading::ResultsFormat::PrairieLearn, ""};

json read_json(const std::string& path) {
    const std::string text = fw::test::read_text(path);
    REQUIRE_MESSAGE(!text.empty(), "cannot read " << path);
    return json::parse(text);
}

// Lab 00: triangle (image 4/4 passed, probe 0/2 failed), secret (hidden, unit
// 3/3 passed), vault (hidden, probe 0/1 failed, with a frame). Lab 01
// crashed: rotate (image 0/5, stat 0/2). 7 of 17 points; 1 of 4 checkpoints passed.
struct Fixture {
    std::string dir = fw::test::out_dir() + "/fixture";
    GradeRun run;
    std::vector<std::string> pngs;  // the triangle's frame, reference and difference

    Fixture() {
        fs::remove_all(dir);
        pngs = write_triangle_pngs(dir);
        LabResult pipeline;
        pipeline.lab = "00_pipeline";
        pipeline.seconds = 1.5;
        CheckResult image = check("00_pipeline", "triangle", "image", "image vs reference", 4, 4,
                                  true, "Observed: 0 of 12 pixels differ");
        image.rendered = pngs[0], image.expected = pngs[1], image.difference = pngs[2];
        pipeline.checks.push_back(image);
        pipeline.checks.push_back(
            check("00_pipeline", "triangle", "probe", "probe (8, 8) colour", 0, 2, false,
                  "Expected (1, 0, 0) < observed & \"quoted\" \x1b[31mred\x01 "
                  "\xff\ntolerance 1/255"));
        pipeline.checks.push_back(check("00_pipeline", "secret", "unit", "unit spin(v, <angle>)", 3,
                                        3, true, "32 inputs within 1e-5", "hidden"));
        CheckResult vault = check("00_pipeline", "vault", "probe", "probe (1, 1) vault colour", 0,
                                  1, false, "Expected: secret-value 42\nObserved: 41", "hidden");
        vault.rendered = pngs[0];
        pipeline.checks.push_back(vault);

        LabResult transforms = crashed_transforms();
        run.labs = {pipeline, transforms};
        run.backend = "osmesa";
        run.seconds = 1.76;
        grading::write_reports(run, dir, kPrairieLearn);
    }
};

// A run of `labs` labs of `checkpoints` failed checkpoints each, every one
// with an image check on the same three 512 x 512 pictures of noise (which
// compress badly), and the given output on its probe.
}  // namespace

TEST_CASE("prairielearn results.json: the documented fields, one test per checkpoint") {
    Fixture f;
    const std::string text = fw::test::read_text(f.dir + "/results.json");
    const json j = json::parse(text);
    INFO(j.dump(2));
    check_schema(j);
    CHECK(j["gradable"] == true);
    CHECK(j["score"].get<double>() == doctest::Approx(7.0 / 17.0));
    REQUIRE(j["tests"].size() == 4);
    const std::vector<std::string> names = {"00_pipeline / triangle", "00_pipeline / secret",
                                            "00_pipeline / vault", "01_transforms / rotate"};
    for (size_t i = 0; i < names.size(); ++i) CHECK(j["tests"][i]["name"] == names[i]);

    // The failed checkpoint: what failed first as the message, its checks
    // (failures first) as the output, as plain text: PrairieLearn escapes it.
    const json& triangle = test_named(j, "00_pipeline / triangle");
    CHECK(triangle["points"] == 4);
    CHECK(triangle["max_points"] == 6);
    CHECK(triangle["description"] == "Checks: probe (8, 8) colour; image vs reference");
    CHECK(triangle["message"] ==
          "probe (8, 8) colour: Expected (1, 0, 0) < observed & \"quoted\" red \xEF\xBF\xBD");
    const std::string output = triangle["output"];
    CHECK(output.find("FAIL  probe (8, 8) colour (0/2 points)") <
          output.find("PASS  image vs reference (4/4 points)"));
    CHECK(output.find('\x1b') == std::string::npos);
    CHECK(output.find('\x01') == std::string::npos);

    // The overall message is the lab table and the total; the output, why a
    // lab's child did not finish, with its log.
    const std::string message = j["message"];
    CHECK(message.rfind("lab ", 0) == 0);
    fw::test::check_mentions(message, {"00_pipeline", "7/10", "01_transforms", "0/7", kCrash,
                                       "Total: 7/17 points, 1 of 4 checkpoints passed."});
    CHECK(j["output"] ==
          "01_transforms: " + kCrash + "\nSegmentation fault <core dumped> & more\n");
    const json& rotate = test_named(j, "01_transforms / rotate");
    fw::test::check_mentions(rotate["message"], {"image vs reference", "the lab wrote no image"});
    fw::test::check_mentions(rotate["output"], {"lab 01_transforms: " + kCrash});
    CHECK(rotate["images"].empty());  // its frame was never written
}

TEST_CASE("prairielearn results.json: a hidden checkpoint shows its name and points only") {
    Fixture f;
    const std::string text = fw::test::read_text(f.dir + "/results.json");
    const json j = json::parse(text);
    for (const char* name : {"00_pipeline / secret", "00_pipeline / vault"}) {
        INFO(name);
        const json& t = test_named(j, name);
        CHECK(t["description"] == "Hidden checkpoint");
        CHECK(t["message"] ==
              "Hidden checkpoint: its checks, and why it failed, are not shown to students.");
        CHECK(t["output"] == "");
        CHECK(t["images"].empty());
    }
    CHECK(test_named(j, "00_pipeline / secret")["points"] == 3);
    CHECK(test_named(j, "00_pipeline / vault")["points"] == 0);
    CHECK(test_named(j, "00_pipeline / vault")["max_points"] == 1);
    // Nothing of their checks anywhere in the file.
    for (const char* secret : {"spin(", "32 inputs", "vault colour", "secret-value"})
        CHECK_MESSAGE(text.find(secret) == std::string::npos, "results.json shows " << secret);
}

TEST_CASE("prairielearn results.json: a failed checkpoint's pictures, small, as data URLs") {
    Fixture f;
    const std::vector<Picture> pictures = check_schema(read_json(f.dir + "/results.json"));
    // Only the visible failed checkpoint has pictures: its frame and the
    // reference; no difference, as its image check passed.
    REQUIRE(pictures.size() == 2);
    CHECK(pictures[0].label == "rendered");
    CHECK(pictures[1].label == "expected");
    for (size_t i = 0; i < 2; ++i)
        if (pictures[i].type == "png")
            CHECK(fw::decode_png(pictures[i].bytes, "picture").pixels ==
                  fw::read_png(f.dir + "/" + f.pngs[i]).pixels);

    // A failed image check adds the difference; pictures shrink to 160 pixels.
    const std::string dir = fw::test::out_dir() + "/thumbs";
    fs::remove_all(dir);
    fs::create_directories(dir + "/lab");
    fw::Image frame(512, 256, {0, 0, 0, 255}), diff(512, 256, {20, 20, 20, 255});
    diff.at(300, 100) = {255, 0, 0, 255};
    fw::write_png(dir + "/lab/cp.png", frame);
    fw::write_png(dir + "/lab/cp.expected.png", frame);
    fw::write_png(dir + "/lab/cp.diff.png", diff);
    GradeRun run;
    run.labs.resize(1);
    run.labs[0].lab = "lab";
    CheckResult image = check("lab", "cp", "image", "image vs reference", 0, 1, false,
                              "Observed: 1 of 131072 pixels differ");
    image.rendered = "lab/cp.png", image.expected = "lab/cp.expected.png";
    image.difference = "lab/cp.diff.png";
    run.labs[0].checks.push_back(image);
    grading::write_reports(run, dir, kPrairieLearn);
    const std::vector<Picture> three = check_schema(read_json(dir + "/results.json"));
    REQUIRE(three.size() == 3);
    CHECK(three[2].label == "difference");
    CHECK(three[2].type == "png");  // JPEG would blur its single pixels
    int w = 0, h = 0;
    CHECK(prairielearn_test::image_size(three[2].bytes, w, h));
    CHECK(w == 160);
    CHECK(h == 80);
}

TEST_CASE("prairielearn results.json: a large failing run with big pictures stays under 1 MB") {
    const std::string dir = fw::test::out_dir() + "/large";
    const GradeRun run = large_run(dir, 7, 20, "Observed: (0, 0, 0), largest difference 1");
    grading::write_reports(run, dir, kPrairieLearn);
    const std::string text = fw::test::read_text(dir + "/results.json");
    MESSAGE("results.json of 140 failed checkpoints: " << text.size() << " bytes");
    CHECK(text.size() <= grading::kResultsLimit);
    CHECK(text.size() < prairielearn_test::kMegabyte);
    const json j = json::parse(text);
    const std::vector<Picture> pictures = check_schema(j);
    CHECK(j["tests"].size() == 140);
    CHECK(j["score"] == 0.0);
    // The first checkpoints have their pictures; once the room is spent, the
    // later ones say why they have none.
    CHECK(j["tests"][0]["images"].size() == 3);
    CHECK(pictures.size() >= 3);
    CHECK(pictures.size() < 3 * 140);
    fw::test::check_mentions(j["tests"][139]["output"], {"No pictures here", "under 1 MB"});
}

TEST_CASE("prairielearn results.json: outputs that alone would pass 1 MB are cut") {
    const std::string dir = fw::test::out_dir() + "/huge";
    // 140 checkpoints of 16 KiB of output each, with multi-byte characters.
    std::string output = "Observed: ";
    while (output.size() < 16 * 1024) output += "caf\xC3\xA9 \xE2\x9C\x93 ";
    const GradeRun run = large_run(dir, 7, 20, output);
    grading::write_reports(run, dir, kPrairieLearn);
    const std::string text = fw::test::read_text(dir + "/results.json");
    MESSAGE("results.json of 140 checkpoints with 16 KiB outputs: " << text.size() << " bytes");
    CHECK(text.size() <= grading::kResultsLimit);
    const json j = json::parse(text);  // throws on a character cut in half
    check_schema(j);
    fw::test::check_mentions(j["tests"][0]["output"],
                             {"more bytes cut here: results.json must stay under 1 MB"});
}

TEST_CASE("course grade --results: results.json elsewhere, the other reports unchanged") {
    Fixture f;
    const std::string dir = fw::test::out_dir() + "/elsewhere",
                      path = dir + "/results/results.json";
    fs::remove_all(dir);
    grading::write_reports(f.run, dir + "/grade",
                           {grading::ResultsFormat::PrairieLearn, path});  // makes results/
    CHECK(read_json(path)["gradable"] == true);
    CHECK(!fs::exists(dir + "/grade/results.json"));
    for (const char* report : {"summary.txt", "junit.xml", "index.html"})
        CHECK_MESSAGE(fs::exists(dir + "/grade/" + report), report);
    // Gradescope's format stays the default.
    grading::write_reports(f.run, dir + "/gradescope");
    const json gradescope = read_json(dir + "/gradescope/results.json");
    CHECK(gradescope.at("extra_data").contains("max_score"));
    CHECK(!gradescope.contains("gradable"));
}

TEST_CASE("prairielearn results.json: a submission not graded counts neither points nor attempt") {
    const json j = json::parse(grading::prairielearn_not_gradable_json(
        "the submission does not build", "pipeline.cpp:3: error: \"x\" \x1b[31mred\x01 \xff"));
    INFO(j.dump(2));
    check_schema(j);
    CHECK(j["gradable"] == false);
    CHECK(j["format_errors"] == json::array({"the submission does not build"}));
    fw::test::check_mentions(j["message"], {"the submission does not build", "not graded"});
    CHECK(j["output"] == "pipeline.cpp:3: error: \"x\" red \xEF\xBF\xBD");
}

TEST_CASE("prairielearn results.json: an empty run") {
    const std::string dir = fw::test::out_dir() + "/empty";
    fs::remove_all(dir);
    grading::write_reports(GradeRun{}, dir, kPrairieLearn);
    const json j = read_json(dir + "/results.json");
    check_schema(j);
    CHECK(j["score"] == 0.0);
    CHECK(j["tests"].empty());
    fw::test::check_mentions(j["message"], {"no labs were graded", "Total: 0/0 points"});
}

namespace {

// The value column of the row for `field` in the contract's table of
// PrairieLearn's per-test fields (or the top-level one, `top`).
std::string contract_row(const std::string& field, bool top) {
    const std::string text = fw::test::read_text(fw::test::source_dir() + "/docs/contract.md");
    const size_t section = text.find("### PrairieLearn's results.json");
    REQUIRE(section != std::string::npos);
    const size_t each = text.find("Each test:", section);
    const size_t from = top ? section : each;
    const size_t row = text.find("| `" + field + "` |", from);
    REQUIRE(row != std::string::npos);
    if (top) REQUIRE(row < each);
    const size_t end = text.find('\n', row);
    return text.substr(row, end - row);
}

}  // namespace

TEST_CASE("prairielearn results.json: what the contract's tables say, the outputs do") {
    // `description`: "`Checks: ` and the titles of its checks".
    const std::string description = contract_row("description", false);
    REQUIRE(description.find("`Checks: ` and the titles of its checks") != std::string::npos);
    // `output`: only the labs whose child did not finish normally, empty
    // when there is none (the sandbox's layers go to the job's log).
    const std::string output = contract_row("output", true);
    REQUIRE(output.find("(empty when there is none)") != std::string::npos);

    const std::string dir = fw::test::out_dir() + "/contract";
    fs::remove_all(dir);
    GradeRun run;
    LabResult lab;
    lab.lab = "00_pipeline";
    // One check, then two: both descriptions begin as the contract says.
    lab.checks.push_back(check("00_pipeline", "one", "unit", "unit spin(v, <angle>)", 3, 3, true,
                               "32 inputs within 1e-5"));
    lab.checks.push_back(check("00_pipeline", "two", "probe", "probe (8, 8) colour", 1, 1, true,
                               "Observed: (1, 0, 0)"));
    lab.checks.push_back(check("00_pipeline", "two", "stat", "stat primitives_generated == 2", 1, 1,
                               true, "Observed: 2"));
    run.labs = {lab};
    run.sandbox = {{"seccomp filter", true, "system calls a lab needs", true},
                   {"namespaces", false, "not permitted here", true}};
    grading::write_reports(run, dir, kPrairieLearn);
    const json j = read_json(dir + "/results.json");
    REQUIRE(j["tests"].size() == 2);
    CHECK(j["tests"][0]["description"] == "Checks: unit spin(v, <angle>)");
    CHECK(j["tests"][1]["description"] ==
          "Checks: probe (8, 8) colour; stat primitives_generated == 2");
    CHECK(j["output"] == "");
}
