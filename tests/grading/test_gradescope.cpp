// `course gradescope` end to end: the folder is written, set up as Gradescope
// would (grading/gradescope/setup.sh, without apt) in a fake /autograder,
// built once, then run_autograder grades submissions made from the solution:
// the solution itself, nothing (the student versions), and hostile ones in
// lab 0 (code that never returns, a shader loop that never ends, a crash, a
// flood of output, snooping on references and results, a compile error).
// Every results.json must list every check of every lab with its points, and
// the labs not at fault must score as they do with the solution.
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>
#include <thread>

#include "framework/checkpoints.hpp"
#include "grading/release.hpp"
#include "tests/support/test_support.hpp"

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

using fw::test::read_text;
using fw::test::shell_quote;
using fw::test::write_text;

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

std::string tail(const std::string& text, size_t bytes = 6000) {
    return text.substr(text.size() > bytes ? text.size() - bytes : 0);
}

// What the data files promise (computed here, not by course): for each
// "lab / checkpoint", how many checks; and the points of them all.
struct Expected {
    std::map<std::string, int> checks;
    double points = 0;
    std::string victim;      // lab 0's name ("lab" in labs/00_*/checkpoints.json)
    std::string victim_dir;  // its folder, e.g. 00_pipeline
};

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
            for (const json& check : cp.checks) e.points += check["points"].get<double>();
        }
    }
    return e;
}

std::string lab_of(const json& test) {
    const std::string name = test.value("name", "");
    return name.substr(0, name.find(" / "));
}

// A run of run_autograder.
struct Run {
    int exit_code = -1;
    std::string output;  // run_autograder's stdout and stderr
    double seconds = 0;
    json results;                               // results/results.json
    std::map<std::string, double> lab_seconds;  // from results/grade/summary.txt
};

// The autograder, set up once for every test case.
struct Autograder {
    fs::path dir, root;  // root: the fake /autograder
    std::string user;    // AUTOGRADER_USER; run-as applies when the test runs as root
    std::vector<std::string> student_files;
    std::map<std::string, std::string> solution_text;  // student file -> as copied
    std::map<std::string, std::string> scripts;        // setup.sh, run_autograder -> as copied
    Expected expected;
    std::string failure;  // why it could not be set up
    std::optional<Run> solution;
};

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
        ag.scripts[script] = read_text(source / "grading" / "gradescope" / script);
    // Gradescope copies run_autograder to /autograder and runs it from there.
    fs::copy_file(source / "run_autograder", ag.root / "run_autograder");

    // Packages are present here; ccache, when installed, keeps re-runs quick.
    std::string env = "SKIP_APT=1";
    if (fw::test::run_command("command -v ccache").exit_code == 0)
        env +=
            " CMAKE_CXX_COMPILER_LAUNCHER=ccache CMAKE_C_COMPILER_LAUNCHER=ccache "
            "CCACHE_NOHASHDIR=1 CCACHE_BASEDIR=" +
            shell_quote(source.string());
    r = fw::test::run_command(environment(ag, env) + "bash " +
                              shell_quote((source / "setup.sh").string()));
    std::printf("[%5.1f s] setup.sh: exit %d\n", seconds_since(start), r.exit_code);
    if (r.exit_code != 0) {
        MESSAGE("setup.sh output (tail):\n" << tail(r.output));
        return "setup.sh failed";
    }
    return "";
}

// Builds the submission folder from `files` (path in the submission -> text)
// and runs run_autograder on it.
Run submit(const Autograder& ag, const std::string& what,
           const std::map<std::string, std::string>& files, const std::string& env = "") {
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
    if (fs::exists(results)) run.results = json::parse(read_text(results), nullptr, false);
    // summary.txt: "lab  score  checks  status...  seconds" under a header line.
    std::istringstream table(read_text(ag.root / "results" / "grade" / "summary.txt"));
    std::string line;
    std::getline(table, line);
    while (std::getline(table, line) && !line.empty()) {
        std::istringstream words(line);
        std::vector<std::string> w{std::istream_iterator<std::string>(words), {}};
        if (w.size() >= 5) run.lab_seconds[w[0]] = std::atof(w.back().c_str());
    }
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

// results.json is complete: every check of every lab, each with its fields,
// the points adding up to the data files' total.
void check_complete(const Run& run, const Expected& e) {
    REQUIRE_MESSAGE(run.exit_code == 0, "run_autograder must exit 0 whatever the submission");
    REQUIRE_MESSAGE(run.results.is_object(), "results.json is missing or not JSON");
    const json& r = run.results;
    REQUIRE(r.contains("tests"));
    std::map<std::string, int> seen;
    double score = 0;
    for (const json& t : r["tests"]) {
        for (const char* field : {"name", "score", "max_score", "status", "output", "visibility"})
            CHECK_MESSAGE(t.contains(field), "test " << t.dump() << " has no " << field);
        const std::string name = t.value("name", "");
        seen[name.substr(0, name.find(" / ", name.find(" / ") + 3))] += 1;
        score += t.value("score", 0.0);
    }
    CHECK_MESSAGE(seen == e.checks,
                  "Expected the checks of the data files, Observed those of results.json");
    CHECK(r.value("max_score", -1.0) == doctest::Approx(e.points));
    CHECK(r.value("score", -1.0) == doctest::Approx(score));
}

const Run& solution_run(Autograder& ag);

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
        CHECK_MESSAGE(t["status"] == want[t["name"]],
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
        CHECK_MESSAGE(t.value("output", "").find(reason) != std::string::npos,
                      t["name"] << ": Expected an output naming \"" << reason << "\", Observed:\n"
                                << t.value("output", ""));
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
                                           const std::string& includes = "") {
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

}  // namespace

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
}

TEST_CASE("gradescope: nothing submitted is graded with the student versions, below full marks") {
    Autograder& ag = autograder();
    Run run = submit(ag, "no code (student versions)", {{"README.txt", "nothing yet\n"}});
    check_complete(run, ag.expected);
    fw::test::check_mentions(run.output, {"not submitted: graded with the student version"});
    const double score = run.results.value("score", -1.0),
                 max = run.results.value("max_score", 0.0);
    MESSAGE("student versions: " << score << " of " << max << " points");
    CHECK(score < max);
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

// A timeout well above what the solution's slowest lab needs.
int short_timeout(Autograder& ag) {
    double slowest = 0;
    for (const auto& [lab, s] : solution_run(ag).lab_seconds) slowest = std::max(slowest, s);
    return std::max(10, static_cast<int>(5 * slowest) + 1);
}

TEST_CASE("gradescope: student code that never returns fails its lab by the timeout") {
    Autograder& ag = autograder();
    const int timeout = short_timeout(ag);
    const std::string file = victim_file(ag, "labs", false);
    Run run =
        submit(ag, "endless loop in " + file,
               hostile(ag, file, "    for (volatile bool forever = true; forever;) {}", false),
               "COURSE_TIMEOUT=" + std::to_string(timeout));
    check_victim_failed(ag, run, "timed out after " + std::to_string(timeout) + " s");
}

// Mesa's llvmpipe (the CPU driver) ends every shader loop after 65535
// iterations in all, so there the lab finishes; a GPU may run the loop for
// ever, and then the timeout must stop it. Either way the grading completes.
TEST_CASE("gradescope: a shader loop that never ends cannot stall the grading") {
    Autograder& ag = autograder();
    const int timeout = short_timeout(ag);
    // The loop starts from a uniform, so no compiler can tell that it never
    // ends: u_mvp's last element is 1 in the scenes drawn with the identity,
    // and spin then tends to 2.
    const std::string file = victim_file(ag, "shaders", true);
    Run run = submit(ag, "endless loop in " + file,
                     hostile(ag, file,
                             "    float spin = u_mvp[3][3];\n"
                             "    while (spin > 0.0) spin = spin * 0.5 + 1.0;\n"
                             "    position.x += spin * 1.0e-30;",
                             true),
                     "COURSE_TIMEOUT=" + std::to_string(timeout));
    check_complete(run, ag.expected);
    check_others_unaffected(ag, run);
    const std::string timed_out = "timed out after " + std::to_string(timeout) + " s";
    const bool stopped = run.output.find(timed_out) != std::string::npos;
    MESSAGE(ag.expected.victim << (stopped ? ": " + timed_out : ": the driver ended the loop")
                               << "; run_autograder took " << run.seconds << " s");
    CHECK(run.lab_seconds[ag.expected.victim] < timeout + 5);
    if (stopped) check_victim_failed(ag, run, timed_out);
}

TEST_CASE("gradescope: a crash in student code fails its lab naming the signal") {
    Autograder& ag = autograder();
    const std::string file = victim_file(ag, "labs", false);
    Run run =
        submit(ag, "null write in " + file,
               hostile(ag, file, "    { volatile int* volatile hostile = nullptr; *hostile = 1; }",
                       false));
    check_victim_failed(ag, run, "SIGSEGV");
}

TEST_CASE("gradescope: gigabytes on stdout are cut at the cap, quickly") {
    Autograder& ag = autograder();
    const std::string file = victim_file(ag, "labs", false);
    Run run = submit(ag, "flood from " + file,
                     hostile(ag, file,
                             "    { static char line[4096];\n"
                             "      std::memset(line, 'x', sizeof line - 1);\n"
                             "      for (long i = 0; i < (1L << 20); ++i)  // 4 GiB\n"
                             "          std::fwrite(line, 1, sizeof line - 1, stdout); }",
                             false, "#include <cstdio>\n#include <cstring>\n"));
    check_victim_failed(ag, run, "to stdout/stderr");
    const double seconds = run.lab_seconds[ag.expected.victim];
    MESSAGE(ag.expected.victim << " ran " << seconds << " s before it was stopped");
    CHECK(seconds < 10);
}

TEST_CASE("gradescope: submitted code can neither read references nor write results") {
    if (geteuid() != 0) {
        MESSAGE(
            "skipped: run-as needs root (run_autograder runs as root on Gradescope); "
            "this test runs as uid "
            << geteuid());
        return;
    }
    Autograder& ag = autograder();
    const std::string file = victim_file(ag, "labs", false);
    const fs::path lab = ag.root / "source" / "labs" / ag.expected.victim_dir;
    std::string reference;
    for (const auto& e : fs::directory_iterator(lab / "reference")) reference = e.path().string();
    REQUIRE_MESSAGE(!reference.empty(), "no reference image in " << lab / "reference");
    // Where the submission reports what it managed: a folder anyone may write.
    const fs::path report = ag.dir / "snoop" / "report.txt";
    fs::remove_all(report.parent_path());
    fs::create_directories(report.parent_path());
    fs::permissions(report.parent_path(), fs::perms::all | fs::perms::sticky_bit);
    const fs::path results = ag.root / "results";
    const std::map<std::string, std::string> values = {
        {"@REPORT@", report.string()},
        {"@REFERENCE@", reference},
        {"@CHECKPOINTS@", (lab / "checkpoints.json").string()},
        {"@RESULTS@", (results / "results.json").string()},
        {"@GRADE_RESULTS@", (results / "grade" / "results.json").string()},
        {"@FORGED@", "{\"score\": 1000000, \"output\": \"forged by the submission\"}"}};
    std::string code = read_text(fw::test::source_dir() + "/tests/grading/submissions/snoop.inc");
    for (const auto& [name, value] : values)
        for (size_t at; (at = code.find(name)) != std::string::npos;)
            code.replace(at, name.size(), json(value).dump());
    Run run = submit(ag, "snooping from " + file,
                     hostile(ag, file, code, false,
                             "#include <fcntl.h>\n#include <unistd.h>\n#include <cerrno>\n"
                             "#include <cstdio>\n#include <cstring>\n"));
    // The lingering process gives up after 11 s.
    std::string log;
    for (int i = 0; i < 40 && (log = read_text(report)).find("last") == std::string::npos; ++i)
        std::this_thread::sleep_for(std::chrono::milliseconds(500));
    MESSAGE("what the submission managed:\n" << log);
    CHECK_MESSAGE(log.find("at once") != std::string::npos, "the snooping code did not run");
    CHECK_MESSAGE(log.find("last") != std::string::npos, "the lingering process did not run");
    CHECK_MESSAGE(log.find("DONE") == std::string::npos, "some attempt succeeded");
    for (const fs::path& p : {results / "results.json", results / "grade" / "results.json"})
        CHECK_MESSAGE(read_text(p).find("forged") == std::string::npos, p << " was forged");
    // The results are course's: complete, and lab 0 scores as the solution does.
    Run now = run;
    now.results = json::parse(read_text(results / "results.json"), nullptr, false);
    check_complete(now, ag.expected);
    check_others_unaffected(ag, now);
    const Run& solution = solution_run(ag);
    CHECK(now.results.value("score", -1.0) ==
          doctest::Approx(solution.results.value("score", 0.0)));
}

TEST_CASE("gradescope: a submission that does not compile scores 0 with the compiler's message") {
    Autograder& ag = autograder();
    const std::string file = victim_file(ag, "labs", false);
    Run run = submit(ag, "compile error in " + file,
                     hostile(ag, file, "    undeclared_name_in_submission = 1;", false));
    check_complete(run, ag.expected);
    CHECK(run.results.value("score", -1.0) == 0.0);
    const std::string output = run.results.value("output", "");
    fw::test::check_mentions(output, {"does not build", fs::path(file).filename().string(),
                                      "undeclared_name_in_submission", "error"});
    for (const json& t : run.results["tests"]) CHECK(t["status"] == "failed");
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
    check_complete(run, ag.expected);
    CHECK(run.results.value("score", -1.0) == 0.0);
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
