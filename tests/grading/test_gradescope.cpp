// `course gradescope` end to end (gradescope_support.hpp sets the
// autograder up once): the folder as written, the solution, nothing (the
// student versions), a file that does not compile (its lab fails, the
// others are graded), and a grader that fails. Every results.json must list
// every check of every lab with its points. The hostile submissions are in
// test_gradescope_hostile.cpp.
#include <unistd.h>

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "framework/checkpoints.hpp"
#include "framework/text.hpp"
#include "grading/release/release.hpp"
#include "tests/grading/grade_support.hpp"
#include "tests/grading/gradescope_support.hpp"
#include "tests/support/test_support.hpp"

using namespace gradescope_test;
using fw::shell_quote;
using fw::test::read_text;

TEST_CASE("gradescope: the folder holds the repository, the scripts and the student versions") {
    Autograder& ag = autograder();
    // Compared with the copy as written: the repository may change meanwhile.
    const fs::path source = ag.root / "source", repo = fw::test::source_dir();
    for (const auto& [script, text] : ag.scripts) {
        INFO(script);
        CHECK((fs::status(source / script).permissions() & fs::perms::owner_exec) !=
              fs::perms::none);
        CHECK(read_text(source / script) == text);
    }
    CHECK(!fs::exists(source / ".git"));
    CHECK(fs::exists(source / "CMakeLists.txt"));
    for (const auto& [rel, text] : ag.solution_text) {
        INFO(rel);
        CHECK(!grading::solution_blocks(text, rel).empty());
        CHECK(read_text(source / "student_versions" / rel) == grading::student_text(text, rel));
    }
    // The course's text of each student shader, aside, where only root may read it.
    size_t shaders = 0;
    for (const auto& [rel, text] : ag.solution_text) {
        if (rel.rfind("shaders/", 0) != 0) continue;
        INFO(rel);
        ++shaders;
        CHECK(read_text(source / "solution_shaders" / rel.substr(8)) == text);
    }
    CHECK(shaders > 0);
    if (geteuid() == 0) {
        const fs::file_status aside = fs::status(source / "solution_shaders");
        CHECK((aside.permissions() & (fs::perms::group_all | fs::perms::others_all)) ==
              fs::perms::none);
    }
    // Every lab's checkpoints, hidden ones included: the autograder grades them.
    for (const auto& entry : fs::directory_iterator(repo / "labs")) {
        const fs::path data = entry.path() / "checkpoints.json";
        if (!fs::exists(data)) continue;
        std::vector<std::string> want, seen;
        for (const auto& cp : fw::read_checkpoint_file(data.string()).checkpoints)
            want.push_back(cp.name);
        const fs::path copy = source / "labs" / entry.path().filename() / "checkpoints.json";
        for (const auto& cp : fw::read_checkpoint_file(copy.string()).checkpoints)
            seen.push_back(cp.name);
        INFO(copy);
        CHECK(seen == want);
    }
    auto again = fw::test::run_command(shell_quote(fw::test::bin_dir() + "/course") +
                                       " gradescope --out " + shell_quote(source.string()));
    fw::test::check_mentions(again.output, {"not empty", source.string()});
    CHECK(again.exit_code == 2);
    // There are hidden checkpoints, which run_autograder shows after the due date.
    CHECK(!ag.expected.hidden.empty());
    fw::test::check_mentions(ag.scripts["run_autograder"],
                             {"\nhidden_as=after_due_date\n", "--hidden-as \"$hidden_as\""});
}

TEST_CASE("gradescope: --hidden-as goes into run_autograder; another value is refused") {
    const std::string course = shell_quote(fw::test::bin_dir() + "/course");
    const fs::path dir = fs::path(fw::test::out_dir()) / "hidden-as";
    for (const char* as : {"after_published", "hidden"}) {
        INFO(as);
        fs::remove_all(dir);
        const auto r = fw::test::run_command("env -u LAB_ROOT " + course + " gradescope --out " +
                                             shell_quote(dir.string()) + " --hidden-as " + as);
        REQUIRE_MESSAGE(r.exit_code == 0, r.output);
        fw::test::check_mentions(r.output, {as});
        const std::string script = read_text(dir / "run_autograder");
        fw::test::check_mentions(
            script, {"\nhidden_as=" + std::string(as) + "\n", "--hidden-as \"$hidden_as\""});
        CHECK(script.find("hidden_as=after_due_date") == std::string::npos);
    }
    fs::remove_all(dir);
    const auto bad = fw::test::run_command(course + " gradescope --out " +
                                           shell_quote(dir.string()) + " --hidden-as never");
    CHECK(bad.exit_code == 2);
    fw::test::check_mentions(bad.output, {"--hidden-as", "never"});
    CHECK(!fs::exists(dir));
}

namespace {

// run_autograder as an assignment of lab 7 alone (its labs= line), on `files`.
Run submit_lab7(Autograder& ag, const std::string& what,
                const std::map<std::string, std::string>& files) {
    const fs::path runner = ag.root / "run_autograder";
    const std::string full = read_text(runner);
    std::string script = full;
    const size_t at = script.find("\nlabs=\n");
    REQUIRE(at != std::string::npos);
    script.replace(at + 1, 5, "labs=" + std::string(kIsolationLab));
    fw::test::write_text(runner, script);
    const Run run = submit(ag, what, files);
    fw::test::write_text(runner, full);
    REQUIRE_MESSAGE(run.exit_code == 0, "run_autograder must exit 0 whatever the submission");
    REQUIRE_MESSAGE(run.results.is_object(), "results.json is missing or not JSON");
    return run;
}

// Lab 7's tests by checkpoint name, their outputs as a student reads them,
// and which of them failed; discard_alpha_test among those.
std::map<std::string, std::string> lab7_outputs(const Run& run, std::set<std::string>& failed) {
    std::map<std::string, std::string> outputs;
    for (const json& t : run.results["tests"]) {
        CHECK(lab_of(t) == kIsolationLab);
        outputs[t["name"]] = grade_test::unescape_markup(t.value("output", ""));
        if (t["status"] == "failed") failed.insert(t["name"]);
    }
    CHECK(failed.count(std::string(kIsolationLab) + " / discard_alpha_test") == 1);
    return outputs;
}

}  // namespace

TEST_CASE("gradescope: a mistake in one shader: results.json names that file") {
    Autograder& ag = autograder();
    const Run run = submit_lab7(ag, "cutout.frag discarding the opaque fragments",
                                shader_mistake(ag.solution_text));
    std::set<std::string> failed;
    const auto outputs = lab7_outputs(run, failed);
    // Under each failed checkpoint (each draws with cutout.frag), once.
    for (const auto& [name, output] : outputs) {
        INFO(name << ":\n" << output);
        CHECK(isolation_mentions(output) == failed.count(name));
        if (failed.count(name))
            CHECK(output.find(isolation_sentence(kIsolationShader)) != std::string::npos);
    }
    MESSAGE(failed.size() << " failed checkpoints of lab 7 name " << std::string(kIsolationShader)
                          << "; " << run.seconds << " s");
}

TEST_CASE("gradescope: a mistake in C++: results.json names no shader file") {
    Autograder& ag = autograder();
    const Run run =
        submit_lab7(ag, "set_blend_mode's factors swapped", cpp_mistake(ag.solution_text));
    std::set<std::string> failed;
    for (const auto& [name, output] : lab7_outputs(run, failed)) {
        INFO(name << ":\n" << output);
        CHECK(isolation_mentions(output) == 0);
    }
}

TEST_CASE("gradescope: nothing submitted is graded with the student versions, below full marks") {
    Autograder& ag = autograder();
    Run run = submit(ag, "no code (student versions)", {{"README.txt", "nothing yet\n"}});
    check_complete(run, ag.expected);
    fw::test::check_mentions(run.output, {"not submitted: graded with the student version"});
    const double score = run.results.value("score", -1.0),
                 max = run.results.value("extra_data", json::object()).value("max_score", 0.0);
    MESSAGE("student versions: " << score << " of " << max << " points; results.json "
                                 << run.results_bytes << " bytes");
    CHECK(score < max);
    // The failed checkpoints show pictures, within the 1 MB (check_complete).
    size_t pictures = 0;
    for (const json& t : run.results["tests"]) {
        const std::string output = t.value("output", "");
        for (size_t at = output.find("<img src=\"data:image/"); at != std::string::npos;
             at = output.find("<img src=\"data:image/", at + 1))
            ++pictures;
    }
    MESSAGE(pictures << " pictures in results.json");
    CHECK(pictures > 0);
}

TEST_CASE("gradescope: the solution, uploaded flat, scores full marks") {
    Autograder& ag = autograder();
    const Run& run = solution_run(ag);
    check_complete(run, ag.expected);
    fw::test::check_mentions(run.output, {"submitted as"});
    for (const json& t : run.results["tests"])
        CHECK_MESSAGE(t["status"] == "passed", t["name"] << ": " << t.value("output", ""));
    CHECK(run.results.value("score", -1.0) == doctest::Approx(ag.expected.points));
}

TEST_CASE("gradescope: a file that does not compile scores 0 on its lab alone, with the message") {
    Autograder& ag = autograder();
    const std::string file = victim_file(ag, "labs", false);
    Run run = submit(ag, "compile error in " + file,
                     hostile(ag, file, "    undeclared_name_in_submission = 1;", false));
    // Each check of the lab names the compiler's first error, at the file's
    // path in the repository; the other labs, built with the lab's starting
    // code, score as the solution's.
    check_victim_failed(ag, run, "does not build: " + file + ":");
    double victim = 0, others = 0;
    for (const json& t : run.results["tests"])
        (lab_of(t) == ag.expected.victim ? victim : others) += t.value("score", 0.0);
    CHECK(victim == 0.0);
    CHECK(others > 0.0);
    const std::string output = run.results.value("output", "");
    fw::test::check_mentions(output, {"does not build", fs::path(file).filename().string(),
                                      "undeclared_name_in_submission", "error"});
    fw::test::check_mentions(run.output,
                             {ag.expected.victim_dir + " does not compile", "--not-built"});
}

TEST_CASE("gradescope: the compiler cannot quote checkpoints or references back to the student") {
    if (geteuid() != 0) {
        MESSAGE("skipped: building as the unprivileged user needs root; this test runs as uid "
                << geteuid());
        return;
    }
    Autograder& ag = autograder();
    const std::string file = victim_file(ag, "labs", false);
    const fs::path checkpoints =
        ag.root / "source" / "labs" / ag.expected.victim_dir / "checkpoints.json";
    // A hidden checkpoint's name: in the course's file, never in what students see.
    const json doc = json::parse(read_text(checkpoints), nullptr, true, /*ignore_comments=*/true);
    std::string hidden;
    for (const json& cp : doc["checkpoints"])
        if (cp.value("visibility", "") == "hidden") hidden = cp["name"].get<std::string>();
    REQUIRE_MESSAGE(!hidden.empty(), checkpoints << " has no hidden checkpoint");
    Run run = submit(ag, "#include of " + checkpoints.string() + " in " + file,
                     hostile(ag, file, "#include " + json(checkpoints.string()).dump(), false));
    check_victim_failed(ag, run, "does not build");
    const std::string output = run.results.value("output", "");
    // The compiler, run as the user, may not even open the file.
    fw::test::check_mentions(output, {"does not build", "checkpoints.json", "Permission denied"});
    CHECK_MESSAGE(output.find(hidden) == std::string::npos,
                  "the compiler's message quotes the hidden checkpoint '" << hidden << "'");
}

TEST_CASE("gradescope: when course grade itself fails, results.json still lists every check") {
    Autograder& ag = autograder();
    // A timeout course grade refuses (usage error, exit 2) stands for any failure of the grader.
    Run run = submit(ag, "the solution, the grader failing", ag.solution_text, "COURSE_TIMEOUT=0");
    check_complete(run, ag.expected);
    CHECK(run.results.value("score", -1.0) == 0.0);
    fw::test::check_mentions(run.results.value("output", ""),
                             {"course grade failed (exit status 2)", "--timeout"});
}

TEST_CASE("gradescope: an assignment of one lab grades it from its own files only") {
    Autograder& ag = autograder();
    const Run& all = solution_run(ag);
    const std::string course = shell_quote(fw::test::bin_dir() + "/course");
    const fs::path dir = fs::path(fw::test::out_dir()) / "assignment";
    fs::remove_all(dir);
    const std::string victim = ag.expected.victim, folder = ag.expected.victim_dir;
    // A lab that does not exist is refused, naming the labs; nothing is written.
    const auto unknown = fw::test::run_command(course + " gradescope --out " +
                                               shell_quote(dir.string()) + " no-such-lab");
    CHECK(unknown.exit_code == 2);
    fw::test::check_mentions(unknown.output, {"unknown lab 'no-such-lab'", victim});
    CHECK(!fs::exists(dir));
    const auto written = fw::test::run_command("env -u LAB_ROOT " + course + " gradescope --out " +
                                               shell_quote(dir.string()) + " " + victim);
    REQUIRE_MESSAGE(written.exit_code == 0, written.output);
    fw::test::check_mentions(written.output, {"graded: " + victim + " only"});
    const std::string script = read_text(dir / "run_autograder");
    fw::test::check_mentions(script, {"\nlabs=\"" + victim + "\"\n", "\"$hidden_as\" $labs"});
    // Only the lab's own files are taken from a submission.
    std::vector<std::string> own;
    std::istringstream lines(read_text(dir / "student_files.txt"));
    for (std::string line; std::getline(lines, line);)
        if (!line.empty()) own.push_back(line);
    REQUIRE(!own.empty());
    for (const std::string& rel : own) {
        INFO(rel);
        CHECK((rel.rfind("labs/" + folder + "/", 0) == 0 ||
               rel.rfind("shaders/" + folder + "/", 0) == 0));
    }
    size_t of_victim = 0;
    for (const std::string& rel : ag.student_files)
        of_victim += rel.find("/" + folder + "/") != std::string::npos;
    CHECK(own.size() == of_victim);

    // The set-up autograder as the assignment: its run_autograder and file list.
    const std::string list = (ag.root / "source" / "student_files.txt").string(),
                      runner = (ag.root / "run_autograder").string();
    const std::string full_list = read_text(list), full_runner = read_text(runner);
    fw::test::write_text(runner, script);
    fw::test::write_text(list, read_text(dir / "student_files.txt"));
    fs::remove_all(dir);
    // The solution of the lab, and a file of another lab that does not compile:
    // the assignment never takes it, so the build and the grade stand.
    std::map<std::string, std::string> files;
    std::string other;
    for (const auto& [rel, text] : ag.solution_text)
        if (rel.find("/" + folder + "/") != std::string::npos)
            files[fs::path(rel).filename().string()] = text;
        else if (other.empty() && rel.ends_with(".cpp"))
            other = rel;
    REQUIRE(!other.empty());
    files[other] = "#error this file is not part of the assignment\n";
    const Run run = submit(ag, "an assignment of " + victim, files);
    fw::test::write_text(runner, full_runner);
    fw::test::write_text(list, full_list);
    REQUIRE(run.results.is_object());
    std::map<std::string, double> want, got;
    for (const json& t : all.results["tests"])
        if (lab_of(t) == victim) want[t["name"]] = t.value("score", -1.0);
    for (const json& t : run.results["tests"]) got[t["name"]] = t.value("score", -1.0);
    REQUIRE(!want.empty());
    CHECK(got == want);
    double points = 0;
    for (const auto& [name, score] : want) points += score;
    CHECK(run.results.value("score", -1.0) == doctest::Approx(points));
    CHECK(run.lab_seconds.size() == 1);
    CHECK(run.lab_seconds.count(victim) == 1);
    MESSAGE("an assignment of " << victim << ": " << run.seconds << " s, " << got.size()
                                << " tests, " << points << " points");
}
