// Which file is wrong (docs/contract.md, Which file is wrong): real labs
// graded by the real `lab`, each with mistakes written into a copy of the
// shaders (LAB_SHADER_DIR) or, for C++, into a copy of the tree, built. A
// failed checkpoint names the one shader file whose course version puts its
// frame right, in every report; a mistake in C++, in two files at once, or
// in a student's copy (no solution to compare with) names none. The fake
// lab (FAKE_LAB_MARK, no target) runs the real one and counts the children:
// a solution starts no more than one.
#include <map>
#include <regex>
#include <set>
#include <sstream>

#include "grading/release/release.hpp"
#include "tests/grading/grade_support.hpp"
#include "tests/grading/tree_support.hpp"

using namespace grade_test;

namespace {

// One change to a file: `find` occurs once in it and becomes `replace`.
struct Change {
    std::string file;  // under shaders/, or the repository for C++
    std::string find, replace;
};

const Change kCutoutKeepsTransparent = {"07_framebuffer_ops/cutout.frag",
                                        "if (u_alpha_test && alpha < u_cutoff) discard;",
                                        "if (u_alpha_test && alpha > u_cutoff) discard;"};
const Change kSilhouetteBackFaces = {
    "10_advanced_geometry/silhouette.geom",
    "    if (!front_facing(gl_in[0].gl_Position, gl_in[2].gl_Position, gl_in[4].gl_Position)) "
    "return;\n",
    ""};
const Change kShadingVertHalfSize = {
    "06_interpolation/shading.vert", "gl_Position = u_view_projection * vec4(a_position, 1.0);",
    "gl_Position = u_view_projection * vec4(a_position * 0.5, 1.0);"};
const Change kShadingFragHalfColour = {"06_interpolation/shading.frag",
                                       "frag_color = vec4(color, 1.0);",
                                       "frag_color = vec4(color * 0.5, 1.0);"};
// Its frames stay right on llvmpipe: only the portable check sees it.
const Change kAdvanceNoBoundsCheck = {"09_buffers/advance.comp", "    if (i >= u_count) return;\n",
                                      ""};

void apply(const fs::path& root, const Change& c) {
    const fs::path file = root / c.file;
    std::string text = fw::test::read_text(file.string());
    const size_t at = text.find(c.find);
    REQUIRE_MESSAGE(at != std::string::npos, c.file << " has no '" << c.find << "'");
    REQUIRE_MESSAGE(text.find(c.find, at + 1) == std::string::npos,
                    c.file << " has '" << c.find << "' more than once");
    fw::test::write_text(file.string(), text.replace(at, c.find.size(), c.replace));
}

// A copy of the shaders with `changes` made: LAB_SHADER_DIR=... for course.
std::string shaders_with(const std::vector<Change>& changes) {
    const fs::path dir = fs::path(fw::test::out_dir()) / "shaders";
    fs::remove_all(dir);
    fs::copy(fs::path(fw::test::source_dir()) / "shaders", dir, fs::copy_options::recursive);
    for (const Change& c : changes) apply(dir, c);
    return "LAB_SHADER_DIR=" + fw::shell_quote(dir.string());
}

// What one grading wrote: each report's text, as a student reads it.
struct Reports {
    Graded graded;
    std::map<std::string, std::string> text;  // by report: summary.txt, index.html, ...
    int child_starts = 0;                     // `lab` processes course started
};

// `course grade LAB` through the fake lab, which runs the real one and
// notes each start.
Reports grade_lab(const std::string& env, const std::string& lab) {
    const std::string out = fw::test::out_dir() + "/report",
                      mark = fw::test::out_dir() + "/child_starts";
    fs::remove(mark);
    Reports r;
    r.graded = grade("env -u LAB_ROOT -u LAB_SHADER_DIR FAKE_LAB_MARK=" + mark + " " + env,
                     lab + " --lab " + fake_lab(), out);
    REQUIRE(r.graded.results.is_object());
    for (const char* report : {"summary.txt", "index.html", "junit.xml"})
        r.text[report] = unescape_markup(fw::test::read_text(out + "/" + report));
    std::string outputs;
    for (const json& t : r.graded.results["tests"]) outputs += unescape_markup(t["output"]) + "\n";
    r.text["results.json"] = outputs;
    r.text["terminal"] = r.graded.output;
    std::istringstream starts(fw::test::read_text(mark));
    for (std::string line; std::getline(starts, line);) r.child_starts += !line.empty();
    return r;
}

// The files the sentences of `text` name, each with the file name it
// quotes, which must be that file's.
std::multiset<std::string> named_files(const std::string& text) {
    static const std::regex sentence(
        "The frame is right with the course's `([^`]+)` in place of yours: the mistake is in "
        "shaders/(\\S+?)\\.(\\s|<|$)");
    std::multiset<std::string> files;
    for (std::sregex_iterator it(text.begin(), text.end(), sentence), end; it != end; ++it) {
        CHECK((*it)[2].str().substr((*it)[2].str().rfind('/') + 1) == (*it)[1].str());
        files.insert((*it)[2].str());
    }
    // Nothing else reads like it.
    size_t mentions = 0;
    for (size_t at = text.find("in place of yours"); at != std::string::npos;
         at = text.find("in place of yours", at + 1))
        ++mentions;
    CHECK(mentions == files.size());
    return files;
}

// Each report names `file` (under shaders/), and no other, `times` times,
// once for each checkpoint in `checkpoints`.
void check_names(const Reports& r, const std::string& file,
                 const std::set<std::string>& checkpoints) {
    for (const auto& [report, text] : r.text) {
        CAPTURE(report);
        const std::multiset<std::string> files = named_files(text);
        CHECK(files.count(file) == files.size());
        // The terminal shows the first 25 failed checks; the others all.
        if (report != "terminal")
            CHECK(files.size() == checkpoints.size());
        else
            CHECK(!files.empty());
    }
    // results.json: under its checkpoint's test, one each.
    for (const json& t : r.graded.results["tests"]) {
        const std::string name = t["name"], output = unescape_markup(t["output"]);
        const std::string checkpoint = name.substr(name.find(" / ") + 3);
        CAPTURE(name);
        CHECK(named_files(output).size() == checkpoints.count(checkpoint));
    }
}

void check_names_none(const Reports& r) {
    CHECK(r.graded.exit_code == 1);  // the mistakes fail checks
    for (const auto& [report, text] : r.text) {
        CAPTURE(report);
        CHECK(named_files(text).empty());
    }
}

// The checkpoints of `lab` in the run whose tests failed.
std::set<std::string> failed_checkpoints(const Reports& r, const std::string& lab) {
    std::set<std::string> failed;
    for (const json& t : r.graded.results["tests"])
        if (t["status"] == "failed" && t["name"].get<std::string>().rfind(lab + " / ", 0) == 0)
            failed.insert(t["name"].get<std::string>().substr(lab.size() + 3));
    return failed;
}

}  // namespace

TEST_CASE("which file: a mistake in one shader names that file under its checkpoints") {
    SUBCASE("lab 7: cutout.frag keeps the transparent fragments, on each backend") {
        for (const std::string backend : {"osmesa", "egl"}) {
            CAPTURE(backend);
            if (!usable_backend(backend, "lab 7's cutout.frag on " + backend)) continue;
            const Reports r = grade_lab(shaders_with({kCutoutKeepsTransparent}),
                                        "framebuffer-ops --backend " + backend);
            CHECK(r.graded.exit_code == 1);
            // Every checkpoint that fails draws with the cutout program.
            const std::set<std::string> failed = failed_checkpoints(r, "framebuffer-ops");
            CHECK(failed.count("discard_alpha_test") == 1);
            check_names(r, "07_framebuffer_ops/cutout.frag", failed);
            // Once, under the checkpoint's first failed check: its image check.
            const std::string summary = r.text.at("summary.txt");
            const size_t image =
                summary.find("framebuffer-ops/discard_alpha_test: image vs reference");
            REQUIRE(image != std::string::npos);
            const size_t next = summary.find("\n  framebuffer-ops/", image + 1);
            CHECK(summary.substr(image, next - image).find("in place of yours") !=
                  std::string::npos);
            // The lab's child, then one more that renders its failed checkpoints again.
            CHECK(r.child_starts == 2);
        }
    }
    SUBCASE("lab 10: silhouette.geom draws the back triangles' edges too") {
        const Reports r = grade_lab(shaders_with({kSilhouetteBackFaces}), "advanced-geometry");
        CHECK(r.graded.exit_code == 1);
        check_names(r, "10_advanced_geometry/silhouette.geom", {"silhouette_cube"});
    }
    SUBCASE("lab 6: shading.vert draws the sphere at half its size") {
        const Reports r = grade_lab(shaders_with({kShadingVertHalfSize}), "interpolation");
        CHECK(r.graded.exit_code == 1);
        const std::set<std::string> failed = failed_checkpoints(r, "interpolation");
        CHECK(failed.size() >= 6);
        check_names(r, "06_interpolation/shading.vert", failed);
    }
    SUBCASE("lab 9: advance.comp runs its step past the count (a portable check fails)") {
        const Reports r = grade_lab(shaders_with({kAdvanceNoBoundsCheck}), "buffers");
        CHECK(r.graded.exit_code == 1);
        const std::set<std::string> failed = failed_checkpoints(r, "buffers");
        CHECK(!failed.empty());
        check_names(r, "09_buffers/advance.comp", failed);
    }
}

TEST_CASE("which file: two files broken at once, and a student's copy, name none") {
    SUBCASE("lab 6: shading.vert and shading.frag, each wrong on every checkpoint of the sphere") {
        const Reports r = grade_lab(shaders_with({kShadingVertHalfSize, kShadingFragHalfColour}),
                                    "interpolation");
        check_names_none(r);
        // The search ran, and found no single file.
        CHECK(r.child_starts == 2);
    }
    SUBCASE("the solution: nothing to search, no second child") {
        const Reports r = grade_lab("", "framebuffer-ops");
        CHECK(r.graded.exit_code == 0);
        CHECK(named_files(r.text.at("summary.txt")).empty());
        CHECK(r.child_starts == 1);
    }
    SUBCASE("a student's copy: no solution to put in place, so no search") {
        const std::string release = fw::test::out_dir() + "/release";
        fs::remove_all(release);
        const fw::test::CommandResult made =
            fw::test::run_command(course() + " release --out " + fw::shell_quote(release));
        REQUIRE_MESSAGE(made.exit_code == 0, made.output);
        const Reports r = grade_lab(
            "LAB_ROOT=" + fw::shell_quote(release) + " " + shaders_with({kCutoutKeepsTransparent}),
            "framebuffer-ops");
        check_names_none(r);
        CHECK(r.child_starts == 1);
    }
}

TEST_CASE("which file: a mistake in C++ names no shader" * doctest::skip()) {
    // Lab 7's set_blend_mode with the factors of "over" swapped: the blended
    // checkpoints fail, and so do those of cutout.frag, which blend over; no
    // shader of the course's puts them right.
    const fs::path source = fw::test::source_dir(), tree = fs::path(fw::test::out_dir()) / "tree";
    tree_test::sync_tree(source, tree, grading::project_files(source.string()));
    apply(tree, {"labs/07_framebuffer_ops/fragment_state.cpp",
                 "glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);",
                 "glBlendFunc(GL_ONE_MINUS_SRC_ALPHA, GL_SRC_ALPHA);"});
    tree_test::build_tree(tree, "lab");
    const Reports r =
        grade_lab("FAKE_LAB_REAL_COPY=" + fw::shell_quote((tree / "build/bin/lab").string()),
                  "framebuffer-ops");
    check_names_none(r);
    CHECK(failed_checkpoints(r, "framebuffer-ops").count("discard_alpha_test") == 1);
    CHECK(r.child_starts == 2);
}
