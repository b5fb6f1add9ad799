// `course autograde` where it cannot grade, through run_autograder (the
// shim), on a small fake /autograder that builds nothing of the repository:
// its `lab` target is a shell script. The reason is shown, and results.json
// is complete, valid JSON whatever the log holds (quotes, backslashes,
// control characters, bytes that are not UTF-8). And the shim's own
// results.json when course cannot run at all.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "framework/text.hpp"
#include "tests/grading/grade_support.hpp"
#include "tests/grading/gradescope_support.hpp"
#include "tests/support/test_support.hpp"

namespace {

namespace fs = std::filesystem;
using fw::shell_quote;
using fw::test::read_text;
using fw::test::write_text;
using gradescope_test::check_log_kept;
using gradescope_test::kBuilds;
using gradescope_test::kHostileLog;
using gradescope_test::make_root;
using nlohmann::json;

struct Outcome {
    int exit_code = -1;
    std::string output;  // run_autograder's
    json results;        // results/results.json; discarded (not an object) when not JSON
};

Outcome run_autograder(const fs::path& root, const std::string& env = "") {
    const std::string shim =
        fw::test::source_dir() + "/grading/platforms/gradescope/run_autograder";
    const auto r = fw::test::run_command(
        "env -u LAB_ROOT -u LAB_SHADER_DIR AUTOGRADER_ROOT=" + shell_quote(root.string()) +
        " AUTOGRADER_USER=no-such-user-of-the-autograde-test " + env + " bash " +
        shell_quote(shim));
    MESSAGE("run_autograder: exit " << r.exit_code << "\n" << r.output);
    Outcome o{r.exit_code, r.output, json()};
    o.results = json::parse(read_text((root / "results/results.json").string()), nullptr, false);
    return o;
}

// Exit 0, and results.json lists every check of lab 0, failed, with `reason`
// in its output.
void check_not_graded(const Outcome& o, const std::string& reason) {
    CHECK(o.exit_code == 0);
    REQUIRE_MESSAGE(o.results.is_object(), "results.json is missing or not JSON");
    CHECK(o.results.value("score", -1.0) == 0.0);
    CHECK(!o.results.contains("max_score"));  // not in Gradescope's specification
    CHECK(o.results.value("extra_data", json::object()).value("max_score", -1.0) ==
          doctest::Approx(grade_test::points(grade_test::lab0_checks())));
    CHECK(grade_test::checks_of(o.results).size() == grade_test::lab0_checks().size());
    for (const json& t : o.results["tests"]) CHECK(t["status"] == "failed");
    fw::test::check_mentions(o.results.value("output", ""), {reason});
}

}  // namespace

TEST_CASE("autograde: a submission that does not build: the reason and the log, as valid JSON") {
    const fs::path root = make_root("no-build", kHostileLog);
    const Outcome o = run_autograder(root);
    check_not_graded(o, "the submission does not build");
    check_log_kept(o.results.value("output", ""));
    fw::test::check_mentions(o.output, {"submitted as pipeline.cpp"});
    CHECK(read_text((root / "source/labs/00_pipeline/pipeline.cpp").string()) == "// submitted\n");
}

TEST_CASE("autograde: course grade failing is reported with its exit status and message") {
    const fs::path root = make_root("grade-fails", kBuilds);
    const Outcome o = run_autograder(root, "COURSE_TIMEOUT=0");
    check_not_graded(o, "course grade failed (exit status 2)");
    fw::test::check_mentions(o.results.value("output", ""), {"--timeout"});
}

TEST_CASE("autograde: a submitted file that cannot be put in place is reported") {
    const fs::path root = make_root("no-copy", kBuilds);
    fs::remove(root / "source/labs/00_pipeline/pipeline.cpp");
    fs::create_directories(root / "source/labs/00_pipeline/pipeline.cpp");
    check_not_graded(run_autograder(root), "the autograder could not copy");
}

TEST_CASE("autograde: a folder without its list of student files is reported") {
    const fs::path root = make_root("no-list", kBuilds);
    fs::remove(root / "source/student_files.txt");
    const Outcome o = run_autograder(root);
    check_not_graded(o, "the autograder failed");
    fw::test::check_mentions(o.results.value("output", ""), {"student_files.txt"});
}

TEST_CASE("autograde: when even the failed reports cannot be made, results.json still says why") {
    const fs::path root = make_root("no-reports", kHostileLog);
    write_text(root / "source/labs/00_pipeline/checkpoints.json", "{\"checkpoints\": [ broken");
    const Outcome o = run_autograder(root);
    CHECK(o.exit_code == 0);
    REQUIRE_MESSAGE(o.results.is_object(), "results.json is missing or not JSON");
    CHECK(o.results.value("score", -1.0) == 0.0);
    const std::string output = o.results.value("output", "");
    fw::test::check_mentions(output, {"the submission does not build", "checkpoints.json"});
    check_log_kept(output);
}

TEST_CASE("autograde: run_autograder writes a results.json of its own when course cannot run") {
    const fs::path root = fs::path(fw::test::out_dir()) / "no-course";
    fs::remove_all(root);
    fs::create_directories(root / "source");
    const Outcome o = run_autograder(root);
    CHECK(o.exit_code == 0);
    REQUIRE_MESSAGE(o.results.is_object(), "results.json is missing or not JSON");
    CHECK(o.results.value("score", -1.0) == 0.0);
    fw::test::check_mentions(o.results.value("output", ""), {"could not run"});
}
