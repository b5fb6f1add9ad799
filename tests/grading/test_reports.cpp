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
#include <nlohmann/json.hpp>
#include <set>

#include "grading/report_text.hpp"
#include "grading/reports.hpp"
#include "tests/support/test_support.hpp"

namespace {

using grading::CheckResult;
using grading::GradeRun;
using grading::LabResult;

// Output of the failing probe: markup, quotes, a terminal escape, a control
// character and a byte that is not UTF-8, as a child's output may be.
const std::string kProbeOutput =
    "Expected (1, 0, 0) < observed & \"quoted\" 'single' \x1b[31mred\x01 \xff\n"
    "tolerance 1/255";
const std::string kCrash = "crashed (signal 11, SIGSEGV)";

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

// An independent decoder (RFC 4648 alphabet) to check the report's encoder.
std::string base64_decode(const std::string& text) {
    const std::string alphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    unsigned bits = 0, value = 0;
    for (char c : text) {
        if (c == '=') break;
        const size_t digit = alphabet.find(c);
        REQUIRE_MESSAGE(digit != std::string::npos, "not base64: '" << c << "'");
        value = (value << 6) | static_cast<unsigned>(digit);
        bits += 6;
        if (bits >= 8) {
            bits -= 8;
            out += static_cast<char>((value >> bits) & 0xFF);
        }
    }
    return out;
}

CheckResult check(const std::string& lab, const std::string& checkpoint, const std::string& kind,
                  const std::string& title, double score, double max_score, bool passed,
                  const std::string& output) {
    CheckResult c;
    c.lab = lab, c.checkpoint = checkpoint, c.kind = kind, c.title = title;
    c.visibility = "visible", c.score = score, c.max_score = max_score, c.passed = passed;
    c.output = output;
    return c;
}

// Lab 00: image 4/4 passed, probe 0/2 failed, hidden unit 3/3 passed.
// Lab 01 crashed: image 0/5 and stat 0/2 failed. Total 7/16, 2 of 5 passed.
struct Fixture {
    std::string dir = fw::test::out_dir();
    GradeRun run;
    std::vector<std::string> pngs;  // the three images of the passing check

    Fixture() {
        std::filesystem::create_directories(dir + "/00_pipeline");
        const char* names[] = {"triangle.png", "triangle.expected.png", "triangle.diff.png"};
        for (int i = 0; i < 3; ++i) {
            fw::Image img(4, 3, {static_cast<std::uint8_t>(80 * i), 200, 30, 255});
            img.at(1, 2) = {255, 0, 255, 255};
            pngs.push_back(std::string("00_pipeline/") + names[i]);
            fw::write_png(dir + "/" + pngs.back(), img);
        }
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
        hidden.visibility = "hidden";
        pipeline.checks.push_back(hidden);

        LabResult transforms;
        transforms.lab = "01_transforms";
        transforms.status = kCrash;
        transforms.log = "Segmentation fault <core dumped> & more";
        transforms.seconds = 0.4;
        CheckResult rotate = check("01_transforms", "rotate", "image", "image vs reference", 0, 5,
                                   false, "the lab wrote no image");
        rotate.rendered = "01_transforms/rotate.png";  // never written: the child crashed
        transforms.checks.push_back(rotate);
        transforms.checks.push_back(
            check("01_transforms", "rotate", "stat", "primitives_generated == 2", 0, 2, false, ""));
        run.labs = {pipeline, transforms};
        run.backend = "osmesa";
        run.seconds = 1.76;
        grading::write_reports(run, dir);
    }
};

}  // namespace

TEST_CASE("results.json follows Gradescope's format") {
    Fixture f;
    const auto j = nlohmann::json::parse(read_text(f.dir + "/results.json"));
    INFO(j.dump(2));
    CHECK(j.at("score").get<double>() == doctest::Approx(7.0));
    CHECK(j.at("max_score").get<double>() == doctest::Approx(16.0));
    CHECK(j.at("execution_time").get<double>() == doctest::Approx(1.76));
    CHECK(j.at("output").is_string());

    const auto& tests = j.at("tests");
    REQUIRE(tests.size() == 5);
    double score = 0, max_score = 0;
    const std::set<std::string> visibilities{"visible", "hidden", "after_due_date",
                                             "after_published"};
    for (const auto& t : tests) {
        CHECK(t.at("name").is_string());
        CHECK(t.at("number").is_string());
        CHECK(t.at("output").is_string());
        CHECK(visibilities.count(t.at("visibility").get<std::string>()) == 1);
        const std::string status = t.at("status").get<std::string>();
        CHECK((status == "passed" || status == "failed"));
        CHECK(t.at("score").get<double>() <= t.at("max_score").get<double>());
        score += t.at("score").get<double>();
        max_score += t.at("max_score").get<double>();
    }
    CHECK(score == doctest::Approx(7.0));
    CHECK(max_score == doctest::Approx(16.0));

    CHECK(tests[1].at("name") == "00_pipeline / triangle / probe (8, 8) colour");
    CHECK(tests[1].at("status") == "failed");
    CHECK(tests[1].at("number") == "0.2");
    const std::string probe = tests[1].at("output");
    CHECK(probe.find("< observed & \"quoted\" 'single' red \xEF\xBF\xBD\n") != std::string::npos);
    CHECK(tests[0].at("visibility") == "visible");
    CHECK(tests[2].at("visibility") == "hidden");
    CHECK(tests[2].at("status") == "passed");
    for (int i : {3, 4}) {
        CHECK(tests[i].at("status") == "failed");
        CHECK(tests[i].at("output").get<std::string>().find(kCrash) != std::string::npos);
    }
    CHECK(j.at("output").get<std::string>().find(kCrash) != std::string::npos);
}

TEST_CASE("junit.xml counts every check and escapes what the checks printed") {
    Fixture f;
    const std::string xml = read_text(f.dir + "/junit.xml");
    INFO(xml);
    CHECK(xml.rfind("<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<testsuites ", 0) == 0);
    CHECK(count(xml, "<testsuite ") == 2);
    CHECK(count(xml, "<testcase ") == 5);
    CHECK(count(xml, "<failure ") == 3);
    CHECK(xml.find("tests=\"5\" failures=\"3\"") != std::string::npos);
    CHECK(xml.find("name=\"00_pipeline\" tests=\"3\" failures=\"1\"") != std::string::npos);
    CHECK(xml.find("name=\"01_transforms\" tests=\"2\" failures=\"2\"") != std::string::npos);
    CHECK(xml.find("classname=\"00_pipeline\" name=\"triangle / probe (8, 8) colour\"") !=
          std::string::npos);

    // The output's markup arrives as text, in the message attribute and the body.
    CHECK(xml.find("< observed") == std::string::npos);
    CHECK(xml.find("<core") == std::string::npos);
    CHECK(xml.find("message=\"Expected (1, 0, 0) &lt; observed &amp; &quot;quoted&quot; "
                   "&#39;single&#39;") != std::string::npos);
    CHECK(xml.find("unit rotate(v, &lt;angle&gt;)") != std::string::npos);
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

TEST_CASE("index.html is self-contained and shows each check with its images") {
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

    for (const char* title : {"triangle / image vs reference", "triangle / probe (8, 8) colour",
                              "secret / unit rotate(v, &lt;angle&gt;)",
                              "rotate / primitives_generated == 2", "rotate / image vs reference"})
        CHECK_MESSAGE(html.find(title) != std::string::npos, "missing check " << title);
    CHECK(html.find("< observed") == std::string::npos);
    CHECK(html.find("&lt; observed &amp; &quot;quoted&quot;") != std::string::npos);
    CHECK(html.find("image not available: 01_transforms/rotate.png") != std::string::npos);
    CHECK(html.find(kCrash) != std::string::npos);
    CHECK(html.find("Segmentation fault &lt;core dumped&gt;") != std::string::npos);

    // Each embedded image decodes to the bytes of one of the check's PNG files.
    std::set<std::string> files;
    for (const std::string& png : f.pngs) files.insert(read_text(f.dir + "/" + png));
    std::set<std::string> decoded;
    for (size_t at = html.find(uri); at != std::string::npos; at = html.find(uri, at + 1)) {
        const size_t begin = at + uri.size();
        decoded.insert(base64_decode(html.substr(begin, html.find_first_of("\")", begin) - begin)));
    }
    CHECK(decoded == files);

    // Within a lab, failed checks come first.
    const std::string lab0 = html.substr(html.find("id=\"lab-0\""));
    CHECK(lab0.find("probe (8, 8) colour") < lab0.find("image vs reference"));
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

    CHECK(text.find("00_pipeline/triangle: probe (8, 8) colour - Expected (1, 0, 0) < observed") !=
          std::string::npos);
    CHECK(text.find("01_transforms/rotate: primitives_generated == 2 - lab 01_transforms: " +
                    kCrash) != std::string::npos);
    CHECK(text.find("image vs reference - the lab wrote no image") != std::string::npos);
    CHECK(text.find("Total: 7/16 points, 2 of 5 checks passed, 2 labs, 1.8 s") !=
          std::string::npos);
}

TEST_CASE("an empty run still writes all four reports") {
    const std::string dir = fw::test::out_dir() + "/fresh/grade";
    std::filesystem::remove_all(fw::test::out_dir() + "/fresh");
    grading::write_reports(GradeRun{}, dir);
    const auto j = nlohmann::json::parse(read_text(dir + "/results.json"));
    CHECK(j.at("score") == 0);
    CHECK(j.at("max_score") == 0);
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

TEST_CASE("a check whose visibility is neither visible nor hidden is an error") {
    GradeRun run;
    run.labs.resize(1);
    run.labs[0].lab = "00_pipeline";
    run.labs[0].checks.push_back(
        check("00_pipeline", "triangle", "probe", "probe", 1, 1, true, ""));
    run.labs[0].checks[0].visibility = "secret";
    fw::test::check_mentions(
        fw::test::thrown([&] { grading::write_reports(run, fw::test::out_dir()); }),
        {"00_pipeline/triangle", "\"secret\"", "visible or hidden"});
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
