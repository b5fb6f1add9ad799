// `course release` end to end, on this repository:
// - the student tree holds no marker and no hidden checkpoint, builds, runs
//   every lab without a crash, and scores below full marks;
// - every solution block is graded: with that block alone in its student
//   version, some check that passes with the solution fails.
// Both build trees of their own (minutes); CMake registers them as separate
// tests (tests/grading/CMakeLists.txt).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <sstream>
#include <thread>

#include "framework/checkpoints.hpp"
#include "framework/text.hpp"
#include "grading/commands.hpp"
#include "grading/release.hpp"
#include "tests/grading/grade_support.hpp"
#include "tests/support/test_support.hpp"

namespace fs = std::filesystem;
using fw::test::run_command;

// release_command() is not called here; the tree is passed explicitly.
std::string grading::source_root() { return fw::test::source_dir(); }

namespace {

using fw::shell_quote;
using fw::test::read_text;
using fw::test::write_text;

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Runs `command`; on failure (exit status other than 0, and than 1 when
// `may_fail`: `course grade` when a check fails) shows its output's tail.
fw::test::CommandResult run(const std::string& command, bool may_fail = false) {
    auto start = std::chrono::steady_clock::now();
    fw::test::CommandResult r = run_command(command);
    std::printf("[%5.1f s] exit %d: %s\n", seconds_since(start), r.exit_code, command.c_str());
    std::fflush(stdout);
    if (r.exit_code != 0 && !(may_fail && r.exit_code == 1))
        MESSAGE("output (tail):\n"
                << r.output.substr(r.output.size() > 6000 ? r.output.size() - 6000 : 0));
    return r;
}

std::string jobs() { return std::to_string(std::max(1u, std::thread::hardware_concurrency())); }

// Configures and builds `targets` of the tree at `source` into source/build,
// warnings as errors (the student version must build cleanly too), through
// ccache when it is installed.
void build_tree(const fs::path& source, const std::string& targets) {
    const std::string build = (source / "build").string();
    std::string configure = "cmake -S " + shell_quote(source.string()) + " -B " +
                            shell_quote(build) + " -DCMAKE_BUILD_TYPE=Release -DLAB_WERROR=ON";
    if (run_command("command -v ccache").exit_code == 0)
        configure += " -DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache";
    REQUIRE_MESSAGE(run(configure).exit_code == 0, "configuring " << source);
    REQUIRE_MESSAGE(
        run("cmake --build " + shell_quote(build) + " -j" + jobs() + " --target " + targets)
                .exit_code == 0,
        "building " << targets << " in " << source);
}

struct Grade {
    int exit_code = -1;
    std::string output;
    nlohmann::json results;                     // results.json
    std::map<std::string, std::string> status;  // lab -> its status in summary.txt
    std::set<std::string> passed, failed;       // names of the checks
};

// `course grade` with `lab` as the child, in an environment without LAB_ROOT
// and LAB_SHADER_DIR but with `env` (VAR=value ...).
Grade grade(const std::string& course, const std::string& lab, const std::string& labs,
            const fs::path& out, const std::string& env = "") {
    fs::remove_all(out);
    Grade g;
    auto r = run("env -u LAB_ROOT -u LAB_SHADER_DIR " + env + " " + shell_quote(course) +
                     " grade " + labs + " --lab " + shell_quote(lab) + " --out " +
                     shell_quote(out.string()) + " --jobs " + jobs(),
                 /*may_fail=*/true);
    g.exit_code = r.exit_code;
    g.output = r.output;
    if (!fs::exists(out / "results.json")) return g;
    g.results = nlohmann::json::parse(read_text(out / "results.json"));
    for (const auto& t : grade_test::checks_of(g.results))
        (t["status"] == "passed" ? g.passed : g.failed).insert(t["name"].get<std::string>());
    for (const std::vector<std::string>& w :
         grade_test::summary_rows(read_text(out / "summary.txt")))
        if (w.size() >= 5) g.status[w[0]] = fw::join(std::vector(w.begin() + 3, w.end() - 1), " ");
    return g;
}

// The labs with a checkpoints file, by folder.
std::vector<std::string> lab_dirs(const fs::path& root) {
    std::vector<std::string> dirs;
    for (const auto& e : fs::directory_iterator(root / "labs"))
        if (fs::exists(e.path() / "checkpoints.json")) dirs.push_back(e.path().filename().string());
    std::sort(dirs.begin(), dirs.end());
    return dirs;
}

// A marker line as a person would spot it, whatever its spacing.
const std::regex kMarker(R"(^\s*//\s*(BEGIN SOLUTION|END SOLUTION|STUDENT:))");

}  // namespace

TEST_CASE("release: the student tree has no solutions, builds, runs and scores below full marks") {
    const fs::path source = fw::test::source_dir(), dir = fw::test::out_dir();
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
    }

    build_tree(student, "lab course");
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
    const double score = g.results["score"], max_score = g.results["max_score"];
    MESSAGE("student version: " << score << " of " << max_score << " points");
    CHECK(max_score > 0);
    CHECK(score < max_score);
}

namespace {

struct Block {
    std::string file;  // relative to the repository
    size_t index = 0;  // in the file
    int line = 0;      // of its BEGIN marker
};

// The lab folder a file belongs to (labs/NN_name/..., shaders/NN_name/...);
// empty for shared code (framework/), which every lab uses.
std::string lab_of(const std::string& file) {
    fs::path p(file);
    auto it = p.begin();
    if (it == p.end() || (*it != "labs" && *it != "shaders") || ++it == p.end()) return "";
    return it->string();
}

bool is_shader(const std::string& file) { return fs::path(file).begin()->string() == "shaders"; }

// Makes `copy` hold the project's files as in `source`, rewriting only what
// differs so that its build stays incremental between runs.
void sync_tree(const fs::path& source, const fs::path& copy,
               const std::vector<std::string>& files) {
    std::set<std::string> wanted(files.begin(), files.end());
    if (fs::exists(copy))
        for (auto it = fs::recursive_directory_iterator(copy);
             it != fs::recursive_directory_iterator(); ++it) {
            std::string rel = fs::relative(it->path(), copy).string();
            if (rel == "build")
                it.disable_recursion_pending();
            else if (it->is_regular_file() && !wanted.count(rel))
                fs::remove(it->path());
        }
    for (const std::string& rel : files) {
        if (!fs::is_regular_file(source / rel)) continue;
        std::string text = read_text(source / rel);
        if (fs::exists(copy / rel) && read_text(copy / rel) == text) continue;
        fs::create_directories((copy / rel).parent_path());
        fs::copy_file(source / rel, copy / rel, fs::copy_options::overwrite_existing);
    }
}

}  // namespace

TEST_CASE("release: every solution block is graded" * doctest::skip()) {
    const fs::path source = fw::test::source_dir(), dir = fw::test::out_dir();
    const std::string course = fw::test::bin_dir() + "/course", lab = fw::test::bin_dir() + "/lab";
    const std::vector<std::string> files = grading::project_files(source.string());
    const std::vector<std::string> labs = lab_dirs(source);  // those with checkpoints
    std::vector<Block> blocks;
    for (const std::string& file : files)
        if (grading::is_marked_source(file) && fs::is_regular_file(source / file)) {
            auto found = grading::solution_blocks(read_text(source / file), file);
            for (size_t i = 0; i < found.size(); ++i)
                blocks.push_back({file, i, found[i].begin_line});
        }
    MESSAGE(blocks.size() << " solution blocks in " << labs.size() << " labs");
    if (blocks.empty()) return;

    // What the solution passes: a block is graded when one of these fails without it.
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
    // how many checks that pass with the solution fail now.
    auto try_block = [&](const Block& b, const std::string& lab_dir) -> std::string {
        if (!lab_dir.empty() && !std::count(labs.begin(), labs.end(), lab_dir))
            return "NOT GRADED: labs/" + lab_dir + " has no checkpoints.json";
        const bool shader = is_shader(b.file);
        const std::string original = read_text(source / b.file);
        const fs::path target =
            shader ? shaders / fs::path(b.file).lexically_relative("shaders") : tree / b.file;
        write_text(target, grading::student_text_of_block(original, b.file, b.index));
        std::string result;
        if (!shader && run("cmake --build " + shell_quote((tree / "build").string()) + " -j" +
                           jobs() + " --target lab")
                               .exit_code != 0) {
            result = "the student version does not build";
        } else {
            std::string env = shader ? "LAB_SHADER_DIR=" + shell_quote(shaders.string()) : "";
            std::string child = shader ? lab : (tree / "build" / "bin" / "lab").string();
            Grade g = grade(course, child, lab_dir, dir / "block", env);
            size_t caught = 0;
            for (const std::string& name : g.failed) caught += solution.passed.count(name);
            if (g.exit_code == 2 || !g.results.is_object())
                result = "grading failed (exit " + std::to_string(g.exit_code) + ")";
            else if (caught == 0)
                result = "NOT GRADED: every check the solution passes still passes";
            else
                result = std::to_string(caught) + " checks fail";
            for (const auto& [id, status] : g.status)
                if (status != "ok") result += " [" + id + ": " + status + "]";
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
        const bool graded = result.find("checks fail") != std::string::npos;
        CHECK_MESSAGE(graded, where << ": " << result);
        all_graded = all_graded && graded;
    }
    MESSAGE("solution blocks, each alone in its student version:\n"
            << report << blocks.size() << " blocks in " << seconds_since(total) << " s"
            << std::string(all_graded ? ""
                                      : "; each block not caught needs a check that fails "
                                        "without it (or is not needed)"));
}
