// The autograder the gradescope tests share (gradescope_support.hpp).
#include "tests/grading/gradescope_support.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <vector>

#include "framework/checkpoints.hpp"
#include "framework/text.hpp"
#include "grading/release/release.hpp"
#include "tests/grading/grade_support.hpp"
#include "tests/support/test_support.hpp"

namespace gradescope_test {

using fw::shell_quote;
using fw::test::read_text;
using fw::test::write_text;

namespace {

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string tail(const std::string& text, size_t bytes = 6000) {
    return text.substr(text.size() > bytes ? text.size() - bytes : 0);
}

Expected expected_from_data(const fs::path& source) {
    Expected e;
    std::vector<fs::path> dirs;
    for (const auto& entry : fs::directory_iterator(source / "labs"))
        if (fs::exists(entry.path() / "checkpoints.json")) dirs.push_back(entry.path());
    std::sort(dirs.begin(), dirs.end());
    for (const fs::path& dir : dirs) {
        fw::CheckpointFile f = fw::read_checkpoint_file((dir / "checkpoints.json").string());
        if (dir.filename().string().rfind("00_", 0) == 0) {
            e.victim = f.lab;
            e.victim_dir = dir.filename().string();
        }
        for (const fw::Checkpoint& cp : f.checkpoints) {
            e.checks[f.lab + " / " + cp.name] += static_cast<int>(cp.checks.size());
            if (cp.visibility == "hidden") e.hidden.insert(f.lab + " / " + cp.name);
            for (const json& check : cp.checks) e.points += check["points"].get<double>();
        }
    }
    return e;
}

std::string environment(const Autograder& ag, const std::string& extra = "") {
    return "env -u LAB_ROOT -u LAB_SHADER_DIR -u CI AUTOGRADER_ROOT=" +
           shell_quote(ag.root.string()) + " AUTOGRADER_USER=" + ag.user + " COURSE_SEED=1 " +
           extra + " ";
}

std::string set_up(Autograder& ag) {
    // One folder per build whichever test case comes first, so that re-runs
    // find their ccache entries (CCACHE_BASEDIR below). It is outside the
    // build, in /tmp: like /autograder, every user must be able to enter it,
    // and a clone may sit below a folder only root can enter.
    ag.dir = fs::path("/tmp") /
             ("course-gradescope-" + std::to_string(std::hash<std::string>{}(fw::test::bin_dir())));
    fs::create_directories(ag.dir);
    fw::test::remove_when_passed(ag.dir.string());
    fs::permissions(ag.dir, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                                fs::perms::others_read | fs::perms::others_exec);
    ag.root = ag.dir / "root";
    ag.user = "nobody";
    fs::remove_all(ag.root);
    fs::create_directories(ag.root / "results");
    const fs::path source = ag.root / "source";
    auto start = std::chrono::steady_clock::now();
    auto r =
        fw::test::run_command("env -u LAB_ROOT " + shell_quote(fw::test::bin_dir() + "/course") +
                              " gradescope --out " + shell_quote(source.string()));
    MESSAGE("course gradescope (exit " << r.exit_code << "):\n" << r.output);
    if (r.exit_code != 0) return "course gradescope failed";

    std::istringstream list(read_text(source / "student_files.txt"));
    for (std::string line; std::getline(list, line);)
        if (!line.empty()) ag.student_files.push_back(line);
    if (ag.student_files.empty()) return "student_files.txt is empty";
    ag.expected = expected_from_data(source);
    if (ag.expected.victim.empty()) return "no labs/00_*/checkpoints.json: lab 0 is the victim";
    // Before any submission replaces them; the submissions are made from these.
    for (const std::string& rel : ag.student_files) ag.solution_text[rel] = read_text(source / rel);
    for (const char* script : {"setup.sh", "run_autograder"})
        ag.scripts[script] = read_text(source / "grading/platforms/gradescope" / script);
    // Gradescope copies run_autograder to /autograder and runs it from there.
    fs::copy_file(source / "run_autograder", ag.root / "run_autograder");

    // Packages are present here.
    r = fw::test::run_command(environment(ag, "SKIP_APT=1 " + ccache_setup_env(source)) + "bash " +
                              shell_quote((source / "setup.sh").string()));
    std::printf("[%5.1f s] setup.sh: exit %d\n", seconds_since(start), r.exit_code);
    if (r.exit_code != 0) {
        MESSAGE("setup.sh output (tail):\n" << tail(r.output));
        return "setup.sh failed";
    }
    return "";
}

}  // namespace

std::string ccache_setup_env(const fs::path& source) {
    if (fw::test::run_command("command -v ccache").exit_code != 0) return "";
    // The sloppiness lets ccache cache the labs' files compiled with the
    // gradescope preset's precompiled header.
    return "CMAKE_CXX_COMPILER_LAUNCHER=ccache CMAKE_C_COMPILER_LAUNCHER=ccache "
           "CCACHE_SLOPPINESS=pch_defines,time_macros CCACHE_NOHASHDIR=1 CCACHE_BASEDIR=" +
           shell_quote(source.string()) + " ";
}

std::string lab_of(const json& test) {
    const std::string name = test.value("name", "");
    return name.substr(0, name.find(" / "));
}

// Builds the submission folder from `files` (path in the submission -> text)
// and runs run_autograder on it.
Run submit(const Autograder& ag, const std::string& what,
           const std::map<std::string, std::string>& files, const std::string& env) {
    fs::remove_all(ag.root / "submission");
    fs::create_directories(ag.root / "submission");
    for (const auto& [rel, text] : files) write_text(ag.root / "submission" / rel, text);
    Run run;
    auto start = std::chrono::steady_clock::now();
    auto r = fw::test::run_command(environment(ag, env) + "bash " +
                                   shell_quote((ag.root / "run_autograder").string()));
    run.seconds = seconds_since(start);
    run.exit_code = r.exit_code;
    run.output = r.output;
    std::printf("[%5.1f s] run_autograder, %s: exit %d\n", run.seconds, what.c_str(), r.exit_code);
    std::fflush(stdout);
    const fs::path results = ag.root / "results" / "results.json";
    if (fs::exists(results)) {
        const std::string text = read_text(results);
        run.results_bytes = text.size();
        run.results = json::parse(text, nullptr, false);
    }
    const fs::path summary = ag.root / "results" / "grade" / "summary.txt";
    for (const std::vector<std::string>& w : grade_test::summary_rows(read_text(summary)))
        if (w.size() >= 5) run.lab_seconds[w[0]] = std::atof(w.back().c_str());
    if (r.exit_code != 0 || !run.results.is_object())
        MESSAGE("run_autograder output (tail):\n" << tail(r.output));
    return run;
}

Autograder& autograder() {
    static Autograder ag;
    static bool tried = false;
    if (!tried) {
        tried = true;
        ag.failure = set_up(ag);
    }
    REQUIRE_MESSAGE(ag.failure.empty(), "the autograder could not be set up: " << ag.failure);
    return ag;
}

// results.json is complete: a test per checkpoint of every lab, each with
// its fields and its checks, the points adding up to the data files' total.
void check_complete(const Run& run, const Expected& e) {
    REQUIRE_MESSAGE(run.exit_code == 0, "run_autograder must exit 0 whatever the submission");
    REQUIRE_MESSAGE(run.results.is_object(), "results.json is missing or not JSON");
    const json& r = run.results;
    REQUIRE(r.contains("tests"));
    double score = 0;
    for (const json& t : r["tests"]) {
        for (const char* field : {"name", "score", "max_score", "status", "output", "output_format",
                                  "visibility", "extra_data"})
            CHECK_MESSAGE(t.contains(field), "test " << t.dump() << " has no " << field);
        score += t.value("score", 0.0);
        // A hidden checkpoint's test shows after the due date (run_autograder's
        // default): Gradescope's "hidden" would hide the student's total too.
        const std::string name = t.value("name", "");
        CHECK_MESSAGE(
            t.value("visibility", "") == (e.hidden.count(name) ? "after_due_date" : "visible"),
            name);
    }
    std::map<std::string, int> seen;
    for (const json& c : grade_test::checks_of(r)) {
        const std::string name = c.value("name", "");
        seen[name.substr(0, name.find(" / ", name.find(" / ") + 3))] += 1;
    }
    CHECK_MESSAGE(seen == e.checks,
                  "Expected the checks of the data files, Observed those of results.json");
    CHECK(!r.contains("max_score"));  // Gradescope's specification has none at the top
    CHECK(r.value("extra_data", json::object()).value("max_score", -1.0) ==
          doctest::Approx(e.points));
    CHECK(r.value("score", -1.0) == doctest::Approx(score));
}

// The labs other than `victim` score test by test as the solution does.
void check_others_unaffected(Autograder& ag, const Run& run) {
    const Run& solution = solution_run(ag);
    std::map<std::string, std::string> want;
    for (const json& t : solution.results["tests"])
        if (lab_of(t) != ag.expected.victim) want[t["name"]] = t["status"];
    size_t compared = 0;
    for (const json& t : run.results["tests"]) {
        if (lab_of(t) == ag.expected.victim) continue;
        ++compared;
        CHECK_MESSAGE(t["status"].get<std::string>() == want[t["name"]],
                      t["name"] << ": Expected " << want[t["name"]]
                                << " (as with the solution), Observed " << t["status"] << "\n"
                                << t.value("output", ""));
    }
    CHECK(compared == want.size());
}

// Every check of the victim lab failed for `reason`; the others as with the solution.
void check_victim_failed(Autograder& ag, const Run& run, const std::string& reason) {
    check_complete(run, ag.expected);
    double score = 0, max = 0;
    for (const json& t : run.results["tests"]) {
        if (lab_of(t) != ag.expected.victim) continue;
        score += t.value("score", 0.0);
        max += t.value("max_score", 0.0);
        const std::string output = grade_test::unescape_markup(t.value("output", ""));
        CHECK_MESSAGE(output.find(reason) != std::string::npos,
                      t["name"] << ": Expected an output naming \"" << reason << "\", Observed:\n"
                                << output);
    }
    MESSAGE(ag.expected.victim << ": " << score << " of " << max << " points");
    CHECK(max > 0);
    CHECK(score < max);
    check_others_unaffected(ag, run);
}

// The student files of lab 0 with the given suffix (".cpp" or a shader's).
std::string victim_file(const Autograder& ag, const std::string& top, bool shader) {
    for (const std::string& rel : ag.student_files) {
        const bool is_shader = fs::path(rel).extension() != ".cpp";
        if (rel.rfind(top + "/" + ag.expected.victim_dir + "/", 0) == 0 && is_shader == shader)
            return rel;
    }
    FAIL("lab " << ag.expected.victim_dir << " has no student " << (shader ? "shader" : "C++")
                << " file in student_files.txt");
    return "";
}

// The solution's student files, at their paths, with `code` added to the
// first solution block of `file`: after its first line, or before its last.
std::map<std::string, std::string> hostile(const Autograder& ag, const std::string& file,
                                           const std::string& code, bool at_end,
                                           const std::string& includes) {
    std::map<std::string, std::string> files = ag.solution_text;
    const std::string text = files[file];
    const auto blocks = grading::solution_blocks(text, file);
    REQUIRE_MESSAGE(!blocks.empty(), file << " has no solution block");
    const int line = at_end ? blocks[0].end_line - 1 : blocks[0].begin_line;  // insert after it
    std::istringstream in(text);
    std::string out = includes, l;
    for (int n = 1; std::getline(in, l); ++n) {
        out += l + "\n";
        if (n == line) out += code + "\n";
    }
    files[file] = out;
    return files;
}

namespace {

std::map<std::string, std::string> changed(std::map<std::string, std::string> files,
                                           const std::string& file, const std::string& find,
                                           const std::string& replace) {
    REQUIRE_MESSAGE(files.count(file) == 1, file << " is not a student file");
    std::string& text = files[file];
    const size_t at = text.find(find);
    REQUIRE_MESSAGE(at != std::string::npos, file << " has no '" << find << "'");
    REQUIRE_MESSAGE(text.find(find, at + 1) == std::string::npos,
                    file << " has '" << find << "' more than once");
    text.replace(at, find.size(), replace);
    return files;
}

}  // namespace

std::map<std::string, std::string> shader_mistake(std::map<std::string, std::string> files) {
    return changed(std::move(files), kIsolationShader,
                   "if (u_alpha_test && alpha < u_cutoff) discard;",
                   "if (u_alpha_test && alpha > u_cutoff) discard;");
}

std::map<std::string, std::string> cpp_mistake(std::map<std::string, std::string> files) {
    return changed(std::move(files), "labs/07_framebuffer_ops/fragment_state.cpp",
                   "glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);",
                   "glBlendFunc(GL_ONE_MINUS_SRC_ALPHA, GL_SRC_ALPHA);");
}

size_t isolation_mentions(const std::string& text) {
    size_t mentions = 0;
    for (size_t at = text.find("in place of yours"); at != std::string::npos;
         at = text.find("in place of yours", at + 1))
        ++mentions;
    return mentions;
}

std::string isolation_sentence(const std::string& file) {
    return "The frame is right with the course's `" + fs::path(file).filename().string() +
           "` in place of yours: the mistake is in " + file + ".";
}

const char* const kHostileLog =
    R"(printf 'pipeline.cpp:3:5: error: "quoted" \\back\\slash\ttab \001\002 \033[31mred\033[0m )"
    R"(\377 end of log\n'
exit 1
)";

const char* const kBuilds = R"(mkdir -p bin && printf '#!/bin/sh\nexit 0\n' >bin/lab
chmod +x bin/lab
)";

void check_log_kept(const std::string& output) {
    fw::test::check_mentions(output, {"\"quoted\"", "\\back\\slash", "red", "end of log"});
    CHECK(output.find('\x01') == std::string::npos);
    CHECK(output.find('\x1b') == std::string::npos);
}

fs::path make_root(const std::string& name, const std::string& lab_script) {
    const fs::path root = fs::path(fw::test::out_dir()) / name, source = root / "source";
    fs::remove_all(root);
    grade_test::make_tree(source.string(), false);
    write_text(source / "student_files.txt", "labs/00_pipeline/pipeline.cpp\n");
    write_text(source / "labs/00_pipeline/pipeline.cpp", "// the solution\n");
    write_text(source / "student_versions/labs/00_pipeline/pipeline.cpp", "// student version\n");
    write_text(root / "project/CMakeLists.txt",
               "cmake_minimum_required(VERSION 3.16)\nproject(fake NONE)\n"
               "add_custom_target(lab COMMAND sh ${CMAKE_SOURCE_DIR}/lab.sh)\n");
    write_text(root / "project/lab.sh", lab_script);
    const auto r = fw::test::run_command("cmake -S " + shell_quote((root / "project").string()) +
                                         " -B " + shell_quote((source / "build").string()));
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    fs::create_directories(source / "course-bin");
    fs::create_symlink(grade_test::course(), source / "course-bin" / "course");
    write_text(root / "submission/pipeline.cpp", "// submitted\n");
    return root;
}

const Run& solution_run(Autograder& ag) {
    if (!ag.solution) {
        // Flat uploads: each file by its name at the top when no other student
        // file shares it, else under a folder; run_autograder finds both.
        std::map<std::string, int> names;
        for (const std::string& rel : ag.student_files) names[fs::path(rel).filename()] += 1;
        std::map<std::string, std::string> files;
        for (const std::string& rel : ag.student_files) {
            const std::string name = fs::path(rel).filename();
            files[names[name] == 1 ? name : "my-work/" + rel] = ag.solution_text.at(rel);
        }
        ag.solution = submit(ag, "the solution", files);
    }
    return *ag.solution;
}

}  // namespace gradescope_test
