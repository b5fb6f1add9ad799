// `course prairielearn` end to end. The folder is written once and its
// image's course built as the Dockerfile builds it (setup.sh, without apt: a
// build of its own, minutes); then grade.sh runs as PrairieLearn runs it, as
// root where the test is root, on a fake /grade (PL_GRADE_ROOT) with the
// solution, with nothing, with a submission that does not compile, and with
// a grader that fails. Every results.json must follow the schema
// (prairielearn_support.hpp) and stay under 1 MB. (Docker is not used: the
// Dockerfile's one step is setup.sh, which this test and the gradescope
// tests run.)
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "framework/checkpoints.hpp"
#include "framework/text.hpp"
#include "grading/release/release.hpp"
#include "tests/grading/gradescope_support.hpp"
#include "tests/grading/prairielearn_support.hpp"
#include "tests/support/test_support.hpp"

namespace {

namespace fs = std::filesystem;
using fw::shell_quote;
using fw::test::read_text;
using nlohmann::json;
using prairielearn_test::check_schema;

// The folder, its course built, and a fake /grade.
struct Grader {
    fs::path out;     // what `course prairielearn` wrote
    fs::path course;  // out/image/course, built: the image's /course
    fs::path data;    // out/serverFilesCourse/gl-labs, with grade.sh
    fs::path root;    // the fake /grade
    std::string user = "nobody";
    std::vector<std::string> student_files;
    std::string failure;  // why it could not be set up
};

struct Graded {
    int exit_code = -1;
    std::string output;  // grade.sh's stdout and stderr
    std::string text;    // results.json
    json results;
};

std::string set_up(Grader& g) {
    // Outside the build, in /tmp: the user must be able to enter every folder above it.
    const fs::path dir =
        fs::path("/tmp") /
        ("course-prairielearn-" + std::to_string(std::hash<std::string>{}(fw::test::bin_dir())));
    fs::remove_all(dir);
    fs::create_directories(dir);
    fw::test::remove_when_passed(dir.string());
    fs::permissions(dir, fs::perms::owner_all | fs::perms::group_read | fs::perms::group_exec |
                             fs::perms::others_read | fs::perms::others_exec);
    g.out = dir / "out";
    g.course = g.out / "image" / "course";
    g.data = g.out / "serverFilesCourse" / "gl-labs";
    g.root = dir / "grade";
    const auto start = std::chrono::steady_clock::now();
    auto r =
        fw::test::run_command("env -u LAB_ROOT " + shell_quote(fw::test::bin_dir() + "/course") +
                              " prairielearn --out " + shell_quote(g.out.string()));
    MESSAGE("course prairielearn (exit " << r.exit_code << "):\n" << r.output);
    if (r.exit_code != 0) return "course prairielearn failed";
    std::istringstream list(read_text(g.course / "student_files.txt"));
    for (std::string line; std::getline(list, line);)
        if (!line.empty()) g.student_files.push_back(line);
    if (g.student_files.empty()) return "student_files.txt is empty";

    // The Dockerfile's step, with the packages present.
    r = fw::test::run_command("env -u CI SKIP_APT=1 AUTOGRADER_USER=" + g.user + " " +
                              gradescope_test::ccache_setup_env(g.course) + "bash " +
                              shell_quote((g.course / "setup.sh").string()));
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("[%5.1f s] course prairielearn and setup.sh: exit %d\n", seconds, r.exit_code);
    std::fflush(stdout);
    if (r.exit_code != 0) {
        MESSAGE("setup.sh output (tail):\n"
                << r.output.substr(r.output.size() > 6000 ? r.output.size() - 6000 : 0));
        return "setup.sh failed";
    }
    return "";
}

Grader& grader() {
    static Grader g;
    static bool tried = false;
    if (!tried) {
        tried = true;
        g.failure = set_up(g);
    }
    REQUIRE_MESSAGE(g.failure.empty(), "the grader could not be set up: " << g.failure);
    return g;
}

// Runs grade.sh as PrairieLearn does (its path, made executable) with
// `files` (name -> text) in /grade/student and `args` after it.
Graded grade(const Grader& g, const std::string& what,
             const std::map<std::string, std::string>& files, const std::string& args,
             const std::string& env = "") {
    fs::remove_all(g.root);
    fs::create_directories(g.root / "student");
    for (const auto& [name, text] : files) fw::test::write_text(g.root / "student" / name, text);
    const auto start = std::chrono::steady_clock::now();
    const auto r = fw::test::run_command(
        "env -u LAB_ROOT -u LAB_SHADER_DIR -u CI PL_GRADE_ROOT=" + shell_quote(g.root.string()) +
        " PL_COURSE_DIR=" + shell_quote(g.course.string()) + " AUTOGRADER_USER=" + g.user +
        " COURSE_SEED=1 " + env + " " + shell_quote((g.data / "grade.sh").string()) + " " + args);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    Graded out{r.exit_code, r.output, read_text(g.root / "results" / "results.json"), json()};
    out.results = json::parse(out.text, nullptr, false);
    std::printf("[%5.1f s] grade.sh %s, %s: exit %d, results.json %zu bytes\n", seconds,
                args.c_str(), what.c_str(), r.exit_code, out.text.size());
    std::fflush(stdout);
    if (r.exit_code != 0 || !out.results.is_object()) MESSAGE("grade.sh output:\n" << r.output);
    REQUIRE_MESSAGE(r.exit_code == 0, "grade.sh must exit 0 whatever the submission");
    REQUIRE_MESSAGE(out.results.is_object(), "results.json is missing or not JSON");
    CHECK(out.text.size() < prairielearn_test::kMegabyte);
    check_schema(out.results);
    return out;
}

// The repository's solution of every student file, by path.
std::map<std::string, std::string> solution_by_path(const Grader& g) {
    std::map<std::string, std::string> files;
    for (const std::string& rel : g.student_files)
        files[rel] = read_text(fs::path(fw::test::source_dir()) / rel);
    return files;
}

// `files` (by path) by name, as a file upload sends them.
std::map<std::string, std::string> uploaded(const std::map<std::string, std::string>& files) {
    std::map<std::string, std::string> by_name;
    for (const auto& [rel, text] : files) by_name[fs::path(rel).filename().string()] = text;
    return by_name;
}

// The repository's solution of every student file, by name.
std::map<std::string, std::string> solution(const Grader& g) {
    return uploaded(solution_by_path(g));
}

// grade.sh of lab 7 on `files` (by path): its tests by name, their message
// and output, and which of them failed: discard_alpha_test among those;
// `shown` the failed ones that are visible (a hidden checkpoint's test says
// nothing).
std::map<std::string, std::string> grade_lab7(const Grader& g, const std::string& what,
                                              const std::map<std::string, std::string>& files,
                                              std::set<std::string>& shown) {
    const Graded r = grade(g, what, uploaded(files), gradescope_test::kIsolationLab);
    CHECK(r.results["gradable"] == true);
    std::map<std::string, std::string> texts;
    bool discard_failed = false;
    for (const json& t : r.results["tests"]) {
        const std::string name = t["name"];
        texts[name] = t.value("message", "") + "\n" + t.value("output", "");
        const bool failed = t["points"] != t["max_points"];
        discard_failed |=
            failed && name == std::string(gradescope_test::kIsolationLab) + " / discard_alpha_test";
        if (failed && t.value("description", "") != "Hidden checkpoint") shown.insert(name);
    }
    CHECK(discard_failed);
    return texts;
}

// Every checkpoint of the repository's data files, "lab / checkpoint".
std::vector<std::string> checkpoints(const fs::path& root, const std::string& only = "") {
    std::vector<std::string> names;
    std::vector<fs::path> files;
    for (const auto& entry : fs::directory_iterator(root / "labs"))
        if (fs::exists(entry.path() / "checkpoints.json"))
            files.push_back(entry.path() / "checkpoints.json");
    std::sort(files.begin(), files.end());
    for (const fs::path& file : files) {
        const fw::CheckpointFile f = fw::read_checkpoint_file(file.string());
        if (!only.empty() && f.lab != only) continue;
        for (const fw::Checkpoint& cp : f.checkpoints) names.push_back(f.lab + " / " + cp.name);
    }
    return names;
}

std::vector<std::string> test_names(const json& results) {
    std::vector<std::string> names;
    for (const json& t : results["tests"]) names.push_back(t.value("name", ""));
    return names;
}

}  // namespace

TEST_CASE("prairielearn: the image holds the student version; serverFilesCourse all checkpoints") {
    Grader& g = grader();
    const fs::path repo = fw::test::source_dir();
    const std::string dockerfile = read_text(g.out / "image" / "Dockerfile");
    CHECK(dockerfile.find("\nFROM debian:") != std::string::npos);
    CHECK(dockerfile.find("RUN bash /course/setup.sh") != std::string::npos);
    CHECK(read_text(g.course / "setup.sh") ==
          read_text(repo / "grading/platforms/gradescope/setup.sh"));
    CHECK(read_text(g.data / "grade.sh") ==
          read_text(repo / "grading/platforms/prairielearn/grade.sh"));
    CHECK((fs::status(g.data / "grade.sh").permissions() & fs::perms::owner_exec) !=
          fs::perms::none);
    // No solution in the image: its student files are the student versions.
    for (const std::string& rel : g.student_files) {
        INFO(rel);
        const std::string text = read_text(repo / rel);
        CHECK(!grading::solution_blocks(text, rel).empty());
        CHECK(read_text(g.course / rel) == grading::student_text(text, rel));
        CHECK(read_text(g.course / "student_versions" / rel) == grading::student_text(text, rel));
    }
    // The image has the visible checkpoints; serverFilesCourse has them all,
    // and every reference.
    const std::vector<std::string> all = checkpoints(repo), visible = checkpoints(g.course);
    CHECK(checkpoints(g.data) == all);
    std::vector<std::string> hidden;
    for (const std::string& name : all)
        if (std::find(visible.begin(), visible.end(), name) == visible.end())
            hidden.push_back(name);
    MESSAGE("hidden checkpoints, left out of the image: " << fw::join(hidden, ", "));
    CHECK(!hidden.empty());
    for (const auto& entry : fs::recursive_directory_iterator(repo / "labs")) {
        if (entry.path().parent_path().filename() != "reference") continue;
        const fs::path rel = fs::relative(entry.path(), repo);
        CHECK_MESSAGE(fs::exists(g.data / rel), rel << " is missing from serverFilesCourse");
    }
    // No reference code in the public image (it holds the solutions); the
    // unit checks' cases, hidden ones too, are recorded in serverFilesCourse.
    for (const auto& entry : fs::recursive_directory_iterator(g.course / "labs")) {
        const fs::path rel = fs::relative(entry.path(), g.course);
        CHECK_MESSAGE(!(entry.path().parent_path().filename() == "grading" &&
                        entry.path().extension() == ".cpp"),
                      rel << ": a unit-check reference in the public image");
    }
    // The course's text of the student shaders, which the image lacks.
    size_t shaders = 0;
    for (const std::string& rel : g.student_files) {
        if (rel.rfind("shaders/", 0) != 0) continue;
        INFO(rel);
        ++shaders;
        CHECK(read_text(g.data / "solution_shaders" / rel.substr(8)) == read_text(repo / rel));
    }
    CHECK(shaders > 0);
    CHECK(!fs::exists(g.course / "solution_shaders"));
    const json cases = json::parse(read_text(g.data / "labs/01_transforms/grading/cases.json"));
    CHECK(cases.at("for") == "autograder");
    std::set<std::string> recorded;
    for (const json& c : cases.at("checks")) recorded.insert(c.at("checkpoint").get<std::string>());
    CHECK(recorded.count("mirror_rotated") == 1);  // a hidden checkpoint's unit check
    CHECK(std::find(hidden.begin(), hidden.end(), "transforms / mirror_rotated") != hidden.end());
    const std::string readme = read_text(g.out / "README.md");
    fw::test::check_mentions(readme,
                             {"externalGradingOptions", "/grade/serverFilesCourse/gl-labs/grade.sh",
                              "docker build --platform linux/amd64", "pl-file-upload"});
    auto again = fw::test::run_command(shell_quote(fw::test::bin_dir() + "/course") +
                                       " prairielearn --out " + shell_quote(g.out.string()));
    fw::test::check_mentions(again.output, {"not empty", g.out.string()});
    CHECK(again.exit_code == 2);
}

TEST_CASE("prairielearn: nothing submitted: the student versions, below full marks, under 1 MB") {
    Grader& g = grader();
    const Graded r = grade(g, "nothing (student versions)", {}, "");
    CHECK(r.results["gradable"] == true);
    CHECK(test_names(r.results) == checkpoints(fw::test::source_dir()));
    CHECK(r.results["score"].get<double>() < 1.0);
    MESSAGE("the student version of the whole course: score " << r.results["score"]);
    fw::test::check_mentions(r.output, {"not submitted: graded with the student version"});
    // The failures show pictures, as many as fit.
    size_t pictures = 0;
    for (const json& t : r.results["tests"]) pictures += t["images"].size();
    CHECK(pictures > 0);
}

TEST_CASE("prairielearn: the solution scores full marks; grade.sh LAB grades that lab alone") {
    Grader& g = grader();
    const Graded all = grade(g, "the solution", solution(g), "");
    CHECK(all.results["gradable"] == true);
    CHECK(all.results["score"] == 1.0);
    for (const json& t : all.results["tests"])
        CHECK_MESSAGE(t["points"] == t["max_points"], t["name"] << ": " << t["output"]);
    fw::test::check_mentions(all.output, {"submitted as"});

    const Graded one = grade(g, "the solution", solution(g), "robot-arm");
    CHECK(test_names(one.results) == checkpoints(fw::test::source_dir(), "robot-arm"));
    CHECK(one.results["score"] == 1.0);
}

TEST_CASE("prairielearn: a submission that does not compile is not gradable, with the message") {
    Grader& g = grader();
    std::map<std::string, std::string> files = solution(g);
    files["pipeline.cpp"] += "\nint broken_submission = undeclared_name_in_submission;\n";
    const Graded r = grade(g, "a compile error in pipeline.cpp", files, "pipeline");
    CHECK(r.results["gradable"] == false);
    fw::test::check_mentions(r.results["format_errors"][0], {"does not build"});
    fw::test::check_mentions(r.results["output"],
                             {"pipeline.cpp", "undeclared_name_in_submission", "error"});
}

TEST_CASE("prairielearn: when course grade itself fails, not gradable with the reason") {
    Grader& g = grader();
    // A timeout course grade refuses (usage error, exit 2) stands for any failure of the grader.
    const Graded r =
        grade(g, "the solution, the grader failing", solution(g), "pipeline", "COURSE_TIMEOUT=0");
    CHECK(r.results["gradable"] == false);
    fw::test::check_mentions(r.results["message"], {"course grade failed (exit status 2)"});
    fw::test::check_mentions(r.results["output"], {"--timeout"});
}

TEST_CASE("prairielearn: a mistake in one shader: results.json names that file") {
    Grader& g = grader();
    std::set<std::string> shown;
    const auto texts = grade_lab7(g, "cutout.frag discarding the opaque fragments",
                                  gradescope_test::shader_mistake(solution_by_path(g)), shown);
    // Under each visible failed checkpoint (each draws with cutout.frag), once.
    for (const auto& [name, text] : texts) {
        INFO(name << ":\n" << text);
        CHECK(gradescope_test::isolation_mentions(text) == shown.count(name));
        if (shown.count(name))
            CHECK(text.find(gradescope_test::isolation_sentence(
                      gradescope_test::kIsolationShader)) != std::string::npos);
    }
    // The data folder, the course's shaders in it, is kept from the user.
    if (geteuid() == 0)
        CHECK((fs::status(g.data).permissions() & (fs::perms::group_all | fs::perms::others_all)) ==
              fs::perms::none);
}

TEST_CASE("prairielearn: a mistake in C++: results.json names no shader file") {
    Grader& g = grader();
    std::set<std::string> shown;
    for (const auto& [name, text] :
         grade_lab7(g, "set_blend_mode's factors swapped",
                    gradescope_test::cpp_mistake(solution_by_path(g)), shown)) {
        INFO(name << ":\n" << text);
        CHECK(gradescope_test::isolation_mentions(text) == 0);
    }
    CHECK(!shown.empty());
}
