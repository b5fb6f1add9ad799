// Each lab's banner against its code (docs/conventions.md, The banner, and The wrapper owns
// lifetimes; the lab shows the lesson), read from the files (no build, no GL):
// - every GL function (gl[A-Z]...) that the banner's "// GL:" field names is called in the
//   lab's own files (labs/NN_name/*.cpp, *.hpp) in code a student receives: outside the
//   `// BEGIN SOLUTION` ... `// END SOLUTION` blocks, or on a `// STUDENT: ` line inside one
//   (code or TODO), since `course release` keeps exactly those;
// - every glBindVertexArray and glDraw* call in those files, solution blocks included, is
//   named by the banner, so that a lab cannot draw without saying how.
// The "GL:" field runs from its line to the next "// Something:" field or the banner's end.
// The tree read is $LAB_ROOT when set, as for course (docs/contract.md, `course`), else the
// source tree.
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <string>
#include <vector>

#include "tests/support/test_support.hpp"

namespace fs = std::filesystem;

namespace {

struct Problem {
    std::string where;  // file:line
    std::string what;   // what is wrong and what to fix
};

// One line of a lab file, split as `course release` sees it.
struct Line {
    int number = 0;
    std::string released;  // code a student receives: comments and strings removed
    std::string student;   // the whole text of a STUDENT line, TODO included; else empty
    std::string solution;  // code inside a solution block, comments and strings removed
};

struct Banner {
    fs::path file;
    int gl_line = 0;                      // where the GL: field starts; 0 if there is none
    std::map<std::string, int> gl_names;  // each name the GL: field gives, and its line
};

struct LabFiles {
    std::string folder;  // labs/NN_name
    std::vector<Banner> banners;
    std::map<fs::path, std::vector<Line>> lines;  // file -> its lines
};

std::string trim(const std::string& s) {
    const auto b = s.find_first_not_of(" \t");
    const auto e = s.find_last_not_of(" \t\r");
    return b == std::string::npos ? "" : s.substr(b, e - b + 1);
}

std::vector<std::string> read_lines(const fs::path& path) {
    std::ifstream in(path);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

// `text` without its comments and the contents of its string and character literals; a
// block comment that does not end on the line leaves `in_comment` set for the next one.
std::string code_of(const std::string& text, bool& in_comment) {
    std::string code;
    for (std::size_t i = 0; i < text.size(); ++i) {
        if (in_comment) {
            if (text.compare(i, 2, "*/") == 0) {
                in_comment = false;
                ++i;
            }
            continue;
        }
        if (text.compare(i, 2, "//") == 0) break;
        if (text.compare(i, 2, "/*") == 0) {
            in_comment = true;
            ++i;
            continue;
        }
        const char c = text[i];
        if (c == '"' || c == '\'') {
            code += c;
            for (++i; i < text.size() && text[i] != c; ++i)
                if (text[i] == '\\') ++i;
            code += c;
            continue;
        }
        code += c;
    }
    return code;
}

// The file's lines as `course release` splits them (docs/conventions.md, Student parts).
std::vector<Line> split_lines(const std::vector<std::string>& text) {
    std::vector<Line> lines;
    bool in_block = false, in_comment = false;
    for (std::size_t i = 0; i < text.size(); ++i) {
        Line line;
        line.number = static_cast<int>(i) + 1;
        const std::string t = trim(text[i]);
        if (t == "// BEGIN SOLUTION" || t == "// END SOLUTION") {
            in_block = t == "// BEGIN SOLUTION";
        } else if (in_block && t.rfind("// STUDENT: ", 0) == 0) {
            line.student = t.substr(12);
            bool student_comment = false;
            line.released = code_of(line.student, student_comment);
        } else if (in_block) {
            line.solution = code_of(text[i], in_comment);
        } else {
            line.released = code_of(text[i], in_comment);
            // In the student's copy (`course release`) a STUDENT line is plain code
            // whose TODO, and the comment lines that go on with it, name the call to
            // write: they count as the STUDENT lines did.
            const std::size_t todo = text[i].find("// TODO:");
            if (todo != std::string::npos)
                line.student = text[i].substr(todo);
            else if (!lines.empty() && !lines.back().student.empty() && t.rfind("//", 0) == 0)
                line.student = t;
        }
        lines.push_back(line);
    }
    return lines;
}

const std::regex kGlName(R"(\bgl[A-Z]\w*)");
// A banner's first line, and a line that opens one of its fields ("// Student parts (marked
// TODO): ...").
const std::regex kBannerStart(R"(^// Lab \d+ `[^`]+`:)");
const std::regex kField(R"(^//\s*([A-Z][A-Za-z ()]*):(\s|$))");

// The banner of `text`, when its first line opens one.
bool parse_banner(const fs::path& file, const std::vector<std::string>& text, Banner& banner) {
    if (text.empty() || !std::regex_search(text[0], kBannerStart)) return false;
    banner.file = file;
    bool in_gl = false;
    for (std::size_t i = 0; i < text.size() && text[i].rfind("//", 0) == 0; ++i) {
        std::smatch field;
        if (std::regex_search(text[i], field, kField)) {
            in_gl = field[1] == "GL";
            if (in_gl) banner.gl_line = static_cast<int>(i) + 1;
        }
        if (!in_gl) continue;
        for (std::sregex_iterator it(text[i].begin(), text[i].end(), kGlName), end; it != end; ++it)
            banner.gl_names.emplace(it->str(), static_cast<int>(i) + 1);
    }
    return true;
}

std::string where(const fs::path& root, const fs::path& file, int line) {
    return fs::relative(file, root).generic_string() + ":" + std::to_string(line);
}

std::vector<LabFiles> read_labs(const fs::path& root) {
    std::vector<LabFiles> labs;
    std::set<fs::path> folders;
    for (const auto& entry : fs::directory_iterator(root / "labs"))
        if (entry.is_directory() &&
            std::regex_match(entry.path().filename().string(), std::regex(R"(\d\d_\w+)")))
            folders.insert(entry.path());
    for (const fs::path& folder : folders) {
        LabFiles lab;
        lab.folder = "labs/" + folder.filename().string();
        std::set<fs::path> files;
        for (const auto& entry : fs::directory_iterator(folder)) {
            const std::string ext = entry.path().extension().string();
            if (entry.is_regular_file() && (ext == ".cpp" || ext == ".hpp"))
                files.insert(entry.path());
        }
        for (const fs::path& file : files) {
            const std::vector<std::string> text = read_lines(file);
            Banner banner;
            if (parse_banner(file, text, banner)) lab.banners.push_back(banner);
            lab.lines[file] = split_lines(text);
        }
        labs.push_back(lab);
    }
    return labs;
}

// Whether some file of `lab` calls `name` in released code or names it on a STUDENT line.
bool student_sees_call(const LabFiles& lab, const std::string& name) {
    const std::regex call("\\b" + name + R"(\s*\()"), word("\\b" + name + "\\b");
    for (const auto& [file, lines] : lab.lines)
        for (const Line& line : lines)
            if (std::regex_search(line.released, call) || std::regex_search(line.student, word))
                return true;
    return false;
}

std::vector<Problem> check_lab(const fs::path& root, const LabFiles& lab, std::size_t& named) {
    std::vector<Problem> problems;
    if (lab.banners.empty()) {
        problems.push_back({lab.folder,
                            "no .cpp file of the lab opens with a banner (// Lab N `id`: ...); "
                            "give the file that holds the lab class one (docs/conventions.md, "
                            "The banner)"});
        return problems;
    }
    std::set<std::string> banner_names;
    for (const Banner& banner : lab.banners) {
        if (banner.gl_line == 0) {
            problems.push_back({where(root, banner.file, 1),
                                "the banner has no \"// GL:\" field; add one naming the GL "
                                "calls and GLSL features the lab uses"});
            continue;
        }
        for (const auto& [name, line] : banner.gl_names) {
            banner_names.insert(name);
            ++named;
            if (!student_sees_call(lab, name))
                problems.push_back(
                    {where(root, banner.file, line),
                     "the banner's GL: field names " + name + ", but no file of " + lab.folder +
                         " calls it outside a solution block or names it on a STUDENT line; "
                         "call it in the lab, or take it out of the banner (and say in words "
                         "what the framework does for the lab)"});
        }
    }
    const std::regex draw(R"(\b(glDraw\w*|glBindVertexArray)\s*\()");
    const Banner& first = lab.banners.front();
    for (const auto& [file, lines] : lab.lines)
        for (const Line& line : lines)
            for (const std::string* code : {&line.released, &line.solution})
                for (std::sregex_iterator it(code->begin(), code->end(), draw), end; it != end;
                     ++it) {
                    const std::string name = (*it)[1];
                    if (banner_names.count(name)) continue;
                    problems.push_back({where(root, file, line.number),
                                        "calls " + name + ", which the banner's GL: field (" +
                                            where(root, first.file, first.gl_line) +
                                            ") does not name; add " + name + " there"});
                }
    return problems;
}

std::vector<Problem> check_labs(const fs::path& root, std::size_t& labs, std::size_t& named) {
    std::vector<Problem> problems;
    for (const LabFiles& lab : read_labs(root)) {
        ++labs;
        for (Problem& p : check_lab(root, lab, named)) problems.push_back(std::move(p));
    }
    return problems;
}

fs::path tree() {
    const char* root = std::getenv("LAB_ROOT");
    return root && *root ? fs::path(root) : fs::path(fw::test::source_dir());
}

// A one-file lab in a fresh folder under the test's output directory.
fs::path lab_with(const std::string& name, const std::string& source) {
    const fs::path root = fs::path(fw::test::out_dir()) / name;
    fs::remove_all(root);
    fs::create_directories(root / "labs/07_demo");
    std::ofstream(root / "labs/07_demo/demo.cpp") << source;
    return root;
}

std::vector<Problem> check_one(const fs::path& root) {
    std::size_t labs = 0, named = 0;
    std::vector<Problem> problems = check_labs(root, labs, named);
    for (const Problem& p : problems) MESSAGE(p.where << ": " << p.what);
    return problems;
}

const char* const kBanner =
    "// Lab 7 `demo`: a demonstration.\n"
    "//\n"
    "// Teaches: nothing.\n"
    "// GL: glBindVertexArray,\n"
    "// glDrawArrays.\n"
    "// Student parts (marked TODO): draw() below.\n";

}  // namespace

TEST_CASE("every lab's banner names the GL calls the lab makes, and only those") {
    const fs::path root = tree();
    std::size_t labs = 0, named = 0;
    const std::vector<Problem> problems = check_labs(root, labs, named);
    MESSAGE(labs << " labs in " << root.string() << ", " << named << " GL calls named");
    CHECK(labs > 0);
    for (const Problem& p : problems) FAIL_CHECK(p.where << ": " << p.what);
}

TEST_CASE("a banner's call must be made where a student sees it") {
    const std::string draw = "void draw() {\n    glBindVertexArray(1);\n";
    SUBCASE("in released code: no problem") {
        CHECK(check_one(lab_with("released", std::string(kBanner) + draw +
                                                 "    glDrawArrays(GL_TRIANGLES, 0, 3);\n}\n"))
                  .empty());
    }
    SUBCASE("named on a STUDENT line: no problem") {
        CHECK(check_one(lab_with("student", std::string(kBanner) + draw +
                                                "    // BEGIN SOLUTION\n"
                                                "    // STUDENT: // TODO: glDrawArrays\n"
                                                "    glDrawArrays(GL_TRIANGLES, 0, 3);\n"
                                                "    // END SOLUTION\n}\n"))
                  .empty());
    }
    SUBCASE("named in a TODO of the student's copy, where the STUDENT line was: no problem") {
        CHECK(
            check_one(lab_with("released_todo",
                               std::string(kBanner) + draw +
                                   "    (void)0;  // TODO: glDrawArrays(GL_TRIANGLES, 0, 3)\n}\n"))
                .empty());
    }
    SUBCASE("only in a solution block, or only in a comment: named but not made") {
        const std::vector<Problem> problems =
            check_one(lab_with("hidden", std::string(kBanner) + draw +
                                             "    // glDrawArrays(GL_TRIANGLES, 0, 3);\n"
                                             "    // BEGIN SOLUTION\n"
                                             "    // STUDENT: // TODO: draw the triangle\n"
                                             "    glDrawArrays(GL_TRIANGLES, 0, 3);\n"
                                             "    // END SOLUTION\n}\n"));
        REQUIRE(problems.size() == 1);
        CHECK(problems[0].where == "labs/07_demo/demo.cpp:5");
        CHECK(problems[0].what.find("names glDrawArrays") != std::string::npos);
    }
}

TEST_CASE("a draw the banner does not name is reported where it is made") {
    const std::vector<Problem> problems = check_one(lab_with(
        "unnamed", std::string(kBanner) + "void draw() {\n    glBindVertexArray(1);\n"
                                          "    glDrawArrays(GL_TRIANGLES, 0, 3);\n"
                                          "    glDrawElements(GL_TRIANGLES, 3, GL_UNSIGNED_INT, "
                                          "nullptr);\n}\n"));
    REQUIRE(problems.size() == 1);
    CHECK(problems[0].where == "labs/07_demo/demo.cpp:10");
    CHECK(problems[0].what.find("calls glDrawElements") != std::string::npos);
}
