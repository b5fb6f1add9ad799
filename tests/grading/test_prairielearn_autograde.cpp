// grade.sh and `course autograde --layout prairielearn` where they cannot
// grade, on the small fake tree of the autograde tests (gradescope_support.hpp:
// its `lab` target is a shell script, so nothing of the repository is built):
// the submission in /grade/student does not build, course grade fails,
// course cannot run at all, and the layout's options are wrong. Each time
// results.json follows PrairieLearn's schema and says it was not gradable.
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "framework/text.hpp"
#include "tests/grading/grade_support.hpp"
#include "tests/grading/gradescope_support.hpp"
#include "tests/grading/prairielearn_support.hpp"
#include "tests/support/test_support.hpp"

namespace {

namespace fs = std::filesystem;
using fw::shell_quote;
using fw::test::read_text;
using nlohmann::json;

// make_root()'s tree in PrairieLearn's places: source/ is the image's course
// and holds grade.sh beside lab 0's checkpoints and references (its own
// serverFilesCourse folder), and the submission is in student/.
fs::path make_grade_root(const std::string& name, const std::string& lab_script) {
    const fs::path root = gradescope_test::make_root("prairielearn-" + name, lab_script);
    fs::rename(root / "submission", root / "student");
    fs::copy_file(fs::path(fw::test::source_dir()) / "grading/platforms/prairielearn/grade.sh",
                  root / "source/grade.sh");
    return root;
}

struct Outcome {
    int exit_code = -1;
    std::string output;  // grade.sh's
    json results;        // results/results.json; discarded (not an object) when not JSON
};

Outcome grade_sh(const fs::path& root, const std::string& env = "",
                 const std::string& course = "") {
    const auto r = fw::test::run_command(
        "env -u LAB_ROOT -u LAB_SHADER_DIR PL_GRADE_ROOT=" + shell_quote(root.string()) +
        " PL_COURSE_DIR=" + shell_quote(course.empty() ? (root / "source").string() : course) +
        " AUTOGRADER_USER=no-such-user-of-the-autograde-test " + env + " bash " +
        shell_quote((root / "source/grade.sh").string()) + " pipeline");
    MESSAGE("grade.sh: exit " << r.exit_code << "\n" << r.output);
    Outcome o{r.exit_code, r.output, json()};
    o.results = json::parse(read_text((root / "results/results.json").string()), nullptr, false);
    return o;
}

// Exit 0, and results.json not gradable, with `reason` in its message and format errors.
void check_not_gradable(const Outcome& o, const std::string& reason) {
    CHECK(o.exit_code == 0);
    REQUIRE_MESSAGE(o.results.is_object(), "results.json is missing or not JSON");
    prairielearn_test::check_schema(o.results);
    CHECK(o.results["gradable"] == false);
    fw::test::check_mentions(o.results.value("message", ""), {reason});
    fw::test::check_mentions(o.results["format_errors"][0].get<std::string>(), {reason});
}

}  // namespace

TEST_CASE("autograde prairielearn: a submission that does not build is not gradable, log kept") {
    const fs::path root = make_grade_root("no-build", gradescope_test::kHostileLog);
    const Outcome o = grade_sh(root);
    check_not_gradable(o, "the submission does not build");
    gradescope_test::check_log_kept(o.results.value("output", ""));
    fw::test::check_mentions(o.output, {"submitted as pipeline.cpp", "grade.sh: "});
    CHECK(read_text((root / "source/labs/00_pipeline/pipeline.cpp").string()) == "// submitted\n");
}

TEST_CASE("autograde prairielearn: course grade failing is not gradable, with its message") {
    const fs::path root = make_grade_root("grade-fails", gradescope_test::kBuilds);
    const Outcome o = grade_sh(root, "COURSE_TIMEOUT=0");
    check_not_gradable(o, "course grade failed (exit status 2)");
    fw::test::check_mentions(o.results.value("output", ""), {"--timeout"});
    fw::test::check_mentions(o.output, {"course grade --timeout 0 --format prairielearn pipeline"});
}

TEST_CASE("autograde prairielearn: grade.sh writes its own results.json when course cannot run") {
    const fs::path root = make_grade_root("no-course", gradescope_test::kBuilds);
    const Outcome o = grade_sh(root, "", (root / "nowhere").string());
    check_not_gradable(o, "could not run");
    fw::test::check_mentions(o.output, {"left no results.json"});
}

TEST_CASE("autograde prairielearn: --data is required, and --source belongs to it") {
    const fs::path root = make_grade_root("usage", gradescope_test::kBuilds);
    auto r =
        fw::test::run_command(grade_test::course() + " autograde --layout prairielearn --root " +
                              shell_quote(root.string()));
    CHECK(r.exit_code == 2);
    fw::test::check_mentions(r.output, {"--data", "serverFilesCourse"});
    r = fw::test::run_command(grade_test::course() + " autograde --source /course --root " +
                              shell_quote(root.string()));
    CHECK(r.exit_code == 2);
    fw::test::check_mentions(r.output, {"--source and --data belong to --layout prairielearn"});
    r = fw::test::run_command(grade_test::course() + " grade --format moodle");
    CHECK(r.exit_code == 2);
    fw::test::check_mentions(r.output, {"--format", "gradescope", "prairielearn"});
}
