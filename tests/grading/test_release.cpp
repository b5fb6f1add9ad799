// `course release`, the text transformations (grading/release/release.hpp) and a
// small tree written by release_tree(). No GL, no git: fast.
#include <sys/stat.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "framework/checkpoints.hpp"
#include "framework/text.hpp"
#include "grading/release/release.hpp"
#include "tests/support/test_support.hpp"

namespace fs = std::filesystem;
using fw::test::check_mentions;
using fw::test::thrown;

namespace {

void check_text(const std::string& observed, const std::string& expected) {
    INFO("expected:\n" << expected << "\nobserved:\n" << observed);
    CHECK(observed == expected);
}

const std::string kSolution =
    "void set_depth_test(bool on) {\n"
    "    // BEGIN SOLUTION\n"
    "    // STUDENT: (void)on;  // TODO: glEnable(GL_DEPTH_TEST) when on\n"
    "    if (on)\n"
    "        glEnable(GL_DEPTH_TEST);\n"
    "    else\n"
    "        glDisable(GL_DEPTH_TEST);\n"
    "    // END SOLUTION\n"
    "}\n";
const std::string kStudent =
    "void set_depth_test(bool on) {\n"
    "    (void)on;  // TODO: glEnable(GL_DEPTH_TEST) when on\n"
    "}\n";

}  // namespace

TEST_CASE("release: a solution block becomes its STUDENT lines") {
    check_text(grading::student_text(kSolution, "a.cpp"), kStudent);
    auto blocks = grading::solution_blocks(kSolution, "a.cpp");
    REQUIRE(blocks.size() == 1);
    CHECK(blocks[0].begin_line == 2);
    CHECK(blocks[0].end_line == 8);
}

TEST_CASE(
    "release: STUDENT lines keep their indentation; one space after the colon is the marker's") {
    const std::string text =
        "int f(int x) {\n"
        "  // BEGIN SOLUTION\n"
        "  return x * 2;\n"
        "  // STUDENT: if (x > 0) {\n"
        "  // STUDENT:     return 0;  // TODO\n"
        "  // STUDENT:\n"
        "\t// STUDENT: }\n"
        "  // STUDENT:return 1;\n"
        "  // END SOLUTION\n"
        "}";
    check_text(grading::student_text(text, "f.hpp"),
               "int f(int x) {\n"
               "  if (x > 0) {\n"
               "      return 0;  // TODO\n"
               "\n"
               "\t}\n"
               "  return 1;\n"
               "}");
}

TEST_CASE("release: GLSL blocks, several in one file") {
    const std::string text =
        "void main() {\n"
        "    // BEGIN SOLUTION\n"
        "    // STUDENT: vec3 position = vec3(0.0);\n"
        "    vec3 position = a_position;\n"
        "    // END SOLUTION\n"
        "    gl_Position = vec4(position, 1.0);\n"
        "    // BEGIN SOLUTION\n"
        "    v_color = a_color;\n"
        "    // END SOLUTION\n"
        "}\n";
    check_text(grading::student_text(text, "x.vert"),
               "void main() {\n"
               "    vec3 position = vec3(0.0);\n"
               "    gl_Position = vec4(position, 1.0);\n"
               "}\n");
    CHECK(grading::solution_blocks(text, "x.vert").size() == 2);
    // One block at a time: the other keeps its markers and code.
    check_text(grading::student_text_of_block(text, "x.vert", 1),
               "void main() {\n"
               "    // BEGIN SOLUTION\n"
               "    // STUDENT: vec3 position = vec3(0.0);\n"
               "    vec3 position = a_position;\n"
               "    // END SOLUTION\n"
               "    gl_Position = vec4(position, 1.0);\n"
               "}\n");
}

TEST_CASE("release: CRLF line endings are kept") {
    auto crlf = [](std::string s) {
        std::string out;
        for (char c : s) out += c == '\n' ? std::string("\r\n") : std::string(1, c);
        return out;
    };
    check_text(grading::student_text(crlf(kSolution), "a.cpp"), crlf(kStudent));
}

TEST_CASE("release: text without markers comes back unchanged") {
    for (const std::string& text :
         {std::string(), std::string("no newline at the end"),
          std::string("// Student parts (between BEGIN SOLUTION and END SOLUTION): f()\n"),
          std::string("int x = 1;  // STUDENT: after code is no marker\r\n\n\n"),
          std::string("const char* s = \"// BEGIN SOLUTION\";\n")}) {
        CHECK(grading::solution_blocks(text, "a.cpp").empty());
        check_text(grading::student_text(text, "a.cpp"), text);
    }
}

TEST_CASE("release: unbalanced or misspelt markers name the file and line") {
    auto error = [](const std::string& text) {
        return thrown([&] { grading::student_text(text, "labs/00_x/x.cpp"); });
    };
    check_mentions(error("a\n// BEGIN SOLUTION\nb\n  // BEGIN SOLUTION\n// END SOLUTION\n"),
                   {"labs/00_x/x.cpp:4", "line 2", "nest"});
    check_mentions(error("a\n\n    // END SOLUTION\n"), {"labs/00_x/x.cpp:3", "without a BEGIN"});
    check_mentions(error("a\n// BEGIN SOLUTION\nb\n"), {"labs/00_x/x.cpp:2", "without an END"});
    check_mentions(error("// BEGIN SOLUTION\n// END SOLUTION\n// BEGIN SOLUTION\n"),
                   {"labs/00_x/x.cpp:3"});
    check_mentions(error("x\n  // STUDENT: y = 1;\n"),
                   {"labs/00_x/x.cpp:2", "outside a solution block"});
    check_mentions(error("//BEGIN SOLUTION\n// END SOLUTION\n"), {"labs/00_x/x.cpp:1", "exactly"});
    check_mentions(error("// BEGIN SOLUTION\n// END SOLUTION part 1\n"),
                   {"labs/00_x/x.cpp:2", "exactly"});
    check_mentions(error("// BEGIN SOLUTION\n//STUDENT: x\n// END SOLUTION\n"),
                   {"labs/00_x/x.cpp:2"});
    // solution_blocks checks alike.
    check_mentions(thrown([] { grading::solution_blocks("// END SOLUTION\n", "s.frag"); }),
                   {"s.frag:1"});
}

TEST_CASE("release: which files carry markers") {
    for (const char* yes : {"a.cpp", "x/b.hpp", "c.h", "s.vert", "s.frag", "s.geom", "s.tesc",
                            "s.tese", "s.comp", "s.glsl"})
        CHECK_MESSAGE(grading::is_marked_source(yes), yes);
    for (const char* no :
         {"README.md", "checkpoints.json", "CMakeLists.txt", "run.sh", "cpp", "a.png"})
        CHECK_MESSAGE(!grading::is_marked_source(no), no);
}

TEST_CASE("release: the solution's records, the sheet's state words and the seed are staff files") {
    // The course's seed: with it, a student could draw the autograder's cases.
    for (const char* staff : {"labs/07_x/reference/blend_over.record.json",
                              "labs/07_x/grading/state_words.json", "labs/course_seed.json"})
        CHECK_MESSAGE(grading::is_staff_only(staff), staff);
    for (const char* student : {"labs/07_x/reference/blend_over.png",
                                "labs/07_x/reference/mistakes/blend_over.json", "labs/07_x/x.cpp"})
        CHECK_MESSAGE(!grading::is_staff_only(student), student);
}

namespace {
const std::string kCheckpoints =
    "// Header comment.\n"
    "{\"lab\": \"x\",\n"
    " \"checkpoints\": [\n"
    "  // about a\n"
    "  {\"name\": \"a\", \"visibility\": \"visible\", \"params\": {\"s\": \"[a, b]\"}},\n"
    "  // about h1, which is hidden\n"
    "  {\"name\": \"h1\", \"visibility\": \"hidden\",\n"
    "   \"checks\": [{\"kind\": \"image\", \"points\": 1}]},\n"
    "\n"
    "  // group comment, not attached\n"
    "\n"
    "  {\"name\": \"b\", \"checks\": []},\n"
    "  {\"name\": \"h2\", \"visibility\": \"hidden\"}\n"
    "]}\n";
}  // namespace

TEST_CASE("release: hidden checkpoints are cut from the text, with their comments") {
    auto v = grading::drop_hidden_checkpoints(kCheckpoints, "labs/x/checkpoints.json");
    CHECK(v.dropped == std::vector<std::string>{"h1", "h2"});
    CHECK(v.hidden_points == 1);
    check_text(
        v.text,
        "// Header comment.\n"
        "{\"hidden\": {\"checkpoints\": 2, \"points\": 1},\n"
        " \"lab\": \"x\",\n"
        " \"checkpoints\": [\n"
        "  // about a\n"
        "  {\"name\": \"a\", \"visibility\": \"visible\", \"params\": {\"s\": \"[a, b]\"}},\n"
        "  {\"name\": \"b\", \"checks\": []}\n"
        "]}\n");
}

TEST_CASE("release: checkpoints files with nothing hidden, or everything") {
    const std::string visible =
        "{\"lab\": \"x\", \"checkpoints\": [{\"name\": \"a\"}, {\"name\": \"b\"}]}";
    auto v = grading::drop_hidden_checkpoints(visible, "c.json");
    CHECK(v.dropped.empty());
    check_text(v.text, visible);

    const std::string all =
        "{\"lab\": \"x\", \"checkpoints\": [{\"name\": \"h\", \"visibility\": \"hidden\"},"
        " /* why */ {\"name\": \"g\", \"visibility\": \"hidden\"}]}";
    v = grading::drop_hidden_checkpoints(all, "c.json");
    CHECK(v.dropped == std::vector<std::string>{"h", "g"});
    check_text(
        v.text,
        "{\"hidden\": {\"checkpoints\": 2, \"points\": 0},\n \"lab\": \"x\", \"checkpoints\": []}");
    // What the student's copy reads back.
    const fs::path file = fs::path(fw::test::out_dir()) / "hidden" / "labs/00_x/checkpoints.json";
    fs::create_directories(file.parent_path());
    std::ofstream(file) << grading::drop_hidden_checkpoints(kCheckpoints, "c.json").text;
    const fw::CheckpointFile read = fw::read_checkpoint_file(file.string());
    CHECK(read.hidden_checkpoints == 2);
    CHECK(read.hidden_points == 1);
    std::ofstream(file)
        << "{\"hidden\": {\"checkpoints\": -1, \"points\": 1}, \"checkpoints\": []}";
    check_mentions(thrown([&] { fw::read_checkpoint_file(file.string()); }),
                   {file.string(), "\"hidden\" must be"});

    check_mentions(thrown([] { grading::drop_hidden_checkpoints("{\"lab\": \"x\"}", "c.json"); }),
                   {"c.json", "\"checkpoints\" array"});
    check_mentions(
        thrown([] { grading::drop_hidden_checkpoints("{\"checkpoints\": [}", "c.json"); }),
        {"c.json", "not valid JSON"});
}

namespace {
void write(const fs::path& path, const std::string& text, fs::perms mode = fs::perms(0644)) {
    fs::create_directories(path.parent_path());
    std::ofstream(path, std::ios::binary) << text;
    fs::permissions(path, mode);
}
std::string read(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}
}  // namespace

TEST_CASE("release: a tree outside git: files, modes, hidden references, build folders") {
    fs::path dir = fw::test::out_dir(), src = dir / "src", out = dir / "out";
    fs::remove_all(src);
    fs::remove_all(out);
    write(src / "labs/00_x/x.cpp", kSolution);
    write(src / "shaders/00_x/x.frag", "void main() {}\n");
    write(src / "scripts/run.sh", "#!/bin/sh\necho hi\n", fs::perms(0755));
    write(src / "labs/00_x/checkpoints.json", kCheckpoints);
    for (const char* name : {"a", "b", "h1", "h2"})
        write(src / "labs/00_x/reference" / (name + std::string(".png")), name);
    write(src / "README.md", "Between `// BEGIN SOLUTION` and `// END SOLUTION`.\n");
    write(src / grading::kStudentReadme, "# The labs, for students\n");
    for (const char* skipped :
         {"build/lab.o", "build-asan/bin/lab", ".cache/clangd/x", "labs/00_x/.git/HEAD"})
        write(src / skipped, "x");
    // The staff's own: tests, benchmarks, CI, unit-check references.
    const char* const staff[] = {"tests/t.cpp", "bench/b.cpp", ".ci/run", "labs/00_x/tests/t.cpp",
                                 "labs/00_x/grading/units.cpp"};
    for (const char* file : staff) write(src / file, "int staff;\n");

    grading::ReleaseSummary s = grading::release_tree(src.string(), out.string());
    CHECK(s.files == 7);
    CHECK(s.staff_only == 7);  // the five above, README.md and the student README's source
    for (const char* file : staff) CHECK_MESSAGE(!fs::exists(out / file), file);
    CHECK(!fs::exists(out / grading::kStudentReadme));
    check_text(read(out / "labs/00_x/x.cpp"), kStudent);
    check_text(read(out / "shaders/00_x/x.frag"), "void main() {}\n");
    check_text(read(out / "README.md"), "# The labs, for students\n");
    CHECK(fs::status(out / "scripts/run.sh").permissions() == fs::perms(0755));
    CHECK(fs::status(out / "labs/00_x/x.cpp").permissions() == fs::perms(0644));
    CHECK(grading::drop_hidden_checkpoints(kCheckpoints, "c").text ==
          read(out / "labs/00_x/checkpoints.json"));
    for (const char* name : {"a", "b"})
        CHECK(fs::exists(out / "labs/00_x/reference" / (name + std::string(".png"))));
    for (const char* name : {"h1", "h2"})
        CHECK(!fs::exists(out / "labs/00_x/reference" / (name + std::string(".png"))));
    for (const char* skipped : {"build", "build-asan", ".cache", "labs/00_x/.git"})
        CHECK_MESSAGE(!fs::exists(out / skipped), skipped);
    REQUIRE(s.blocks.size() == 1);
    CHECK(s.blocks[0] == std::pair<std::string, int>("labs/00_x/x.cpp", 1));
    CHECK(s.references_left_out.size() == 2);

    // The output must be new or empty.
    check_mentions(thrown([&] { grading::release_tree(src.string(), out.string()); }),
                   {out.string(), "not empty"});
    // An output that cannot be created is named.
    const fs::path blocked = src / "README.md" / "out";
    check_mentions(thrown([&] { grading::release_tree(src.string(), blocked.string()); }),
                   {blocked.string(), "cannot create"});
    // A marker error anywhere: nothing is written, and every faulty file is named.
    write(src / "framework/y.hpp", "// END SOLUTION\n");
    write(src / "shaders/00_x/z.vert", "\n// BEGIN SOLUTION\n");
    fs::path out2 = dir / "out2";
    fs::remove_all(out2);
    check_mentions(thrown([&] { grading::release_tree(src.string(), out2.string()); }),
                   {"framework/y.hpp:1", "shaders/00_x/z.vert:2", "not written"});
    CHECK(!fs::exists(out2));
    // An unreadable source tree is named.
    check_mentions(
        thrown([&] { grading::release_tree((dir / "nowhere").string(), out2.string()); }),
        {(dir / "nowhere").string()});
}

TEST_CASE("release: in a git checkout, only tracked files; untracked ones are named") {
    const fs::path dir = fs::path(fw::test::out_dir()) / "git", src = dir / "src",
                   out = dir / "out";
    fs::remove_all(dir);
    write(src / "labs/00_x/x.cpp", kSolution);
    write(src / "notes.txt", "a staff member's notes\n");
    const std::string git = "git -C " + fw::shell_quote(src.string()) + " ";
    REQUIRE(std::system((git + "init -q && " + git + "add labs/00_x/x.cpp").c_str()) == 0);
    write(src / "labs/00_x/new.cpp", "int not_yet_committed;\n");
    const grading::ReleaseSummary s = grading::release_tree(src.string(), out.string());
    CHECK(s.files == 1);
    CHECK(fs::exists(out / "labs/00_x/x.cpp"));
    CHECK(!fs::exists(out / "notes.txt"));
    CHECK(!fs::exists(out / "labs/00_x/new.cpp"));
    CHECK(s.untracked == std::vector<std::string>{"labs/00_x/new.cpp", "notes.txt"});
}

// This repository's own markers, checked in milliseconds rather than by the
// end-to-end release test; and no solution line quoted where `course release`
// copies text as is (READMEs, data files).
TEST_CASE("release: this repository's markers are well formed and its docs quote no solution") {
    const fs::path root = fw::test::source_dir();
    std::vector<std::pair<std::string, std::string>> solution_lines;  // file:line, text
    std::vector<std::string> docs;
    for (const std::string& file : grading::project_files(root.string())) {
        const std::string ext = fs::path(file).extension().string();
        if (ext == ".md" || ext == ".txt" || ext == ".json" || ext == ".html") docs.push_back(file);
        if (!grading::is_marked_source(file) || !fs::is_regular_file(root / file)) continue;
        const std::string text = read(root / file);
        std::vector<grading::SolutionBlock> blocks;
        try {
            blocks = grading::solution_blocks(text, file);
        } catch (const fw::Error& e) {
            FAIL_CHECK(e.what());
        }
        std::vector<std::string> lines;
        std::istringstream in(text);
        for (std::string line; std::getline(in, line);) lines.push_back(line);
        for (const auto& b : blocks)
            for (int n = b.begin_line + 1; n < b.end_line; ++n) {
                std::string t = lines[n - 1];
                t.erase(0, t.find_first_not_of(" \t"));
                // Long code lines only: short ones ("return P;") occur anywhere;
                // and a path the mistake list gives (`"file": "labs/..."`,
                // which the known mistakes' signatures repeat) is no solution.
                if (t.size() >= 30 && t.rfind("//", 0) != 0 && t.rfind("\"file\": ", 0) != 0)
                    solution_lines.push_back({file + ":" + std::to_string(n), t});
            }
    }
    MESSAGE(solution_lines.size() << " long solution lines, " << docs.size() << " documents");
    for (const std::string& doc : docs) {
        const std::string text = read(root / doc);
        for (const auto& [where, line] : solution_lines)
            CHECK_MESSAGE(text.find(line) == std::string::npos,
                          doc << " quotes the solution line " << where << ": " << line);
    }
}
