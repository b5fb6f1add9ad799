// `course release` end to end, on this repository:
// - the student tree holds no marker, no hidden checkpoint and none of the
//   staff's files (tests, references, CI), builds, runs every lab without a
//   crash, scores below full marks, and its own self-checks fail there and
//   pass with the solution's files put in; a part still as released is
//   said as such there (its starting.json), and not once written;
// - every solution block is graded before the deadline: with that block
//   alone in its student version, some check of a visible checkpoint that
//   passes with the solution fails (hidden checkpoints test the same code
//   with other parameters);
// - every part is checkable in the sheet's order: from a lab's starting
//   code, writing its parts one by one in the order of the sheet's "What you
//   implement" list raises the lab's visible score at every part.
// Both build trees of their own (minutes); CMake registers them as separate
// tests (tests/grading/CMakeLists.txt).
#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>

#include "framework/checkpoints.hpp"
#include "framework/text.hpp"
#include "grading/release/release.hpp"
#include "tests/grading/grade_support.hpp"
#include "tests/grading/tree_support.hpp"
#include "tests/support/test_support.hpp"

namespace fs = std::filesystem;
using fw::shell_quote;
using fw::test::read_text;
using fw::test::write_text;
using nlohmann::json;
using namespace tree_test;

namespace {

// A marker line as a person would spot it, whatever its spacing.
const std::regex kMarker(R"(^\s*//\s*(BEGIN SOLUTION|END SOLUTION|STUDENT:))");

// The staff's `text` as a student who wrote it would have it: no marker lines.
std::string without_markers(const std::string& text) {
    std::istringstream lines(text);
    std::string out;
    for (std::string line; std::getline(lines, line);)
        if (!std::regex_search(line, kMarker)) out += line + "\n";
    return out;
}

// `text` with the definition of `function` (from its line to the next
// unindented "}") replaced by that of `with`.
std::string with_function(const std::string& text, const std::string& with,
                          const std::string& function) {
    const auto span = [&](const std::string& t) {
        const size_t name = t.find(" " + function + "(");
        REQUIRE(name != std::string::npos);
        const size_t begin = t.rfind('\n', name) + 1, end = t.find("\n}\n", name);
        REQUIRE(end != std::string::npos);
        return std::make_pair(begin, end + 3);
    };
    const auto [b, e] = span(text);
    const auto [wb, we] = span(with);
    return text.substr(0, b) + with.substr(wb, we - wb) + text.substr(e);
}

// What a grade says of a checkpoint: its checks' outputs in results.json.
std::string said_of(const Grade& g, const std::string& lab, const std::string& checkpoint) {
    std::string words;
    for (const auto& [name, e] : g.entries)
        if (name.rfind(lab + " / " + checkpoint + " / ", 0) == 0) words += e.output + "\n";
    return words;
}

bool has(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

}  // namespace

TEST_CASE("release: the student tree has no solutions, builds, runs and scores below full marks") {
    const fs::path source = fw::test::source_dir(), dir = fw::test::out_dir();
    fw::test::remove_when_passed(dir.string());
    const fs::path student = dir / "student";
    fs::remove_all(student);
    auto r = run("env -u LAB_ROOT " + shell_quote(fw::test::bin_dir() + "/course") +
                 " release --out " + shell_quote(student.string()));
    MESSAGE(r.output);
    REQUIRE(r.exit_code == 0);

    // No marker line left in any C++ or GLSL file.
    size_t code_files = 0;
    for (const auto& e : fs::recursive_directory_iterator(student)) {
        if (!e.is_regular_file() || !grading::is_marked_source(e.path().string())) continue;
        ++code_files;
        std::istringstream lines(read_text(e.path()));
        std::string line;
        for (int n = 1; std::getline(lines, line); ++n)
            CHECK_MESSAGE(!std::regex_search(line, kMarker),
                          "marker left in " << e.path().string() << ":" << n << ": " << line);
    }
    CHECK(code_files > 0);

    // The student's code is formatted as the course's is (the release turns
    // STUDENT lines into code, which must fit too): the format check passes on
    // the student tree, or skips (77) where clang-format is missing and not
    // required.
    const auto format = run("bash " + shell_quote((source / "scripts/check-format.sh").string()) +
                            " " + shell_quote(student.string()));
    CHECK_MESSAGE((format.exit_code == 0 || format.exit_code == 77), format.output);

    // Each lab's checkpoints: exactly the visible ones; hidden references absent.
    for (const std::string& lab : lab_dirs(source)) {
        fw::CheckpointFile solution =
            fw::read_checkpoint_file((source / "labs" / lab / "checkpoints.json").string());
        fw::CheckpointFile released =
            fw::read_checkpoint_file((student / "labs" / lab / "checkpoints.json").string());
        std::vector<std::string> expected, observed;
        for (const auto& cp : solution.checkpoints) {
            fs::path ref = fs::path("labs") / lab / "reference" / (cp.name + ".png");
            if (cp.visibility == "visible") expected.push_back(cp.name);
            if (cp.visibility == "hidden")
                CHECK_MESSAGE(!fs::exists(student / ref),
                              ref << " of a hidden checkpoint was released");
            else if (fs::exists(source / ref))
                CHECK_MESSAGE(fs::exists(student / ref),
                              ref << " of a visible checkpoint is missing");
        }
        for (const auto& cp : released.checkpoints) observed.push_back(cp.name);
        INFO(lab << ": expected the visible checkpoints, in order");
        CHECK(observed == expected);
        // The known mistakes' frames (CHECKPOINT.json, CHECKPOINT.N.png):
        // those of visible checkpoints only, all of them.
        const fs::path frames = fs::path("labs") / lab / "reference" / "mistakes";
        if (!fs::is_directory(source / frames)) continue;
        for (const auto& e : fs::directory_iterator(source / frames)) {
            const std::string name = e.path().filename().string();
            const std::string checkpoint = name.substr(0, name.find('.'));
            const bool visible = std::count(expected.begin(), expected.end(), checkpoint) > 0;
            CHECK_MESSAGE(fs::exists(student / frames / name) == visible,
                          (frames / name).string()
                              << (visible ? " of a visible checkpoint is missing"
                                          : " of a hidden checkpoint was released"));
        }
    }

    // The staff's own files stay out; the README is the student's.
    for (const char* staff : {"tests", "bench", ".ci", "Dockerfile", "scripts/test.sh"})
        CHECK_MESSAGE(!fs::exists(student / staff), staff << " was released");
    for (const std::string& lab : lab_dirs(student)) {
        CHECK_MESSAGE(!fs::exists(student / "labs" / lab / "tests"), lab << "'s tests released");
        const fs::path refs = student / "labs" / lab / "grading";
        if (fs::exists(refs))
            for (const auto& e : fs::directory_iterator(refs))
                CHECK_MESSAGE(e.path().extension() != ".cpp", e.path()
                                                                  << " (a reference) released");
    }
    CHECK(read_text(student / "README.md") == read_text(source / grading::kStudentReadme));

    build_tree(student, "lab course");
    // Its own tests: one self-check per lab, each red on the starting code.
    const auto self = run("ctest --test-dir " + shell_quote((student / "build").string()) +
                              " -L self-check -j " + jobs(),
                          /*may_fail=*/true);
    MESSAGE(self.output);
    CHECK(self.exit_code != 0);
    for (const std::string& lab : lab_dirs(student)) {
        const std::string id =
            fw::read_checkpoint_file((student / "labs" / lab / "checkpoints.json").string()).lab;
        CHECK_MESSAGE(self.output.find(" - check." + id + " (Failed)") != std::string::npos,
                      "the self-check of " << id << " is missing or passes on the starting code");
    }
    const std::string bin = (student / "build" / "bin").string();
    Grade g = grade(bin + "/course", bin + "/lab", "", dir / "grade");
    MESSAGE(g.output);
    CHECK(g.exit_code == 1);
    REQUIRE(g.results.is_object());
    for (const std::string& lab : lab_dirs(student)) {
        // summary.txt names a lab by its checkpoints file's "lab".
        std::string id =
            fw::read_checkpoint_file((student / "labs" / lab / "checkpoints.json").string()).lab;
        INFO("lab " << id << " (labs/" << lab << ") in summary.txt");
        CHECK(g.status.count(id) == 1);
        CHECK(g.status[id] == "ok");
    }
    // The hidden checkpoints it lacks are counted, in the terminal and the report.
    CHECK(g.output.find("On submission the autograder adds ") != std::string::npos);
    CHECK(read_text(dir / "grade" / "index.html").find("On submission the autograder adds ") !=
          std::string::npos);
    const double score = g.results["score"], max_score = g.results["extra_data"]["max_score"];
    MESSAGE("student version: " << score << " of " << max_score << " points");
    CHECK(max_score > 0);
    CHECK(score < max_score);

    // A part still as released is said as such there too (each lab's
    // grading/starting.json), and the guesses a missing part's frame is no
    // evidence of are not: in lab 7 with every part unwritten, sorting_sorted
    // names part 1; with every part but 4 written, part 4. Part 4 begun
    // (wrong), sorting_order still fails and names no part; written, it passes.
    const std::string part1 =
        "Part 1 (`set_blend_mode()` in labs/07_framebuffer_ops/fragment_state.cpp) still has its "
        "starting code; this checkpoint needs it.";
    const std::string part4 =
        "Part 4 (`back_to_front()` in labs/07_framebuffer_ops/blending.cpp) still has its "
        "starting code; this checkpoint needs it.";
    const std::string lab7 = "framebuffer-ops",
                      state = "labs/07_framebuffer_ops/fragment_state.cpp",
                      blending = "labs/07_framebuffer_ops/blending.cpp";
    const auto no_guess = [](const std::string& words) {
        for (const char* guess : {"treats", "Your frame is the one"})
            CHECK_MESSAGE(!has(words, guess), words);
    };
    const auto grade_lab7 = [&](const std::string& name) {
        REQUIRE(rebuild_tree(student, "lab"));
        return grade(bin + "/course", bin + "/lab", lab7, dir / name);
    };
    std::string words = said_of(g, lab7, "sorting_sorted");
    CHECK_MESSAGE(has(words, part1), words);
    no_guess(words);
    write_text(student / state, without_markers(read_text(source / state)));
    Grade part = grade_lab7("grade-part4");
    for (const std::string checkpoint : {"sorting_sorted", "sorting_order"}) {
        words = said_of(part, lab7, checkpoint);
        CHECK_MESSAGE(has(words, part4), words);
        no_guess(words);
    }
    const std::string released = read_text(student / blending);
    std::string begun = released;
    const size_t back = begun.find("    return order;", begun.find(" back_to_front("));
    REQUIRE(back != std::string::npos);
    begun.insert(back, "    std::reverse(order.begin(), order.end());\n");
    write_text(student / blending, begun);
    part = grade_lab7("grade-part4-begun");
    CHECK(std::any_of(part.failed.begin(), part.failed.end(), [&](const std::string& name) {
        return name.rfind(lab7 + " / sorting_order / ", 0) == 0;
    }));
    words = said_of(part, lab7, "sorting_order");
    CHECK_MESSAGE(!has(words, "still has its starting code"), words);
    write_text(
        student / blending,
        with_function(released, without_markers(read_text(source / blending)), "back_to_front"));
    part = grade_lab7("grade-part4-written");
    for (const std::string checkpoint : {"sorting_sorted", "sorting_order"})
        for (const auto& [name, e] : part.entries)
            if (name.rfind(lab7 + " / " + checkpoint + " / ", 0) == 0)
                CHECK_MESSAGE(part.passed.count(name) == 1, name << ": " << e.output);

    // Its self-checks are green on the solution: the staff's versions of the files students
    // edit, put in their place.
    size_t solved = 0;
    for (const std::string& file : grading::project_files(source.string()))
        if (grading::is_marked_source(file) && !grading::is_staff_only(file) &&
            fs::is_regular_file(source / file) &&
            !grading::solution_blocks(read_text(source / file), file).empty()) {
            write_text(student / file, read_text(source / file));
            ++solved;
        }
    CHECK(solved > 0);
    REQUIRE(rebuild_tree(student, "lab course"));
    const auto solution = run("ctest --test-dir " + shell_quote((student / "build").string()) +
                                  " -L self-check -j " + jobs(),
                              /*may_fail=*/true);
    MESSAGE(solution.output);
    CHECK_MESSAGE(solution.exit_code == 0, "the self-checks fail on the solution");
}

namespace {

struct Block {
    std::string file;  // relative to the repository
    size_t index = 0;  // in the file
    int line = 0;      // of its BEGIN marker
};

// The name of the function a block sits in: the identifier before the
// first "(" of the nearest line above it that starts in column 0 and is no
// comment or directive; empty at file scope (a shader's declarations).
std::string enclosing_function(const std::string& text, int begin_line) {
    std::vector<std::string> lines;
    std::istringstream in(text);
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    static const std::regex name(R"((\w+)\s*\()");
    for (int i = begin_line - 2; i >= 0; --i) {
        const std::string& t = lines[static_cast<size_t>(i)];
        if (t.empty() || std::isspace(static_cast<unsigned char>(t[0])) || t.rfind("//", 0) == 0 ||
            t[0] == '#' || t[0] == '}')
            continue;
        std::smatch m;
        if (std::regex_search(t, m, name)) return m[1];
        return "";
    }
    return "";
}

// The numbered parts of a lab sheet's "## What you implement" section, each
// part's text.
std::vector<std::string> sheet_parts(const std::string& sheet) {
    std::vector<std::string> parts;
    const size_t at = sheet.find("\n## What you implement\n");
    if (at == std::string::npos) return parts;
    const size_t end = sheet.find("\n## ", at + 1);
    std::istringstream in(sheet.substr(at + 1, end == std::string::npos ? end : end - at - 1));
    static const std::regex item(R"(^\d+\. )");
    for (std::string line; std::getline(in, line);) {
        if (std::regex_search(line, item))
            parts.push_back(line);
        else if (!parts.empty())
            parts.back() += "\n" + line;
    }
    return parts;
}

// The part of `parts` that a block of `file` in `function` belongs to: the
// first that names both the file and the function, else the first naming
// the file, else the first naming the function; -1 when none does.
int part_of(const std::vector<std::string>& parts, const std::string& file,
            const std::string& function) {
    const std::string base = fs::path(file).filename().string();
    const std::regex word("\\b" + (function.empty() ? std::string("$^") : function) + "\\b");
    int by_file = -1, by_name = -1;
    for (size_t k = 0; k < parts.size(); ++k) {
        const bool f = parts[k].find(base) != std::string::npos;
        const bool n = std::regex_search(parts[k], word);
        if (f && n) return static_cast<int>(k);
        if (f && by_file < 0) by_file = static_cast<int>(k);
        if (n && by_name < 0) by_name = static_cast<int>(k);
    }
    return by_file >= 0 ? by_file : by_name;
}

// `text` with every block of `file` not in `kept` in its student version.
std::string with_blocks(const std::string& text, const std::string& file,
                        const std::set<size_t>& kept) {
    std::string out = text;
    const size_t n = grading::solution_blocks(text, file).size();
    for (size_t i = n; i-- > 0;)  // from the last: earlier blocks keep their index
        if (!kept.count(i)) out = grading::student_text_of_block(out, file, i);
    return out;
}

// The visible points of a grade.
double visible_score(const Grade& g) {
    double sum = 0.0;
    for (const auto& [name, e] : g.entries)
        if (e.visibility == "visible") sum += e.score;
    return sum;
}

// The checkpoints of `lab_dir` that list the part placed at the function
// holding block `b` (checkpoints.json's "parts"), yet score full marks in `g`,
// the grade of that block alone in its student version: where its function
// still has its starting code, the grader would tell a student that such a
// checkpoint needs it, which is false there.
std::vector<std::string> listed_but_passing(const fs::path& source, const std::string& lab_dir,
                                            const Block& b, const Grade& g) {
    const fw::CheckpointFile file =
        fw::read_checkpoint_file((source / "labs" / lab_dir / "checkpoints.json").string());
    const std::string function = enclosing_function(read_text(source / b.file), b.line);
    std::set<int> parts;
    for (const json& p : file.parts)
        if (p.value("file", "") == b.file && p.value("function", "") == function)
            parts.insert(p.value("part", 0));
    std::vector<std::string> out;
    for (const fw::Checkpoint& cp : file.checkpoints) {
        const bool lists = std::any_of(cp.parts.begin(), cp.parts.end(),
                                       [&](int n) { return parts.count(n) > 0; });
        // Its entries: "LAB / CHECKPOINT", or one "LAB / CHECKPOINT / CHECK" a check.
        const std::string name = file.lab + " / " + cp.name;
        size_t graded = 0, failed = 0;
        for (const auto& [entry, e] : g.entries)
            if (entry == name || entry.rfind(name + " / ", 0) == 0) {
                ++graded;
                failed += g.failed.count(entry);
            }
        if (lists && graded > 0 && failed == 0) out.push_back(cp.name);
    }
    return out;
}

}  // namespace

TEST_CASE("release: every solution block is graded" * doctest::skip()) {
    const fs::path source = fw::test::source_dir(), dir = fw::test::out_dir();
    fw::test::remove_when_passed(dir.string());
    const std::string course = fw::test::bin_dir() + "/course", lab = fw::test::bin_dir() + "/lab";
    const std::vector<std::string> files = grading::project_files(source.string());
    const std::vector<std::string> labs = lab_dirs(source);  // those with checkpoints
    std::vector<Block> blocks;
    for (const std::string& file : files)
        if (grading::is_marked_source(file) && fs::is_regular_file(source / file)) {
            auto found = grading::solution_blocks(read_text(source / file), file);
            // A block under tests/ is no student part: it keeps course data
            // that quotes the solution (the mistake suite's list) out of the
            // release.
            if (fs::path(file).begin()->string() == "tests") {
                if (!found.empty())
                    MESSAGE(file << ": " << found.size() << " blocks of course data, not graded");
                continue;
            }
            for (size_t i = 0; i < found.size(); ++i)
                blocks.push_back({file, i, found[i].begin_line});
        }
    MESSAGE(blocks.size() << " solution blocks in " << labs.size() << " labs");
    if (blocks.empty()) return;

    // What the solution passes: a block is graded when one of these, in a
    // visible checkpoint, fails without it.
    Grade solution = grade(course, lab, "", dir / "solution");
    REQUIRE(solution.results.is_object());
    MESSAGE("the solution passes " << solution.passed.size() << " of "
                                   << grade_test::checks_of(solution.results).size() << " checks");

    // Shaders need no rebuild: the built `lab` reads them from LAB_SHADER_DIR.
    const fs::path shaders = dir / "shaders", tree = dir / "tree";
    fs::remove_all(shaders);
    fs::copy(source / "shaders", shaders, fs::copy_options::recursive);
    // C++ blocks: one copy of the tree, rebuilt incrementally for each block.
    bool cpp = std::any_of(blocks.begin(), blocks.end(),
                           [](const Block& b) { return !is_shader(b.file); });
    if (cpp) {
        sync_tree(source, tree, files);
        build_tree(tree, "lab");
    }

    // Block b alone in its student version, graded on its lab (or all labs):
    // how many checks that pass with the solution fail now, and how many of
    // those are in visible checkpoints (the ones that count).
    auto try_block = [&](const Block& b, const std::string& lab_dir) -> std::string {
        if (!lab_dir.empty() && !std::count(labs.begin(), labs.end(), lab_dir))
            return "NOT GRADED: labs/" + lab_dir + " has no checkpoints.json";
        const bool shader = is_shader(b.file);
        const std::string original = read_text(source / b.file);
        const fs::path target =
            shader ? shaders / fs::path(b.file).lexically_relative("shaders") : tree / b.file;
        write_text(target, grading::student_text_of_block(original, b.file, b.index));
        std::string result;
        if (!shader && !rebuild_tree(tree, "lab")) {
            result = "the student version does not build";
        } else {
            std::string env = shader ? "LAB_SHADER_DIR=" + shell_quote(shaders.string()) : "";
            std::string child = shader ? lab : (tree / "build" / "bin" / "lab").string();
            Grade g = grade(course, child, lab_dir, dir / "block", env);
            size_t caught = 0;
            for (const std::string& name : g.failed) caught += solution.passed.count(name);
            const std::vector<Loss> visible = visible_losses(solution, g);
            if (g.exit_code == 2 || !g.results.is_object())
                result = "grading failed (exit " + std::to_string(g.exit_code) + ")";
            else if (caught == 0)
                result = "NOT GRADED: every check the solution passes still passes";
            else if (visible.empty())
                result = "NOT GRADED BEFORE THE DEADLINE: only hidden checks fail (" +
                         std::to_string(caught) + ")";
            else
                result = std::to_string(visible.size()) + " visible checks fail (" +
                         std::to_string(caught) + " in all)";
            for (const auto& [id, status] : g.status)
                if (status != "ok") result += " [" + id + ": " + status + "]";
            if (!lab_dir.empty())
                for (const std::string& cp : listed_but_passing(source, lab_dir, b, g))
                    result += " [LISTS ITS PART, YET PASSES: " + cp + "]";
        }
        write_text(target, original);
        return result;
    };

    auto total = std::chrono::steady_clock::now();
    std::string report;
    bool all_graded = true;
    for (const Block& b : blocks) {
        auto start = std::chrono::steady_clock::now();
        const std::string where = b.file + ":" + std::to_string(b.line), lab_dir = lab_of(b.file);
        const std::string result = try_block(b, lab_dir);
        char line[1024];
        std::snprintf(line, sizeof line, "%-48s %-18s %s (%.1f s)\n", where.c_str(),
                      lab_dir.empty() ? "all labs" : lab_dir.c_str(), result.c_str(),
                      seconds_since(start));
        std::printf("%s", line);
        std::fflush(stdout);
        report += line;
        const bool graded = result.find("visible checks fail") != std::string::npos;
        CHECK_MESSAGE(graded, where << ": " << result);
        CHECK_MESSAGE(result.find("LISTS ITS PART") == std::string::npos,
                      where << ": " << result
                            << " (a checkpoint lists a part only where each of its functions, "
                               "alone at its starting code, makes it fail)");
        all_graded = all_graded && graded;
    }
    MESSAGE("solution blocks, each alone in its student version:\n"
            << report << blocks.size() << " blocks in " << seconds_since(total) << " s"
            << std::string(all_graded ? ""
                                      : "; each block not caught needs a check of a visible "
                                        "checkpoint that fails without it (or is not needed)"));

    // The sheet's order: per lab, its parts written one by one from the
    // starting code; each part must raise the visible score.
    std::string order;
    for (const std::string& lab_dir : labs) {
        const std::vector<std::string> parts =
            sheet_parts(read_text(source / "labs" / lab_dir / "README.md"));
        std::map<int, std::vector<Block>> by_part;
        for (const Block& b : blocks) {
            if (lab_of(b.file) != lab_dir) continue;
            const std::string function = enclosing_function(read_text(source / b.file), b.line);
            const int part = part_of(parts, b.file, function);
            by_part[part].push_back(b);
        }
        if (by_part.empty()) continue;
        if (by_part.size() > 1)
            CHECK_MESSAGE(!by_part.count(-1),
                          lab_dir << "'s sheet names no part for " << by_part[-1].front().file
                                  << ":" << by_part[-1].front().line << " (What you implement)");
        // Writes the lab's files with the blocks of `done` parts in their
        // solution; returns whether `lab` built.
        auto write_lab = [&](const std::set<int>& done) {
            std::map<std::string, std::set<size_t>> kept;
            std::set<std::string> lab_files;
            for (const auto& [part, list] : by_part)
                for (const Block& b : list) {
                    lab_files.insert(b.file);
                    if (done.count(part)) kept[b.file].insert(b.index);
                }
            bool rebuild = false;
            for (const std::string& file : lab_files) {
                const fs::path target = is_shader(file)
                                            ? shaders / fs::path(file).lexically_relative("shaders")
                                            : tree / file;
                write_text(target, with_blocks(read_text(source / file), file, kept[file]));
                rebuild = rebuild || !is_shader(file);
            }
            return !rebuild || rebuild_tree(tree, "lab");
        };
        auto grade_lab = [&]() {
            return grade(course, cpp ? (tree / "build" / "bin" / "lab").string() : lab, lab_dir,
                         dir / "order", "LAB_SHADER_DIR=" + shell_quote(shaders.string()));
        };
        std::set<int> done;
        REQUIRE(write_lab(done));
        double before = visible_score(grade_lab());
        order += lab_dir + ": starting code " + fw::number_text(before, 6) + " visible points";
        for (const auto& [part, list] : by_part) {
            done.insert(part);
            REQUIRE(write_lab(done));
            const double after = visible_score(grade_lab());
            order += std::string(", part ") +
                     (part < 0 ? "(the only one)" : std::to_string(part + 1)) + " " +
                     fw::number_text(after, 6);
            CHECK_MESSAGE(after > before,
                          lab_dir << ": part " << part + 1 << " (" << list.front().file << ":"
                                  << list.front().line << ") leaves the visible score at "
                                  << fw::number_text(after, 6)
                                  << "; a check of a visible checkpoint must "
                                     "pass once it is written in the sheet's order");
            before = after;
        }
        order += "\n";
        // The solution again, for the next lab; a file already holding it is
        // left as it is, so that the lab built from it is not older than its
        // sources (course grade refuses a lab older than a file it is built from).
        bool rewrote_cpp = false;
        for (const auto& [part, list] : by_part)
            for (const Block& b : list) {
                const fs::path target =
                    is_shader(b.file) ? shaders / fs::path(b.file).lexically_relative("shaders")
                                      : tree / b.file;
                const std::string original = read_text(source / b.file);
                if (read_text(target) == original) continue;
                write_text(target, original);
                rewrote_cpp = rewrote_cpp || !is_shader(b.file);
            }
        if (rewrote_cpp) REQUIRE(rebuild_tree(tree, "lab"));
    }
    if (cpp) REQUIRE(rebuild_tree(tree, "lab"));
    MESSAGE("each lab's parts written in the sheet's order, its visible score:\n" << order);
}
