// `course gradescope` end to end, hostile submissions in lab 0: code that
// never returns, a shader loop that never ends, a crash, a flood of output,
// snooping on references, the course's shaders and results. Each fails at
// most its own lab, and the labs not at fault score as they do with the
// solution.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>

#include "tests/grading/gradescope_support.hpp"
#include "tests/support/test_support.hpp"

using namespace gradescope_test;
using fw::test::read_text;

namespace {

// A timeout well above what the solution's slowest lab needs.
int short_timeout(Autograder& ag) {
    double slowest = 0;
    for (const auto& [lab, s] : solution_run(ag).lab_seconds) slowest = std::max(slowest, s);
    return std::max(10, static_cast<int>(5 * slowest) + 1);
}

}  // namespace

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

TEST_CASE(
    "gradescope: submitted code can neither read references or the course's shaders nor write "
    "results") {
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
        {"@SOLUTION_SHADER@",
         (ag.root / "source" / "solution_shaders" / victim_file(ag, "shaders", true).substr(8))
             .string()},
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
    // The lingering process would try again 11 s later: the sandbox kills it
    // when its lab ends (grading/sandbox/sandbox.hpp), so it never gets there.
    std::this_thread::sleep_for(std::chrono::seconds(12));
    const std::string log = read_text(report);
    MESSAGE("what the submission managed:\n" << log);
    CHECK_MESSAGE(log.find("at once") != std::string::npos, "the snooping code did not run");
    CHECK_MESSAGE(log.find("last") == std::string::npos, "the lingering process outlived its lab");
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
