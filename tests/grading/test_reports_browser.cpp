// The reports as a student sees them, in a real browser (headless Chromium,
// tests/support/browser.hpp): index.html as `course grade` writes it, and
// Gradescope's and PrairieLearn's results.json laid out as those sites show a
// test (its name, points, output, and its pictures). The run is real: lab 0
// graded with a realistic shader mistake (every colour's red and blue swapped),
// beside lab 1 whose child crashes. In every page each picture must load and
// show, pixel for pixel where the picture is of one colour, the frame, the
// reference or the difference it stands for; index.html must keep a card's
// pictures above its checks and Observed beside Expected. Screenshots of the
// pages are left in build/test-out/ to look at.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>

#include "framework/text.hpp"
#include "tests/grading/grade_support.hpp"
#include "tests/support/browser.hpp"

using namespace grade_test;
using fw::test::Browser;

namespace {

struct Box {
    double x = 0, y = 0, w = 0, h = 0;  // page CSS pixels (the screenshot's, at scale 1)
};
Box box_of(const json& j) { return {j["x"], j["y"], j["w"], j["h"]}; }

// JavaScript: the content box of element `e` in page coordinates.
const char* const kBoxJs =
    "const box = e => { const r = e.getBoundingClientRect(); return {x: r.left + scrollX + "
    "e.clientLeft, y: r.top + scrollY + e.clientTop, w: e.clientWidth, h: e.clientHeight}; };\n";

// The run every case looks at, graded once: lab 0 with the mistake, lab 1's
// child crashing (fake_lab), in Gradescope's format and in PrairieLearn's.
struct Run {
    std::string out, pl_results, mistaken_shaders;
};
const Run& graded_run() {
    static const Run run = [] {
        Run r;
        const std::string dir = fs::path(fw::test::out_dir()).parent_path() / "reports_browser_run";
        r.out = dir + "/report";
        r.pl_results = dir + "/prairielearn/results.json";
        r.mistaken_shaders = dir + "/shaders";
        fs::remove_all(dir);
        fs::create_directories(dir);
        fs::copy(fw::test::source_dir() + "/shaders", r.mistaken_shaders,
                 fs::copy_options::recursive);
        const std::string frag = r.mistaken_shaders + "/00_pipeline/pipeline.frag";
        std::string text = fw::test::read_text(frag);
        const std::string right = "vec4(v_color, 1.0)";
        const size_t at = text.find(right);
        REQUIRE_MESSAGE(at != std::string::npos, frag << " no longer writes " << right);
        text.replace(at, right.size(), "vec4(v_color.bgr, 1.0)");
        fw::test::write_text(frag, text);
        const std::string env = "LAB_SHADER_DIR=" + fw::shell_quote(r.mistaken_shaders) +
                                " FAKE_LAB_TARGET=transforms FAKE_LAB_MODE=segv";
        const std::string args = "pipeline transforms --lab " + fake_lab();
        const Graded gs = grade(env, args, r.out);
        REQUIRE(gs.exit_code == 1);
        REQUIRE(gs.results.is_object());
        const Graded pl = grade(env, args + " --format prairielearn --results " + r.pl_results,
                                dir + "/prairielearn-report");
        REQUIRE(pl.exit_code == 1);
        return r;
    }();
    return run;
}

json read_json(const std::string& path) {
    json j = json::parse(fw::test::read_text(path), nullptr, false);
    REQUIRE_MESSAGE(!j.is_discarded(), path << " is not JSON");
    return j;
}

// Whether `box` of the screenshot shows `source` scaled to fill it: compared
// at a grid of points where `source` is of one colour all around (away from
// edges, where scaling may take either side), within 0.1 per channel.
// Returns how many points were compared; a mismatch fails a check.
int check_shows(const fw::Image& shot, const Box& box, const fw::Image& source,
                const std::string& what) {
    CAPTURE(what);
    REQUIRE(box.w >= 8);
    REQUIRE(box.h >= 8);
    REQUIRE(box.x + box.w <= shot.width + 0.5);
    REQUIRE(box.y + box.h <= shot.height + 0.5);
    // Source pixels per shown pixel, and a margin of a few of them.
    const int margin = 2 + 2 * static_cast<int>(std::ceil(source.width / box.w));
    const int grid = 16;
    int compared = 0, wrong = 0;
    for (int gy = 0; gy < grid; ++gy)
        for (int gx = 0; gx < grid; ++gx) {
            const double u = (gx + 0.5) / grid, v = (gy + 0.5) / grid;  // v from the top
            const int sx = static_cast<int>(u * source.width);
            const int sy = source.height - 1 - static_cast<int>(v * source.height);
            const fw::Rgba8 want = source.at(sx, sy);
            bool uniform = true;
            for (int dy = -margin; dy <= margin && uniform; ++dy)
                for (int dx = -margin; dx <= margin && uniform; ++dx) {
                    const int x = std::clamp(sx + dx, 0, source.width - 1);
                    const int y = std::clamp(sy + dy, 0, source.height - 1);
                    uniform = source.at(x, y) == want;
                }
            if (!uniform) continue;
            const int px = static_cast<int>(box.x + u * box.w);
            const int py = shot.height - 1 - static_cast<int>(box.y + v * box.h);
            const fw::Rgba8 got = shot.at(px, py);
            const bool same = std::abs(got.r - want.r) <= 25 && std::abs(got.g - want.g) <= 25 &&
                              std::abs(got.b - want.b) <= 25;
            ++compared;
            if (!same && ++wrong <= 3)
                FAIL_CHECK(what << ": page pixel (" << px << ", "
                                << static_cast<int>(box.y + v * box.h) << ") is (" << +got.r << ", "
                                << +got.g << ", " << +got.b << "), the picture's (" << sx << ", "
                                << source.height - 1 - sy << ") is (" << +want.r << ", " << +want.g
                                << ", " << +want.b << ")");
        }
    CHECK_MESSAGE(wrong == 0, what << ": " << wrong << " of " << compared << " points differ");
    CHECK_MESSAGE(compared >= 16,
                  what << ": only " << compared << " points of one colour to compare");
    return compared;
}

// Text for an HTML page the test writes (the reports' own escaping is what
// is under test, so it is not used here).
std::string escape(const std::string& text) {
    std::string out;
    for (char c : text) {
        if (c == '&')
            out += "&amp;";
        else if (c == '<')
            out += "&lt;";
        else if (c == '>')
            out += "&gt;";
        else if (c == '"')
            out += "&quot;";
        else
            out += c;
    }
    return out;
}

// Starts the browser on `page` (a file), with no errors while loading it.
void open(Browser& browser, const std::string& page) {
    browser.navigate("file://" + fs::absolute(page).string());
    for (const std::string& e : browser.page_errors()) FAIL_CHECK("the page reported: " << e);
}

// A page laid out as a course site shows a test: its name and points, its
// output (`body`, HTML already), then its pictures as <img>.
std::string test_html(const std::string& name, double points, double max_points,
                      const std::string& body, const json& images) {
    std::ostringstream h;
    h << "<section class=\"test\" data-name=\"" << escape(name) << "\"><h2>" << escape(name) << " ("
      << points << " / " << max_points << ")</h2>\n"
      << body << "\n";
    for (const json& im : images)
        h << "<figure><img src=\"" << im["url"].get<std::string>() << "\" alt=\""
          << im["label"].get<std::string>() << "\"><figcaption>" << im["label"].get<std::string>()
          << "</figcaption></figure>\n";
    h << "</section>\n";
    return h.str();
}

std::string page_html(const std::string& title, const std::string& body) {
    return "<!DOCTYPE html><html lang=\"en\"><head><meta charset=\"utf-8\"><title>" + title +
           "</title><style>body { font: 14px sans-serif; margin: 1em; background: #fff; } "
           "section.test { border: 1px solid #ccc; margin: 1em 0; padding: 0.5em 1em; } "
           "figure { display: inline-block; margin: 0 1em 0 0; } pre { white-space: pre-wrap; "
           "}</style></head><body>\n" +
           body + "</body></html>\n";
}

// The pictures of each <img> in sections: {section name, label, content box,
// natural size}.
struct Picture {
    std::string section, label;
    Box box;
    int natural_width = 0, natural_height = 0;
    bool complete = false;
};
std::vector<Picture> pictures_in(Browser& browser) {
    const json found = browser.evaluate(
        std::string("(() => {") + kBoxJs +
        "return [...document.querySelectorAll('img')].map(i => ({section: "
        "i.closest('section').dataset.name, label: i.alt, box: box(i), complete: i.complete, "
        "w: i.naturalWidth, h: i.naturalHeight})); })()");
    std::vector<Picture> out;
    for (const json& p : found)
        out.push_back({p["section"], p["label"], box_of(p["box"]), p["w"], p["h"], p["complete"]});
    return out;
}

// The files behind a checkpoint's pictures, from index.html's figures:
// label -> image.
std::map<std::string, fw::Image> files_of(const std::string& checkpoint, const json& cards) {
    std::map<std::string, fw::Image> files;
    for (const json& card : cards)
        if (card["name"] == checkpoint)
            for (const json& f : card["figures"])
                files[f["caption"]] =
                    fw::read_png(fs::path(f["file"].get<std::string>()).is_absolute()
                                     ? f["file"].get<std::string>()
                                     : graded_run().out + "/" + f["file"].get<std::string>());
    return files;
}

// index.html's cards as the browser lays them out: name ("lab / checkpoint"),
// failed, figures (caption, file, content box, background), the checks
// table's box, its header cells and its failed rows' cells.
json index_cards(Browser& browser) {
    return browser.evaluate(
        std::string("(() => {") + kBoxJs +
        "return [...document.querySelectorAll('article.check')].map(a => ({"
        " name: a.closest('section').querySelector('h2').textContent + ' / ' +"
        "       a.querySelector('h3').childNodes[1].textContent,"
        " failed: a.classList.contains('fail'),"
        " figures: [...a.querySelectorAll('figure .shot')].map(s => ({caption:"
        "   s.closest('figure').querySelector('figcaption').textContent, file: s.title, box: "
        "box(s),"
        "   background: getComputedStyle(s).backgroundImage.slice(0, 27)})),"
        " table: box(a.querySelector('table.checks')),"
        " heads: [...a.querySelectorAll('table.checks th')].map(t => ({text: t.textContent, box: "
        "box(t)})),"
        " rows: [...a.querySelectorAll('table.checks tr.fail')].map(r => [...r.cells].map(box))"
        "})); })()");
}

// index.html's cards, from a browser of their own.
json cards_of_run() {
    Browser index(fw::test::out_dir() + "/chromium-index.log");
    open(index, graded_run().out + "/index.html");
    return index_cards(index);
}

// The pictures of a course site's page: each loaded, at its own size, showing
// the file it stands for; how many each test has.
std::map<std::string, int> check_pictures(Browser& browser, const std::string& page,
                                          const json& cards) {
    const std::vector<Picture> pictures = pictures_in(browser);
    const fw::Image shot = browser.screenshot(fw::test::out_dir() + "/" + page + ".png");
    MESSAGE("screenshot: " << fw::test::out_dir() << "/" << page << ".png (" << shot.width << "x"
                           << shot.height << "), " << pictures.size() << " pictures");
    std::map<std::string, int> per_test;
    for (const Picture& p : pictures) {
        CAPTURE(p.section);
        CAPTURE(p.label);
        ++per_test[p.section];
        CHECK(p.complete);
        CHECK(p.natural_width > 0);
        CHECK(p.natural_width <= 160);
        CHECK(p.natural_height <= 160);
        CHECK(p.box.w == p.natural_width);
        const std::map<std::string, fw::Image> files = files_of(p.section, cards);
        REQUIRE(files.count(p.label) == 1);
        check_shows(shot, p.box, files.at(p.label), p.section + " " + p.label);
    }
    // A failed checkpoint shows three pictures (rendered, expected,
    // difference) or none.
    for (const auto& [test, count] : per_test) CHECK_MESSAGE(count == 3, test);
    return per_test;
}

}  // namespace

TEST_CASE("index.html in a browser: each failed card shows its pictures above its checks") {
    fw::test::chromium_or_skip();
    const Run& run = graded_run();
    Browser browser(fw::test::out_dir() + "/chromium.log");
    open(browser, run.out + "/index.html");
    const json cards = index_cards(browser);
    const fw::Image shot = browser.screenshot(fw::test::out_dir() + "/index.png");
    MESSAGE("screenshot: " << fw::test::out_dir() << "/index.png (" << shot.width << "x"
                           << shot.height << ")");
    // Nothing wider than the window: the checks table wraps instead.
    CHECK(shot.width == 1280);

    int failed_cards = 0, compared = 0;
    for (const json& card : cards) {
        const std::string name = card["name"];
        CAPTURE(name);
        if (!card["failed"]) continue;
        ++failed_cards;
        const Box table = box_of(card["table"]);
        for (const json& f : card["figures"]) {
            CAPTURE(f["caption"].get<std::string>());
            CHECK(f["background"] == "url(\"data:image/png;base64,");
            const Box b = box_of(f["box"]);
            CHECK_MESSAGE(b.y + b.h <= table.y, "a picture below the checks table");
        }
        for (const auto& [caption, image] : files_of(name, cards))
            for (const json& f : card["figures"])
                if (f["caption"] == caption)
                    compared += check_shows(shot, box_of(f["box"]), image, name + " " + caption);
        // Expected and Observed side by side: one row, Observed to the right,
        // in the header and in every failed check's row.
        std::map<std::string, Box> heads;
        for (const json& th : card["heads"]) heads[th["text"]] = box_of(th["box"]);
        REQUIRE(heads.count("Expected") == 1);
        REQUIRE(heads.count("Observed") == 1);
        // (A content box's width is whole pixels, its place is not: 1 px slack.)
        auto beside = [](const Box& left, const Box& right) {
            return left.y == right.y && left.x + left.w <= right.x + 1;
        };
        CHECK(beside(heads["Expected"], heads["Observed"]));
        for (const json& row : card["rows"]) {
            REQUIRE(row.size() == 4);
            CHECK(beside(box_of(row[2]), box_of(row[3])));
        }
    }
    MESSAGE(failed_cards << " failed cards, " << compared << " picture points compared");
    // Every visible and hidden checkpoint of lab 0 with an image failed.
    CHECK(failed_cards >= 6);

    // The table at the top says why lab 1 has no points.
    const json statuses = browser.evaluate(
        "[...document.querySelectorAll('table.labs tr')].slice(1).map(r => [r.cells[0].textContent,"
        " r.cells[3].textContent])");
    CHECK(statuses.dump().find("[\"transforms\",\"crashed (signal 11, SIGSEGV)\"]") !=
          std::string::npos);
    CHECK(statuses.dump().find("[\"pipeline\",\"ok\"]") != std::string::npos);
}

TEST_CASE(
    "Gradescope's html outputs in a browser: each failed checkpoint's pictures load and show") {
    fw::test::chromium_or_skip();
    const Run& run = graded_run();
    const json results = read_json(run.out + "/results.json");
    // As a student sees it before the due date: the overview and the visible tests.
    std::string body = "<section class=\"test\" data-name=\"overview\">" +
                       results["output"].get<std::string>() + "</section>\n";
    size_t shown = 0;
    for (const json& t : results["tests"]) {
        if (t["visibility"] != "visible") continue;
        REQUIRE(t["output_format"] == "html");
        body += test_html(t["name"], t["score"], t["max_score"], t["output"], json::array());
        ++shown;
    }
    const std::string page = fw::test::out_dir() + "/gradescope.html";
    fw::test::write_text(page, page_html("Gradescope results", body));

    const json cards = cards_of_run();
    Browser browser(fw::test::out_dir() + "/chromium.log");
    open(browser, page);
    std::map<std::string, int> per_test = check_pictures(browser, "gradescope", cards);
    MESSAGE(shown << " visible tests");
    // Three pictures (rendered, expected, difference) for each visible
    // checkpoint of lab 0 that failed its image check.
    int with_pictures = 0;
    for (const json& t : results["tests"])
        if (t["visibility"] == "visible" &&
            t["name"].get<std::string>().rfind("pipeline /", 0) == 0 && t["status"] == "failed") {
            CHECK_MESSAGE(per_test[t["name"]] == 3, t["name"]);
            with_pictures += per_test[t["name"]] == 3;
        }
    CHECK(with_pictures >= 4);
}

TEST_CASE("PrairieLearn's images in a browser: each failed checkpoint's pictures load and show") {
    fw::test::chromium_or_skip();
    const Run& run = graded_run();
    const json results = read_json(run.pl_results);
    std::string body = "<section class=\"test\" data-name=\"overview\"><pre>" +
                       escape(results["output"].get<std::string>()) + "</pre></section>\n";
    for (const json& t : results["tests"])
        body += test_html(t["name"], t["points"], t["max_points"],
                          "<p>" + escape(t["message"].get<std::string>()) + "</p><pre>" +
                              escape(t["output"].get<std::string>()) + "</pre>",
                          t["images"]);
    const std::string page = fw::test::out_dir() + "/prairielearn.html";
    fw::test::write_text(page, page_html("PrairieLearn results", body));

    const json cards = cards_of_run();
    Browser browser(fw::test::out_dir() + "/chromium.log");
    open(browser, page);
    std::map<std::string, int> per_test = check_pictures(browser, "prairielearn", cards);
    // Pictures for lab 0's failed visible checkpoints; none for hidden ones.
    int with_pictures = 0;
    for (const json& t : results["tests"])
        if (t["name"].get<std::string>().rfind("pipeline /", 0) == 0 &&
            t["points"] < t["max_points"])
            with_pictures += per_test[t["name"]] == 3;
    CHECK(with_pictures >= 4);
}

TEST_CASE("index.html in a browser: no accessibility violation (contrast, headers, landmarks)") {
    fw::test::chromium_or_skip();
    const Run& run = graded_run();
    Browser browser(fw::test::out_dir() + "/chromium-a11y.log");
    open(browser, run.out + "/index.html");
    const json found = fw::test::check_accessibility(browser);
    CHECK(found["texts"] > 100);
}

// The W3C checker (vnu) is not in Debian: index.html is parsed instead by
// html5lib in strict mode (parse_html_strictly), which refuses any parse
// error: a stray end tag, an unclosed element, a misnested table, a bad
// character reference, a missing doctype.
TEST_CASE("index.html parses as HTML without an error (html5lib, strict)") {
    const Run& run = graded_run();
    const std::optional<fw::test::CommandResult> parsed =
        fw::test::parse_html_strictly(run.out + "/index.html");
    if (!parsed) return;
    INFO(parsed->output);
    CHECK(parsed->exit_code == 0);
    CHECK(parsed->output == "ok\n");
}
