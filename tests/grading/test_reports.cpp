// The reports of `course grade` (docs/contract.md, Reports): summary.txt, results.json
// (Gradescope's format), junit.xml and the self-contained index.html, written
// for a run built by hand: a passing image check with real PNG files, a
// failing probe whose output holds markup and control characters, a hidden
// check, and a lab whose child crashed. Expected numbers come from the
// fixture's own constants.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "framework/image.hpp"
#include "grading/diagnosis/image_words.hpp"
#include "grading/judge/checks.hpp"
#include "grading/judge/image_matches.hpp"
#include "grading/report/by_checkpoint.hpp"
#include "grading/report/prairielearn_results.hpp"
#include "grading/report/report_text.hpp"
#include "grading/report/reports.hpp"
#include "grading/run/repository.hpp"
#include "tests/grading/report_fixture.hpp"
#include "tests/support/test_support.hpp"

namespace {

using grading::CheckResult;
using grading::GradeRun;
using grading::LabResult;
using report_fixture::base64_decode;
using report_fixture::check;
using report_fixture::crashed_transforms;
using report_fixture::kCrash;
using report_fixture::large_run;
using report_fixture::write_triangle_pngs;

// Output of the failing probe: markup, quotes, a terminal escape, a control
// character and a byte that is not UTF-8, as a child's output may be.
const std::string kProbeOutput =
    "Expected (1, 0, 0) < observed & \"quoted\" 'single' \x1b[31mred\x01 \xff\n"
    "tolerance 1/255";

std::string read_text(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    REQUIRE_MESSAGE(file, "cannot read " << path);
    return {std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
}

size_t count(const std::string& text, const std::string& needle) {
    size_t n = 0;
    for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1))
        ++n;
    return n;
}

// Lab 00: image 4/4 passed, probe 0/2 failed, hidden unit 3/3 passed.
// Lab 01 crashed: image 0/5 and stat 0/2 failed. Total 7/16, 2 of 5 passed.
struct Fixture {
    std::string dir = fw::test::out_dir();
    GradeRun run;
    std::vector<std::string> pngs;  // the three images of the passing check

    Fixture() {
        pngs = write_triangle_pngs(dir);
        LabResult pipeline;
        pipeline.lab = "00_pipeline";
        pipeline.seconds = 1.5;
        CheckResult image = check("00_pipeline", "triangle", "image", "image vs reference", 4, 4,
                                  true, "0 of 12 pixels differ by more than 8/255; limit 0.1%");
        image.rendered = pngs[0], image.expected = pngs[1], image.difference = pngs[2];
        pipeline.checks.push_back(image);
        pipeline.checks.push_back(check("00_pipeline", "triangle", "probe", "probe (8, 8) colour",
                                        0, 2, false, kProbeOutput));
        CheckResult hidden = check("00_pipeline", "secret", "unit", "unit rotate(v, <angle>)", 3, 3,
                                   true, "32 inputs within 1e-5");
        hidden.visibility = grading::Visibility::Hidden;
        pipeline.checks.push_back(hidden);

        LabResult transforms = crashed_transforms();
        run.labs = {pipeline, transforms};
        run.backend = "osmesa";
        run.seconds = 1.76;
        grading::write_reports(run, dir);
    }
};

}  // namespace

// The <img> data URIs of a Gradescope html output, decoded.
std::vector<std::string> inline_pngs(const std::string& html) {
    const std::string uri = "<img src=\"data:image/png;base64,";
    std::vector<std::string> out;
    for (size_t at = html.find(uri); at != std::string::npos; at = html.find(uri, at + 1)) {
        const size_t begin = at + uri.size();
        out.push_back(base64_decode(html.substr(begin, html.find('"', begin) - begin)));
    }
    return out;
}

TEST_CASE("results.json follows Gradescope's format: one test per checkpoint") {
    Fixture f;
    const auto j = nlohmann::json::parse(read_text(f.dir + "/results.json"));
    INFO(j.dump(2));
    CHECK(j.at("score").get<double>() == doctest::Approx(7.0));
    // Gradescope's specification has no top-level max_score.
    CHECK(!j.contains("max_score"));
    CHECK(j.at("extra_data").at("max_score").get<double>() == doctest::Approx(16.0));
    CHECK(j.at("execution_time").get<double>() == doctest::Approx(1.76));
    CHECK(j.at("output").is_string());
    CHECK(j.at("output_format") == "html");

    const auto& tests = j.at("tests");
    REQUIRE(tests.size() == 3);
    double score = 0, max_score = 0;
    const std::set<std::string> visibilities{"visible", "hidden", "after_due_date",
                                             "after_published"};
    for (const auto& t : tests) {
        CHECK(t.at("name").is_string());
        CHECK(t.at("number").is_string());
        CHECK(t.at("output").is_string());
        CHECK(t.at("output_format") == "html");
        CHECK(visibilities.count(t.at("visibility").get<std::string>()) == 1);
        const std::string status = t.at("status").get<std::string>();
        CHECK((status == "passed" || status == "failed"));
        CHECK(t.at("score").get<double>() <= t.at("max_score").get<double>());
        CHECK(t.at("extra_data").at("checks").is_array());
        score += t.at("score").get<double>();
        max_score += t.at("max_score").get<double>();
    }
    CHECK(score == doctest::Approx(7.0));
    CHECK(max_score == doctest::Approx(16.0));

    // The checkpoint holds its checks, the failed probe before the passed image.
    const auto& triangle = tests[0];
    CHECK(triangle.at("name") == "00_pipeline / triangle");
    CHECK(triangle.at("number") == "0.1");
    CHECK(triangle.at("status") == "failed");
    CHECK(triangle.at("score") == 4);
    CHECK(triangle.at("max_score") == 6);
    CHECK(triangle.at("visibility") == "visible");
    CHECK(triangle.at("extra_data").at("checks").size() == 2);
    CHECK(triangle.at("extra_data").at("checks")[0].at("title") == "probe (8, 8) colour");
    const std::string html = triangle.at("output");
    CHECK(html.find("probe (8, 8) colour") < html.find("image vs reference"));
    // The child's text is escaped: its markup cannot reach the page.
    CHECK(html.find("< observed") == std::string::npos);
    CHECK(html.find("&lt; observed &amp; &quot;quoted&quot; &#39;single&#39; red \xEF\xBF\xBD\n") !=
          std::string::npos);
    // A failed checkpoint shows its frame and the reference, small; the
    // difference only when its image check failed (here it passed).
    const std::vector<std::string> pictures = inline_pngs(html);
    REQUIRE(pictures.size() == 2);
    for (const std::string& png : pictures) {
        int w = 0, h = 0;
        CHECK(fw::png_header_size(png, w, h));
        CHECK(w == 4);  // already smaller than the thumbnail size: kept as it is
        CHECK(h == 3);
    }
    CHECK(fw::decode_png(pictures[0], "rendered").pixels ==
          fw::read_png(f.dir + "/" + f.pngs[0]).pixels);
    CHECK(fw::decode_png(pictures[1], "expected").pixels ==
          fw::read_png(f.dir + "/" + f.pngs[1]).pixels);

    CHECK(tests[1].at("name") == "00_pipeline / secret");
    // A hidden checkpoint is shown after the due date by default: Gradescope's
    // "hidden" would hide the student's total score too.
    CHECK(tests[1].at("visibility") == "after_due_date");
    CHECK(tests[1].at("status") == "passed");
    CHECK(inline_pngs(tests[1].at("output")).empty());
    CHECK(tests[2].at("name") == "01_transforms / rotate");
    CHECK(tests[2].at("number") == "1.1");
    CHECK(tests[2].at("status") == "failed");
    CHECK(tests[2].at("output").get<std::string>().find(kCrash) != std::string::npos);
    // The overall output: the table of labs, with the crash and its log.
    const std::string overall = j.at("output");
    CHECK(overall.find("<table>") != std::string::npos);
    CHECK(overall.find("<td>00_pipeline</td><td>7 / 9</td><td>2 / 3</td><td>ok</td>") !=
          std::string::npos);
    CHECK(overall.find(kCrash) != std::string::npos);
    CHECK(overall.find("Segmentation fault &lt;core dumped&gt;") != std::string::npos);
    CHECK(j.at("extra_data").at("labs").size() == 2);
}

TEST_CASE("results.json: a hidden checkpoint's test has the visibility --hidden-as chose") {
    Fixture f;
    for (const grading::HiddenAs as :
         {grading::HiddenAs::AfterDueDate, grading::HiddenAs::AfterPublished,
          grading::HiddenAs::Hidden}) {
        const std::string dir = f.dir + "/hidden-as-" + grading::name_of(as);
        grading::write_reports(f.run, dir, {grading::ResultsFormat::Gradescope, "", as});
        const auto j = nlohmann::json::parse(read_text(dir + "/results.json"));
        std::map<std::string, std::string> visibility;
        for (const auto& t : j.at("tests")) visibility[t.at("name")] = t.at("visibility");
        CHECK(visibility["00_pipeline / triangle"] == "visible");
        CHECK(visibility["00_pipeline / secret"] == grading::name_of(as));
        CHECK(visibility["01_transforms / rotate"] == "visible");
    }
    CHECK(std::string(grading::name_of(grading::HiddenAs::AfterDueDate)) == "after_due_date");
    CHECK(std::string(grading::name_of(grading::HiddenAs::AfterPublished)) == "after_published");
    CHECK(std::string(grading::name_of(grading::HiddenAs::Hidden)) == "hidden");
}

TEST_CASE("results.json's pictures: shrunk to 160 pixels, the difference kept bright") {
    const std::string dir = fw::test::out_dir() + "/thumbs";
    std::filesystem::remove_all(dir);
    std::filesystem::create_directories(dir + "/lab");
    fw::Image frame(512, 256, {0, 0, 0, 255}), diff(512, 256, {20, 20, 20, 255});
    diff.at(300, 100) = {255, 0, 0, 255};  // one failed pixel
    fw::write_png(dir + "/lab/cp.png", frame);
    fw::write_png(dir + "/lab/cp.expected.png", frame);
    fw::write_png(dir + "/lab/cp.diff.png", diff);
    GradeRun run;
    run.labs.resize(1);
    run.labs[0].lab = "lab";
    CheckResult image = check("lab", "cp", "image", "image vs reference", 0, 1, false, "differs");
    image.rendered = "lab/cp.png", image.expected = "lab/cp.expected.png";
    image.difference = "lab/cp.diff.png";
    run.labs[0].checks.push_back(image);
    grading::write_reports(run, dir);
    const auto j = nlohmann::json::parse(read_text(dir + "/results.json"));
    const std::vector<std::string> pictures = inline_pngs(j["tests"][0]["output"]);
    REQUIRE(pictures.size() == 3);
    const fw::Image small = fw::decode_png(pictures[2], "difference");
    CHECK(small.width == 160);
    CHECK(small.height == 80);
    // The one red pixel survives the shrinking as a red one (300 * 160 / 512 =
    // 93.75), each channel the largest of its block: red over the dark grey.
    CHECK(small.at(93, 31) == fw::Rgba8{255, 20, 20, 255});
    CHECK(small.at(10, 10) == fw::Rgba8{20, 20, 20, 255});
    CHECK(fw::decode_png(pictures[0], "rendered").width == 160);
}

TEST_CASE("results.json's pictures fill the room under 1 MB, checkpoint by checkpoint") {
    // Failed runs of every size: a checkpoint's pictures (about 180 KB of
    // noise) go in whole or not at all, in order, and the pictures that fit
    // are there, however the text and the pictures fall against the limit.
    const std::string dir = fw::test::out_dir() + "/large";
    for (int checkpoints : {3, 10, 20, 40}) {
        const GradeRun run = large_run(dir, 7, checkpoints, "Observed: (0, 0, 0)");
        const size_t failed = run.labs.size() * static_cast<size_t>(checkpoints);
        grading::write_reports(run, dir);
        const std::string text = read_text(dir + "/results.json");
        const auto j = nlohmann::json::parse(text);
        INFO(failed << " failed checkpoints: results.json is " << text.size() << " bytes");
        CHECK(text.size() <= grading::kResultsLimit);
        REQUIRE(j["tests"].size() == failed);
        size_t pictured = 0, room = 0;
        for (const auto& t : j["tests"]) {
            const std::string output = t["output"];
            const size_t n = count(output, "<img src=\"data:image/");
            if (n == 0) break;
            CHECK(n == 3);
            room = std::max(room, output.size());
            ++pictured;
        }
        MESSAGE(failed << " failed checkpoints: " << pictured << " with pictures, " << text.size()
                       << " bytes");
        CHECK(pictured >= 1);
        // Every later checkpoint says why it has none, and one more
        // checkpoint's pictures would not have fitted twice over.
        for (size_t i = pictured; i < j["tests"].size(); ++i)
            CHECK(count(j["tests"][i]["output"], "No pictures here") == 1);
        if (pictured < j["tests"].size()) CHECK(text.size() + 2 * room > grading::kResultsLimit);
    }
}

TEST_CASE("a failed image check's words never say the same colour was expected and found") {
    // Two greens trade places, as when a mistake shifts thin lines: the left
    // half should be the light one and the right half the dark one, and the
    // frame has them the other way round. Each side's most common colour
    // alone is the same green (as many pixels of each); the pairs at the same
    // pixels are not.
    const fw::Rgba8 light{40, 200, 60, 255}, dark{20, 150, 40, 255};
    fw::Image expected(8, 4, light), actual(8, 4, dark);
    for (int y = 0; y < 4; ++y)
        for (int x = 4; x < 8; ++x) expected.at(x, y) = dark, actual.at(x, y) = light;
    fw::CompareOptions exact;
    exact.radius = 0;
    const fw::CompareResult c = fw::compare_images(actual, expected, exact);
    REQUIRE(c.failed_pixels == 32);
    const std::string words = grading::describe_difference(actual, expected, c);
    INFO(words);
    CHECK(grading::colour_name(light) == grading::colour_name(dark));  // one group
    const std::string light_words = grading::colour_words(light),
                      dark_words = grading::colour_words(dark);
    CHECK(light_words != dark_words);
    const bool light_first = words.find("expected " + light_words + ", found " + dark_words) !=
                             std::string::npos,
               dark_first = words.find("expected " + dark_words + ", found " + light_words) !=
                            std::string::npos;
    CHECK((light_first || dark_first));
    for (const std::string& w : {light_words, dark_words})
        CHECK(words.find("expected " + w + ", found " + w) == std::string::npos);
}

TEST_CASE(
    "a colour a lab's sheet names, as in \"light blue (0.5, 0.5, 1)\", has that name in reports") {
    // Every "NAME (r, g, b)" of every lab's sheet, r, g and b in [0, 1], whose
    // last word is a colour the reports use: the reports' name holds it.
    const std::set<std::string> words = {"red",     "green",  "blue",  "yellow", "cyan",
                                         "magenta", "orange", "white", "black",  "grey",
                                         "purple",  "pink",   "brown"};
    const std::regex named(R"(([a-z]+) \((\d*\.?\d+), (\d*\.?\d+), (\d*\.?\d+)\))");
    int checked = 0;
    namespace fs = std::filesystem;
    for (const auto& entry : fs::directory_iterator(fs::path(grading::source_root()) / "labs")) {
        const fs::path sheet = entry.path() / "README.md";
        if (!fs::is_regular_file(sheet)) continue;
        std::ifstream in(sheet);
        const std::string text((std::istreambuf_iterator<char>(in)), {});
        for (std::sregex_iterator m(text.begin(), text.end(), named), end; m != end; ++m) {
            const std::string word = (*m)[1];
            const double r = std::stod((*m)[2]), g = std::stod((*m)[3]), b = std::stod((*m)[4]);
            if (!words.count(word) || std::max({r, g, b}) > 1.0) continue;
            auto byte = [](double v) { return static_cast<std::uint8_t>(v * 255.0 + 0.5); };
            const std::string name = grading::colour_name({byte(r), byte(g), byte(b), 255});
            INFO(sheet.string() << ": " << m->str() << " is named " << name);
            CHECK((" " + name + " ").find(" " + word + " ") != std::string::npos);
            ++checked;
        }
    }
    CHECK(checked > 20);
    CHECK(grading::colour_name({128, 128, 255, 255}) == "light blue");
    CHECK(grading::colour_name({128, 153, 179, 255}) == "greyish blue");
}

TEST_CASE("a failed frame that is another checkpoint's expected image is named so") {
    std::vector<grading::LabData> labs =
        grading::select_labs(grading::discover_labs(fw::test::source_dir()), {"transforms"});
    REQUIRE(labs.size() == 1);
    grading::LabData& lab = labs[0];
    grading::parse_checks(lab);
    auto checkpoint = [&](const std::string& name) -> const fw::Checkpoint& {
        for (const fw::Checkpoint& cp : lab.file.checkpoints)
            if (cp.name == name) return cp;
        FAIL("no checkpoint " << name);
        throw;
    };
    grading::ReferenceImages references(lab);
    const fw::Image* srt = references.get("srt");
    REQUIRE(srt != nullptr);
    // trs drawn as srt: the one parameter in which they differ is named.
    const std::string sentence = grading::matching_checkpoint_sentence(
        lab, checkpoint("trs"), *srt, fw::CompareOptions{}, references);
    CHECK(sentence ==
          "Your frame is the one checkpoint srt expects (order \"srt\", here \"trs\"): your "
          "code most likely treats order \"trs\" as \"srt\".");
    // translate drawn as the identity (its model matrix ignores tx and ty):
    // every parameter that differs is named.
    const fw::Image* identity = references.get("identity");
    REQUIRE(identity != nullptr);
    CHECK(grading::matching_checkpoint_sentence(lab, checkpoint("translate"), *identity,
                                                fw::CompareOptions{}, references) ==
          "Your frame is the one checkpoint identity expects, which differs from translate in tx "
          "(the default there, 1 here), ty (the default there, -0.5 here): your code most likely "
          "ignores these parameters or mixes them up.");
    // A frame that is no checkpoint's (all black), or of another size: nothing.
    const fw::Image black(srt->width, srt->height, fw::Rgba8{0, 0, 0, 255});
    CHECK(grading::matching_checkpoint_sentence(lab, checkpoint("trs"), black, fw::CompareOptions{},
                                                references)
              .empty());
    const fw::Image small(8, 8, fw::Rgba8{0, 0, 0, 255});
    CHECK(grading::matching_checkpoint_sentence(lab, checkpoint("trs"), small, fw::CompareOptions{},
                                                references)
              .empty());
    // Its own expected image is not "another" checkpoint's.
    CHECK(grading::matching_checkpoint_sentence(lab, checkpoint("srt"), *srt, fw::CompareOptions{},
                                                references)
              .find("checkpoint srt") == std::string::npos);
}

TEST_CASE("a failed frame that a known mistake draws is named by the mistake's id") {
    namespace fs = std::filesystem;
    // A copy of lab 1's data with one known mistake's frame for trs: black.
    const fs::path root = fs::path(fw::test::out_dir()) / "known-mistakes";
    const fs::path lab_dir = root / "labs" / "01_transforms";
    fs::remove_all(root);
    fs::create_directories(lab_dir);
    const fs::path source = fs::path(fw::test::source_dir()) / "labs" / "01_transforms";
    fs::copy_file(source / "checkpoints.json", lab_dir / "checkpoints.json");
    fs::copy(source / "reference", lab_dir / "reference", fs::copy_options::recursive);
    fs::remove_all(lab_dir / "reference" / "mistakes");
    const fs::path folder = lab_dir / "reference" / "mistakes";
    const fw::Image srt = fw::read_png((lab_dir / "reference" / "srt.png").string());
    const fw::Image black(srt.width, srt.height, fw::Rgba8{0, 0, 0, 255});
    fs::create_directories(folder);
    fw::write_png((folder / "trs.1.png").string(), black);
    const grading::KnownMistake late{"transforms-late", "multiplies on the wrong side", "", {}, {}},
        blank{"transforms-blank", "draws nothing", "", {}, {}};
    fw::test::write_text((folder / "trs.json").string(),
                         grading::mistake_frames_text({{"trs.1.png", {late}}}));
    auto load = [&] {
        std::vector<grading::LabData> labs = grading::discover_labs(root.string());
        REQUIRE(labs.size() == 1);
        grading::parse_checks(labs[0]);
        return labs[0];
    };
    grading::LabData lab = load();
    REQUIRE(lab.mistake_frames.count("trs") == 1);
    const fw::Checkpoint* trs = nullptr;
    for (const fw::Checkpoint& cp : lab.file.checkpoints)
        if (cp.name == "trs") trs = &cp;
    REQUIRE(trs != nullptr);
    grading::ReferenceImages references(lab);
    CHECK(grading::known_mistake_frame_sentence(lab, *trs, black, {}, references) ==
          "Your frame is the one a known mistake draws (transforms-late): the frame of code that "
          "multiplies on the wrong side. Another mistake can draw the same frame: check whether "
          "your code does this.");
    // Another frame, or another checkpoint: nothing.
    CHECK(grading::known_mistake_frame_sentence(lab, *trs, srt, {}, references).empty());
    // A frame that passes the comparison with the mistake's one way only
    // (black, where the mistake's frame has two thin white lines: each black
    // pixel finds a black one beside the lines) is not that mistake's.
    {
        fw::Image lines = black;
        for (int x = 0; x < lines.width; ++x)
            for (int y : {lines.height / 3, 2 * lines.height / 3})
                lines.at(x, y) = fw::Rgba8{255, 255, 255, 255};
        fw::write_png((folder / "trs.1.png").string(), lines);
        grading::LabData thin = load();
        grading::ReferenceImages thin_refs(thin);
        const fw::Checkpoint& thin_trs =
            thin.file.checkpoints.at(static_cast<size_t>(trs - lab.file.checkpoints.data()));
        CHECK(grading::known_mistake_frame_sentence(thin, thin_trs, black, {}, thin_refs).empty());
        CHECK_FALSE(
            grading::known_mistake_frame_sentence(thin, thin_trs, lines, {}, thin_refs).empty());
        fw::write_png((folder / "trs.1.png").string(), black);
    }
    CHECK(grading::known_mistake_frame_sentence(lab, lab.file.checkpoints.front(), black, {},
                                                references)
              .empty());
    // Two mistakes that draw the same frame are both named.
    CHECK(grading::known_mistake_sentence({"trs.1.png", {late, blank}}) ==
          "Your frame is the one known mistakes draw (transforms-late, transforms-blank): the "
          "frame of code that multiplies on the wrong side, or of code that draws nothing. "
          "Another mistake can draw the same frame: check whether your code does this.");

    // A frame that is a known mistake's and another checkpoint's expected
    // image: the known mistake first, then the checkpoint, a line each.
    fw::write_png((folder / "trs.2.png").string(), srt);
    fw::test::write_text(
        (folder / "trs.json").string(),
        grading::mistake_frames_text({{"trs.1.png", {late}}, {"trs.2.png", {blank}}}));
    const grading::LabData both = load();
    const fw::Checkpoint& trs2 =
        both.file.checkpoints.at(static_cast<size_t>(trs - lab.file.checkpoints.data()));
    grading::ReferenceImages again(both);
    const std::string checkpoint_words =
        grading::matching_checkpoint_sentence(both, trs2, srt, {}, again);
    CHECK(checkpoint_words.find("checkpoint srt expects") != std::string::npos);
    CHECK(grading::failed_frame_diagnosis(both, trs2, srt, {}, again) ==
          "Your frame is the one a known mistake draws (transforms-blank): the frame of code "
          "that draws nothing. Another mistake can draw the same frame: check whether your "
          "code does this.\n" +
              checkpoint_words);
    CHECK(grading::failed_frame_diagnosis(both, trs2, black, {}, again) ==
          grading::known_mistake_frame_sentence(both, trs2, black, {}, again));
    fs::remove(folder / "trs.2.png");

    // The files are validated with the checkpoints, each error naming the file.
    fw::test::write_text((folder / "trs.json").string(),
                         grading::mistake_frames_text({{"trs.2.png", {late}}}));
    fw::test::check_mentions(fw::test::thrown([&] { load(); }),
                             {"reference/mistakes/trs.json", "no image trs.2.png"});
    fw::test::write_text((folder / "trs.json").string(), "{\"frames\": [");
    fw::test::check_mentions(fw::test::thrown([&] { load(); }), {"trs.json", "not valid JSON"});
    fs::remove(folder / "trs.json");
    fw::test::write_text((folder / "renamed.json").string(),
                         grading::mistake_frames_text({{"trs.1.png", {late}}}));
    fw::test::check_mentions(fw::test::thrown([&] { load(); }),
                             {"renamed.json", "no checkpoint renamed"});
}

TEST_CASE("junit.xml has a test case per checkpoint and escapes what the checks printed") {
    Fixture f;
    const std::string xml = read_text(f.dir + "/junit.xml");
    INFO(xml);
    CHECK(xml.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites ", 0) == 0);
    CHECK(count(xml, "<testsuite ") == 2);
    CHECK(count(xml, "<testcase ") == 3);
    CHECK(count(xml, "<failure ") == 2);
    CHECK(xml.find("tests=\"3\" failures=\"2\"") != std::string::npos);
    CHECK(xml.find("name=\"00_pipeline\" tests=\"2\" failures=\"1\"") != std::string::npos);
    CHECK(xml.find("name=\"01_transforms\" tests=\"1\" failures=\"1\"") != std::string::npos);
    CHECK(xml.find("classname=\"00_pipeline\" name=\"triangle\"") != std::string::npos);

    // The output's markup arrives as text, in the message attribute and the body.
    CHECK(xml.find("< observed") == std::string::npos);
    CHECK(xml.find("<core") == std::string::npos);
    CHECK(xml.find("message=\"probe (8, 8) colour: Expected (1, 0, 0) &lt; observed &amp; "
                   "&quot;quoted&quot; &#39;single&#39;") != std::string::npos);
    CHECK(xml.find("unit rotate(v, &lt;angle&gt;)") != std::string::npos);
    // Within a checkpoint the failed check comes first.
    const std::string triangle = xml.substr(xml.find("name=\"triangle\""));
    CHECK(triangle.find("FAIL  probe (8, 8) colour") < triangle.find("PASS  image vs reference"));
    // Characters XML 1.0 forbids are gone, and the file is UTF-8.
    CHECK(xml.find('\x01') == std::string::npos);
    CHECK(xml.find('\x1b') == std::string::npos);
    CHECK(xml.find('\xff') == std::string::npos);
    // Every '<' left opens a tag, a declaration or a closing tag.
    for (size_t at = xml.find('<'); at != std::string::npos; at = xml.find('<', at + 1))
        CHECK_MESSAGE(
            std::string("?/abcdefghijklmnopqrstuvwxyz").find(xml[at + 1]) != std::string::npos,
            "stray '<' at byte " << at);
    // The crashed lab's checks fail with the reason, and its log is kept.
    CHECK(count(xml, kCrash) >= 3);
    CHECK(xml.find("Segmentation fault &lt;core dumped&gt; &amp; more") != std::string::npos);
}

TEST_CASE("index.html is self-contained: a card per checkpoint, images first, then its checks") {
    Fixture f;
    const std::string html = read_text(f.dir + "/index.html");
    const std::string uri = "data:image/png;base64,";
    CHECK(count(html, uri) == 3);
    for (const char* external :
         {"src=\"http", "href=\"http", "src=\"//", "href=\"//", "<link", "<script", "@import"})
        CHECK_MESSAGE(html.find(external) == std::string::npos, "external reference " << external);
    // Images are CSS backgrounds, each embedded once: url() only ever holds data.
    for (size_t at = html.find("url("); at != std::string::npos; at = html.find("url(", at + 1))
        CHECK_MESSAGE(html.compare(at, 4 + uri.size(), "url(" + uri) == 0,
                      "a url() that is not embedded data: " << html.substr(at, 40));
    for (size_t at = html.find("href=\""); at != std::string::npos;
         at = html.find("href=\"", at + 1))
        CHECK_MESSAGE(html[at + 6] == '#', "a link out of the page: " << html.substr(at, 40));

    for (const char* title : {"image vs reference", "probe (8, 8) colour",
                              "unit rotate(v, &lt;angle&gt;)", "primitives_generated == 2"})
        CHECK_MESSAGE(html.find(title) != std::string::npos, "missing check " << title);
    CHECK(count(html, "<article class=\"check ") == 3);
    CHECK(html.find("< observed") == std::string::npos);
    CHECK(html.find("&lt; observed &amp; &quot;quoted&quot;") != std::string::npos);
    CHECK(html.find("image not available: 01_transforms/rotate.png") != std::string::npos);
    CHECK(html.find(kCrash) != std::string::npos);
    CHECK(html.find("Segmentation fault &lt;core dumped&gt;") != std::string::npos);
    // The failed list at the top gives each failed checkpoint's cause.
    CHECK(html.find("00_pipeline / triangle</a>: probe (8, 8) colour: Expected (1, 0, 0) &lt; "
                    "observed") != std::string::npos);
    CHECK(html.find("01_transforms / rotate</a>: image vs reference: the lab wrote no image") !=
          std::string::npos);

    // Each embedded image decodes to the bytes of one of the check's PNG files.
    std::set<std::string> files;
    for (const std::string& png : f.pngs) files.insert(read_text(f.dir + "/" + png));
    std::set<std::string> decoded;
    for (size_t at = html.find(uri); at != std::string::npos; at = html.find(uri, at + 1)) {
        const size_t begin = at + uri.size();
        decoded.insert(base64_decode(html.substr(begin, html.find_first_of("\")", begin) - begin)));
    }
    CHECK(decoded == files);

    // Within a lab, failed checkpoints come first; in a card, the images come
    // before the checks, and the failed check before the passed one.
    const std::string lab0 = html.substr(html.find("id=\"lab-0\""));
    const std::string card = lab0.substr(lab0.find("<article"));
    CHECK(card.find("triangle") < card.find("secret"));
    CHECK(card.find("<figure>") < card.find("<table class=\"checks\">"));
    CHECK(card.find("probe (8, 8) colour") < card.find("image vs reference"));

    // The hidden points are counted, in the total and in their lab's header;
    // the page has one <main>, and no table header without text.
    CHECK(html.find("3 of the 16 points are hidden (1 hidden checkpoint, 3 points scored "
                    "there)") != std::string::npos);
    CHECK(html.find("7 / 9 points (3 hidden)") != std::string::npos);
    CHECK(count(html, "<main>") == 1);
    CHECK(count(html, "</main>") == 1);
    CHECK(count(html, "<th></th>") == 0);
}

TEST_CASE("summary.txt has an aligned row per lab, the failed checks and the total") {
    Fixture f;
    const std::string text = read_text(f.dir + "/summary.txt");
    INFO(text);
    CHECK(text == grading::summary_table(f.run));
    CHECK(std::all_of(text.begin(), text.end(),
                      [](char c) { return c == '\n' || (c >= 0x20 && c < 0x7F); }));
    std::istringstream in(text);
    std::string header, row0, row1;
    std::getline(in, header), std::getline(in, row0), std::getline(in, row1);
    CHECK(header.rfind("lab", 0) == 0);
    CHECK(row0.rfind("00_pipeline", 0) == 0);
    CHECK(row1.rfind("01_transforms", 0) == 0);
    for (const char* cell : {" 7/9", " 2/3", " ok", " 1.5"})
        CHECK(row0.find(cell) != std::string::npos);
    for (const char* cell : {" 0/7", " 0/2", " crashed (signal 11, SIGSEGV)", " 0.4"})
        CHECK(row1.find(cell) != std::string::npos);
    // Columns line up: status starts at one offset, and the seconds end the rows.
    CHECK(header.find("status") == row0.find("ok"));
    CHECK(header.find("status") == row1.find("crashed"));
    CHECK(header.size() == row0.size());
    CHECK(header.size() == row1.size());

    CHECK(text.find("00_pipeline/triangle: probe (8, 8) colour (0/2 points) - Expected (1, 0, 0) "
                    "< observed") != std::string::npos);
    CHECK(text.find("01_transforms/rotate: primitives_generated == 2 (0/2 points) - lab "
                    "01_transforms: " +
                    kCrash) != std::string::npos);
    CHECK(text.find("image vs reference (0/5 points) - the lab wrote no image") !=
          std::string::npos);
    CHECK(text.find("Total: 7/16 points, 2 of 5 checks passed, 2 labs, 1.8 s") !=
          std::string::npos);
}

TEST_CASE("an empty run still writes all four reports") {
    const std::string dir = fw::test::out_dir() + "/fresh/grade";
    std::filesystem::remove_all(fw::test::out_dir() + "/fresh");
    grading::write_reports(GradeRun{}, dir);
    const auto j = nlohmann::json::parse(read_text(dir + "/results.json"));
    CHECK(j.at("score") == 0);
    CHECK(j.at("extra_data").at("max_score") == 0);
    CHECK(j.at("tests").empty());
    CHECK(count(read_text(dir + "/junit.xml"), "<testcase") == 0);
    CHECK(read_text(dir + "/index.html").find("No labs were graded") != std::string::npos);
    CHECK(read_text(dir + "/summary.txt").find("Total: 0/0 points, 0 of 0 checks passed, 0 labs") !=
          std::string::npos);
}

TEST_CASE("a report that cannot be written is an error naming it") {
    const std::string dir = fw::test::out_dir();
    std::filesystem::create_directories(dir + "/summary.txt");  // a directory in the file's place
    fw::test::check_mentions(fw::test::thrown([&] { grading::write_reports(GradeRun{}, dir); }),
                             {dir + "/summary.txt", "cannot write"});

    const std::string file = dir + "/not-a-directory";
    std::ofstream(file) << "x";
    fw::test::check_mentions(fw::test::thrown([&] { grading::write_reports(GradeRun{}, file); }),
                             {file, "--out"});
}

TEST_CASE("a visibility is visible or hidden; any other name is an error") {
    CHECK(grading::visibility_named("visible") == grading::Visibility::Visible);
    CHECK(grading::visibility_named("hidden") == grading::Visibility::Hidden);
    fw::test::check_mentions(fw::test::thrown([] { grading::visibility_named("secret"); }),
                             {"\"secret\"", "visible or hidden"});
}

TEST_CASE("text from a child is cleaned for XML, HTML and JSON") {
    using grading::report::clean_text;
    using grading::report::escape_markup;
    CHECK(escape_markup("a<b>&\"c'\x01\x7f\td") == "a&lt;b&gt;&amp;&quot;c&#39;\td");
    CHECK(clean_text("\x1b[1;31merror:\x1b[m x\x1b") == "error: x");
    CHECK(clean_text("caf\xC3\xA9 \xE2\x9C\x93 \xF0\x9F\x99\x82") ==
          "caf\xC3\xA9 \xE2\x9C\x93 \xF0\x9F\x99\x82");
    const std::string replacement = "\xEF\xBF\xBD";
    CHECK(clean_text("a\xff") == "a" + replacement);
    CHECK(clean_text("\xC0\xAF") == replacement + replacement);                    // overlong '/'
    CHECK(clean_text("\xED\xA0\x80") == replacement + replacement + replacement);  // surrogate
    CHECK(clean_text("\xE2\x9C") == replacement + replacement);                    // cut short
    CHECK(clean_text("\xEF\xBF\xBE") == "");                                       // U+FFFE
    CHECK(grading::report::points(2.5) == "2.5");
    CHECK(grading::report::points(10.0) == "10");
    CHECK(grading::report::points(1.0 / 3.0) == "0.33");
    CHECK(grading::report::first_line("\n  \n  first  \nsecond") == "first");
}

TEST_CASE("base64 gives RFC 4648's test vectors, padding included") {
    const std::pair<const char*, const char*> vectors[] = {{"", ""},
                                                           {"f", "Zg=="},
                                                           {"fo", "Zm8="},
                                                           {"foo", "Zm9v"},
                                                           {"foob", "Zm9vYg=="},
                                                           {"fooba", "Zm9vYmE="},
                                                           {"foobar", "Zm9vYmFy"}};
    for (const auto& [text, encoded] : vectors) CHECK(grading::base64(text) == encoded);
    std::string all;
    for (int i = 0; i < 256; ++i) all += static_cast<char>(i);
    CHECK(base64_decode(grading::base64(all)) == all);
}

TEST_CASE(
    "the summary of a failed unit check: partial points, its likely mistake and first case, what "
    "the score means; the CPU and sandbox lines only where asked") {
    const std::string dir = fw::test::out_dir() + "/partial";
    std::filesystem::remove_all(dir);
    LabResult lab;
    lab.lab = "01_transforms";
    CheckResult unit = check("01_transforms", "trs", "unit", "unit compose (1009 cases)", 3.9, 4,
                             false, "Expected: every case\nObserved: 1008 of 1009 cases passed");
    unit.diagnosis =
        "Likely mistake (transpose): your matrix is the transpose of the expected one.";
    unit.first_case = "  compose(1, 2) [edge case]\n    expected: 1\n    observed: 2\n";
    lab.checks.push_back(unit);
    lab.checks.push_back(
        check("01_transforms", "trs", "probe", "probe (1, 1) colour", 2, 2, true, "ok"));
    lab.checks.push_back(check("01_transforms", "secret", "probe", "probe (2, 2) colour", 0, 3,
                               false, "Observed: (0, 0, 0)", "hidden"));
    GradeRun run;
    run.labs = {lab};
    run.sandbox = {{"seccomp filter", true, "in every lab child", true}};
    grading::write_reports(run, dir);

    const std::string terminal = grading::summary_table(run, false);
    INFO(terminal);
    CHECK(terminal.find("01_transforms/trs: unit compose (1009 cases) (3.9/4 points) - Observed: "
                        "1008 of 1009 cases passed\n"
                        "    Likely mistake (transpose): your matrix is the transpose of the "
                        "expected one.\n"
                        "    compose(1, 2) [edge case]\n"
                        "      expected: 1\n") != std::string::npos);
    CHECK(terminal.find("Total: 5.9/9 points, 1 of 3 checks passed") != std::string::npos);
    CHECK(terminal.find("3 of these points are in hidden checkpoints") != std::string::npos);
    CHECK(terminal.find("starting copy scores low until its TODO parts are written") !=
          std::string::npos);
    CHECK(terminal.find("Sandbox:") == std::string::npos);
    CHECK(grading::summary_table(run).find("\nSandbox: on: seccomp filter") != std::string::npos);
    CHECK(read_text(dir + "/summary.txt") == grading::summary_table(run));
    // Not measured (as here): no CPU line; measured: one, before the sandbox's.
    CHECK(grading::summary_table(run).find("CPU:") == std::string::npos);
    run.course_cpu_seconds = 0.5;
    run.children_cpu_seconds = 1.254;
    const std::string cpu =
        "\nCPU: 0.50 s in course (judging, the report's images), 1.25 s in the labs' children "
        "(rendering)\nSandbox: ";
    CHECK(grading::summary_table(run).find(cpu) != std::string::npos);
    CHECK(grading::summary_table(run, false).find("CPU:") == std::string::npos);
    run.course_cpu_seconds = -1.0;
    // The terminal's cap: the first failed check shown, the other counted.
    const std::string capped = grading::summary_table(run, false, 1);
    CHECK(capped.find("Likely mistake (transpose)") != std::string::npos);
    CHECK(capped.find("01_transforms/secret") == std::string::npos);
    CHECK(capped.find("  ... and 1 more failed check: the report and summary.txt list them all") !=
          std::string::npos);
    CHECK(terminal.find("more failed check") == std::string::npos);

    // Fractional scores reach Gradescope's and PrairieLearn's results as numbers.
    const auto gradescope = nlohmann::json::parse(read_text(dir + "/results.json"));
    CHECK(gradescope.at("score").get<double>() == doctest::Approx(5.9));
    CHECK(gradescope.at("score").dump() == "5.9");
    CHECK(gradescope.at("tests").at(0).at("score").get<double>() == doctest::Approx(5.9));
    const auto pl = nlohmann::json::parse(grading::prairielearn_results_json(run, dir));
    CHECK(pl.at("score").get<double>() == doctest::Approx(5.9 / 9));
    CHECK(pl.at("tests").at(0).at("points").get<double>() == doctest::Approx(5.9));
}
