// `course grade-class`'s page for the staff, DIR/class.html
// (grading/class/class_page.hpp). A small class graded for real, lab 1 only,
// two submissions at once: the solution, the starting copy, a copy with a
// known mistake from the mistakes suite's list, and a copy that does not
// build. The page's histogram and its table against grades.csv, the
// checkpoints' failures against the students' results.json and in their
// order, the named mistake with its student and its frame, the build failure
// with its first error, and the page in headless Chromium through the
// reports' accessibility checks (tests/support/browser.hpp). Then a page from
// rows made by hand (a timeout, a crash, a submission that could not be read,
// two students in one submission), and the sentences that name a mistake.
#include <algorithm>
#include <cmath>
#include <map>
#include <regex>

#include "grading/class/class_findings.hpp"
#include "grading/class/class_page.hpp"
#include "grading/diagnosis/solution_blocks.hpp"
#include "tests/grading/grade_support.hpp"
#include "tests/mistakes/mistakes.hpp"
#include "tests/support/browser.hpp"

using namespace grade_test;

namespace {

const char* const kMistake = "transforms-translate-bottom-row";
const char* const kFile = "labs/01_transforms/transforms_math.cpp";

// The mistake `id` of the suite's list: {"find", "replace", "named", ...}.
json listed_mistake(const std::string& id) {
    const json list = json::parse(kMistakesJson, nullptr, true, /*ignore_comments=*/true);
    for (const json& m : list.at("mistakes"))
        if (m.at("id") == id) return m;
    FAIL(id << " is no longer in tests/mistakes/mistakes.hpp");
    return {};
}

std::string with_mistake(std::string text, const json& m) {
    const std::string find = m.at("find"), replace = m.at("replace");
    const size_t at = text.find(find);
    REQUIRE_MESSAGE(at != std::string::npos, kFile << " no longer holds the mistake's text");
    return text.replace(at, find.size(), replace);
}

struct ClassRun {
    std::string out;
    int exit_code = -1;
};

// The class, graded once for every case.
const ClassRun& graded_class() {
    static const ClassRun run = [] {
        const fs::path dir = fs::path(fw::test::out_dir()).parent_path() / "class_page_run";
        fs::remove_all(dir);
        const std::string solution = fw::test::read_text(fw::test::source_dir() + "/" + kFile);
        const std::map<std::string, std::string> submissions = {
            {"alice", solution},
            {"bob", grading::student_text(solution, kFile)},
            {"carol", with_mistake(solution, listed_mistake(kMistake))},
            {"dave", solution + "\nint does_not_build = ;\n"}};
        for (const auto& [key, text] : submissions)
            fw::test::write_text((dir / "subs" / key / "transforms_math.cpp").string(), text);
        const fw::test::CommandResult r = fw::test::run_command(
            course() + " grade-class " + fw::shell_quote((dir / "subs").string()) + " --out " +
            fw::shell_quote((dir / "out").string()) + " --labs transforms --jobs 2 2>&1");
        MESSAGE("course grade-class: exit " << r.exit_code << "\n" << r.output);
        return ClassRun{(dir / "out").string(), r.exit_code};
    }();
    return run;
}

// grades.csv's rows as maps from its header's names (RFC 4180 quoting).
std::vector<std::map<std::string, std::string>> read_csv(const std::string& path) {
    std::vector<std::vector<std::string>> lines(1);
    std::string field;
    bool quoted = false;
    const std::string text = fw::test::read_text(path);
    for (size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (quoted && c == '"' && i + 1 < text.size() && text[i + 1] == '"') {
            field += '"';
            ++i;
        } else if (c == '"') {
            quoted = !quoted;
        } else if (!quoted && (c == ',' || c == '\n')) {
            lines.back().push_back(field);
            field.clear();
            if (c == '\n') lines.emplace_back();
        } else if (quoted || c != '\r') {
            field += c;
        }
    }
    lines.pop_back();
    std::vector<std::map<std::string, std::string>> rows;
    for (size_t l = 1; l < lines.size(); ++l) {
        REQUIRE(lines[l].size() == lines[0].size());
        std::map<std::string, std::string>& row = rows.emplace_back();
        for (size_t i = 0; i < lines[0].size(); ++i) row[lines[0][i]] = lines[l][i];
    }
    return rows;
}

// The part of the page in <section ... id="ID">.
std::string section(const std::string& page, const std::string& id) {
    const size_t from = page.find("<section class=\"part\" id=\"" + id + "\">");
    REQUIRE_MESSAGE(from != std::string::npos, "class.html has no section " << id);
    return page.substr(from, page.find("</section>", from) - from);
}

// Every match of `pattern` in `text`: its groups.
std::vector<std::vector<std::string>> all_matches(const std::string& text,
                                                  const std::string& pattern) {
    std::vector<std::vector<std::string>> out;
    const std::regex re(pattern);
    for (auto it = std::sregex_iterator(text.begin(), text.end(), re); it != std::sregex_iterator();
         ++it) {
        std::vector<std::string>& groups = out.emplace_back();
        for (size_t i = 1; i < it->size(); ++i) groups.push_back((*it)[i]);
    }
    return out;
}

std::string page_of(const ClassRun& run) {
    const std::string page = fw::test::read_text(run.out + "/class.html");
    REQUIRE_MESSAGE(!page.empty(), run.out << "/class.html is missing or empty");
    return page;
}

}  // namespace

TEST_CASE("class.html: the histogram and its table hold grades.csv's scores") {
    const ClassRun& run = graded_class();
    CHECK(run.exit_code == 1);  // dave's copy does not build
    const auto rows = read_csv(run.out + "/grades.csv");
    REQUIRE(rows.size() == 4);
    const double max = std::stod(rows[0].at("max"));
    REQUIRE(max > 10);
    // Bins of whole points, about ten, the last one closed (the page's rule).
    const double width = std::ceil(max / 10);
    const size_t bins = size_t(std::ceil(max / width));
    std::vector<int> counts(bins, 0);
    double lowest = max, highest = 0;
    for (const auto& r : rows) {
        const double s = std::stod(r.at("transforms"));
        ++counts[std::min(bins - 1, size_t(s / width))];
        lowest = std::min(lowest, s);
        highest = std::max(highest, s);
    }
    const std::string scores = section(page_of(run), "scores");
    const auto table =
        all_matches(scores, R"(<tr><th scope="row">([^<]*)</th><td class="num">(\d+)</td></tr>)");
    REQUIRE(table.size() == bins);
    for (size_t i = 0; i < bins; ++i) {
        const std::string from = fw::trimmed_decimals(double(i) * width, 2);
        CHECK(table[i][0] ==
              (i + 1 < bins ? from + " to under " + fw::trimmed_decimals(double(i + 1) * width, 2)
                            : from + " to " + fw::trimmed_decimals(max, 2)));
        CHECK(table[i][1] == std::to_string(counts[i]));
    }
    // The bars: one per bin that has students, labelled with its count.
    const auto bars = all_matches(scores, R"(<rect [^>]*/><text [^>]*>(\d+)</text>)");
    std::vector<std::string> shown, expected;
    for (const auto& b : bars) shown.push_back(b[0]);
    for (int c : counts)
        if (c > 0) expected.push_back(std::to_string(c));
    CHECK(shown == expected);
    CHECK(scores.find("4 students of " + fw::trimmed_decimals(max, 2) + " points") !=
          std::string::npos);
    CHECK(scores.find("lowest " + fw::trimmed_decimals(lowest, 2) + ", highest " +
                      fw::trimmed_decimals(highest, 2)) != std::string::npos);
}

TEST_CASE("class.html: each checkpoint's failures, the most failed first") {
    const ClassRun& run = graded_class();
    // Independently: the tests of every results.json of a lab that ran.
    std::map<std::string, std::pair<int, int>> expected;  // checkpoint -> failed, passed
    for (const char* key : {"alice", "bob", "carol"}) {
        const json results = json::parse(
            fw::test::read_text(run.out + "/students/" + key + "/transforms/results.json"));
        for (const json& t : results.at("tests")) {
            auto& [failed, passed] = expected[t.at("extra_data").at("checkpoint")];
            (t.at("status") == "passed" ? passed : failed) += 1;
        }
    }
    const std::string part = section(page_of(run), "checkpoints");
    CHECK(part.find("(3 students)") != std::string::npos);  // dave's did not build
    const auto table = all_matches(
        part, R"(<tr><th scope="row">([a-z_0-9]+)(?:<span class="tag">hidden</span>)?</th>)"
              R"(<td class="num">(\d+)</td><td class="num">(\d+)</td>)");
    REQUIRE(table.size() == expected.size());
    double rate_before = 2;
    for (const auto& row : table) {
        CAPTURE(row[0]);
        REQUIRE(expected.count(row[0]));
        CHECK(std::stoi(row[1]) == expected[row[0]].first);
        CHECK(std::stoi(row[2]) == expected[row[0]].second);
        const double rate = std::stod(row[1]) / (std::stod(row[1]) + std::stod(row[2]));
        CHECK(rate <= rate_before);
        rate_before = rate;
    }
}

TEST_CASE("class.html: the named mistake with its student and a frame of theirs") {
    const ClassRun& run = graded_class();
    const std::string part = section(page_of(run), "mistakes");
    // The rows, each from its rank cell on.
    std::vector<std::string> rows;
    for (size_t at = part.find("<tr><td class=\"num\">"); at != std::string::npos;) {
        const size_t next = part.find("<tr><td class=\"num\">", at + 1);
        rows.push_back(part.substr(at, next == std::string::npos ? next : next - at));
        at = next;
    }
    REQUIRE(rows.size() >= 2);
    double before = 1e9;
    for (const std::string& row : rows) {  // ranked by students, the most first
        const auto students = all_matches(row, R"(</td><td class="num">(\d+)</td><td><ul>)");
        REQUIRE(students.size() == 1);
        CHECK(std::stod(students[0][0]) <= before);
        before = std::stod(students[0][0]);
    }
    // The known mistake's frame, and the unit check's name for it, both carol's only.
    const json m = listed_mistake(kMistake);
    for (const std::string& name : {std::string(kMistake), m.at("named").get<std::string>()}) {
        CAPTURE(name);
        const auto row = std::find_if(rows.begin(), rows.end(), [&](const std::string& r) {
            return std::regex_search(r, std::regex("<th scope=\"row\">([a-z-]+ or )?" + name +
                                                   "( or [a-z-]+)?<details>"));
        });
        REQUIRE(row != rows.end());
        CHECK(row->find("href=\"students/carol/transforms/index.html\"") != std::string::npos);
        CHECK(row->find("students/alice/") == std::string::npos);
        CHECK(row->find("students/bob/") == std::string::npos);
    }
    const auto frame = all_matches(
        part,
        std::string(">") + kMistake +
            R"re(<details>[\s\S]*?<a href="(students/carol/transforms/transforms/[a-z_]+\.png)">)re"
            R"re(<img class="frame" src="data:image/png;base64,([A-Za-z0-9+/=]+)" alt="([^"]+)")re");
    REQUIRE(frame.size() == 1);
    const std::string file = fw::test::read_text(run.out + "/" + frame[0][0]);
    REQUIRE(!file.empty());
    CHECK(fw::test::base64_decode(frame[0][1]) == file);
    CHECK(frame[0][2].find("carol") != std::string::npos);
    // The solution names nothing.
    CHECK(part.find("students/alice/") == std::string::npos);
}

TEST_CASE("class.html: the copy that does not build, with the compiler's first error") {
    const ClassRun& run = graded_class();
    const auto rows = read_csv(run.out + "/grades.csv");
    const auto dave = std::find_if(rows.begin(), rows.end(),
                                   [](const auto& r) { return r.at("submission") == "dave"; });
    REQUIRE(dave != rows.end());
    const std::string lead = "does not build: ", status = dave->at("status");
    REQUIRE(status.rfind(lead, 0) == 0);
    const std::string first_error = status.substr(lead.size());
    CHECK(first_error.find("transforms_math.cpp:") != std::string::npos);
    CHECK(first_error.find("error") != std::string::npos);
    const std::string part = unescape_markup(section(page_of(run), "attention"));
    CHECK(part.find("Did not build (1)") != std::string::npos);
    CHECK(part.find("<pre>" + first_error + "</pre>") != std::string::npos);
    CHECK(part.find("Timed out or crashed (0)") != std::string::npos);
    CHECK(part.find("Not graded (0)") != std::string::npos);
    CHECK(page_of(run).find("Grading took ") != std::string::npos);
}

TEST_CASE("class.html in a browser: accessible, its frame and histogram shown") {
    if (!fw::test::chromium_for_case()) return;
    const ClassRun& run = graded_class();
    fw::test::Browser browser(fw::test::out_dir() + "/chromium-class.log");
    browser.navigate("file://" + fs::absolute(run.out + "/class.html").string());
    for (const std::string& e : browser.page_errors()) FAIL_CHECK("the page reported: " << e);
    const json found = fw::test::check_accessibility(browser);
    CHECK(found["texts"] > 50);
    const json shown = browser.evaluate(
        "(() => ({frames: [...document.querySelectorAll('img.frame')].map(i => i.complete && "
        "i.naturalWidth > 0 && i.clientWidth > 0), svg: [...document.querySelectorAll('svg')]"
        ".map(s => s.getBoundingClientRect().width)}))()");
    REQUIRE(shown["frames"].size() >= 1);
    for (const json& f : shown["frames"]) CHECK(f == true);
    REQUIRE(shown["svg"].size() == 1);
    CHECK(shown["svg"][0] > 200);
    browser.screenshot(fw::test::out_dir() + "/class.png");
    MESSAGE("screenshot: " << fw::test::out_dir() << "/class.png");
}

TEST_CASE("class.html parses as HTML without an error (html5lib, strict)") {
    const std::optional<fw::test::CommandResult> parsed =
        fw::test::parse_html_strictly(graded_class().out + "/class.html");
    if (!parsed) return;
    INFO(parsed->output);
    CHECK(parsed->exit_code == 0);
    CHECK(parsed->output == "ok\n");
}

namespace {

grading::cls::ClassRow made_row(const std::string& key, double score, const std::string& status) {
    grading::cls::ClassRow r;
    r.submission.key = key;
    grading::cls::LabGrade& g = r.labs["transforms"];
    g.status = status;
    g.score = score;
    g.max_score = 40;
    return r;
}

// A report of lab 1 whose checkpoint identity fails a unit check that
// names `mistakes` apart, as results.json writes it.
void write_report(const fs::path& dir, const std::string& key,
                  const std::vector<std::string>& mistakes) {
    std::string pre;
    for (const std::string& m : mistakes) pre += "Likely mistake (" + m + "): it is.\n";
    const json test = {
        {"name", "transforms / identity"},
        {"status", "failed"},
        {"visibility", "visible"},
        {"output", "<p><strong>FAIL</strong> unit translate (0 / 3 points)</p>\n<pre>" + pre +
                       "</pre>\n<p><strong>PASS</strong> image vs reference (2 / 2 points)</p>"},
        {"extra_data",
         {{"checkpoint", "identity"},
          {"checks",
           {{{"title", "unit translate"}, {"kind", "unit"}, {"passed", false}},
            {{"title", "image vs reference"}, {"kind", "image"}, {"passed", true}}}}}}};
    fw::test::write_text((dir / "students" / key / "transforms" / "results.json").string(),
                         json{{"tests", {test}}}.dump());
}

}  // namespace

TEST_CASE("class.html from rows made by hand: a timeout, a crash, a submission not read") {
    const fs::path dir = fs::path(fw::test::out_dir()) / "by_hand";
    fs::remove_all(dir);
    fs::create_directories(dir);
    std::vector<grading::cls::ClassRow> rows = {
        made_row("a<b&c", 10, "timed out after 60 s"), made_row("crash", 0, "crashed (SIGSEGV)"),
        made_row("pair", 40, "graded"), made_row("close", 39.99, "graded"),
        made_row("unread", 0, "not graded")};
    rows[2].submission.students = {{"Ann Lee", "ann@example.edu", "1"},
                                   {"Ben Ode", "ben@example.edu", "2"}};
    rows[4].error = "the archive is not a zip file";
    rows[4].labs["transforms"].reason = "the submission could not be read";
    write_report(dir, "pair", {"shared-one"});
    write_report(dir, "close", {"alone", "shared-one"});
    grading::cls::write_class_page(dir, rows, {{"transforms", "01_transforms"}}, 75);
    const std::string page = fw::test::read_text((dir / "class.html").string());
    REQUIRE(!page.empty());
    // 40 points: bins of 4; the pair counts twice, 39.99 is in the last bin.
    const auto table =
        all_matches(section(page, "scores"),
                    R"(<tr><th scope="row">([^<]*)</th><td class="num">(\d+)</td></tr>)");
    REQUIRE(table.size() == 10);
    CHECK(table[0] == std::vector<std::string>{"0 to under 4", "2"});
    CHECK(table[2] == std::vector<std::string>{"8 to under 12", "1"});
    CHECK(table[9] == std::vector<std::string>{"36 to 40", "3"});
    CHECK(page.find("6 students of 40 points") != std::string::npos);
    CHECK(page.find("Grading took 1 min 15 s") != std::string::npos);
    const std::string attention = section(page, "attention");
    CHECK(attention.find("Timed out or crashed (2)") != std::string::npos);
    CHECK(attention.find("timed out after 60 s") != std::string::npos);
    CHECK(attention.find("crashed (SIGSEGV)") != std::string::npos);
    CHECK(attention.find("Not graded (1)") != std::string::npos);
    CHECK(attention.find("the archive is not a zip file") != std::string::npos);
    CHECK(attention.find("Did not build (0)") != std::string::npos);
    // A key is text, escaped, and a path, percent-encoded.
    CHECK(attention.find("href=\"students/a%3Cb%26c/transforms/index.html\">a&lt;b&amp;c</a>") !=
          std::string::npos);
    CHECK(page.find("a<b&c") == std::string::npos);
    // The reports written above: three students name one mistake, one the other.
    const auto named = all_matches(section(page, "mistakes"),
                                   R"(<th scope="row">([a-z-]+)<details>[\s\S]*?</td><td )"
                                   R"(class="num">(\d+)</td>)");
    CHECK(named == std::vector<std::vector<std::string>>{{"shared-one", "3"}, {"alone", "1"}});
    CHECK(section(page, "checkpoints").find("(3 students)") != std::string::npos);
}

TEST_CASE("the sentences that name a mistake, and those that do not") {
    using grading::cls::namings_in;
    using Keys = std::vector<std::string>;
    const auto keys = [](const std::string& kind, const std::string& text) {
        Keys k;
        for (const grading::cls::Naming& n : namings_in(kind, text)) k.push_back(n.key);
        return k;
    };
    CHECK(keys("unit",
               "Observed: 1 of 10 cases passed\n"
               "Likely mistake (flipped-angle): the turn runs clockwise.\n") ==
          Keys{"likely:flipped-angle"});
    CHECK(keys("unit", "Likely mistake (transpose): a.\nLikely mistake (inverse): b.\n") ==
          Keys{"likely:transpose", "likely:inverse"});
    CHECK(keys("unit",
               "Likely mistake (transpose): a.\nLikely mistake (inverse): b.\nThe likely "
               "mistakes above give the same values on these cases, so any one of them "
               "may be the cause.") == Keys{"likely:transpose or inverse"});
    CHECK(keys("buffer", "Observed: ...\nLikely mistake (gravity-twice): gravity applied twice.") ==
          Keys{"likely:gravity-twice"});
    CHECK(keys("image",
               "Observed: ...\nYour frame is the one a known mistake draws (t-b): the "
               "frame of code that x. Another mistake can draw the same frame.") ==
          Keys{"known:t-b"});
    CHECK(keys("image", "Your frame is the one known mistakes draw (a-b, c-d): the frame of ...") ==
          Keys{"known:a-b or c-d"});
    CHECK(keys("image", "Your frame is the one checkpoint srt expects (angle 90, here 0): ...") ==
          Keys{"checkpoint:srt"});
    // Not names: a sentence under a kind of check that never writes it, the
    // difference's words, the state diff's, a part's starting code, a name
    // within another line, an id that is none.
    for (const auto& [kind, text] : std::vector<std::pair<std::string, std::string>>{
             {"image", "Likely mistake (transpose): a."},
             {"probe", "Likely mistake (transpose): a."},
             {"unit", "Your frame is the one a known mistake draws (x): y."},
             {"image",
              "Where: the differing pixels lie in x 0-10, y 0-10\n  27 pixels: expected "
              "black (0, 0, 0), found red (1, 0, 0), in x 0-2, y 1-5"},
             {"image",
              "Draw 2 of checkpoint `trs`: glBlendFunc's source factor is GL_ONE; the "
              "reference's is GL_SRC_ALPHA."},
             {"image",
              "Part 4 (`back_to_front()` in labs/07_framebuffer_ops/blending.cpp) still "
              "has its starting code; this checkpoint needs it."},
             {"unit", "the lab printed: Likely mistake (transpose): a."},
             {"unit", "Likely mistake (two words): a."},
             {"image", "Your frame is the one known mistakes draw (a): one where several are."}})
        CHECK_MESSAGE(namings_in(kind, text).empty(), kind << ": " << text);
}
