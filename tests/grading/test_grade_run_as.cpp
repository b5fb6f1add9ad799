// `course grade --run-as USER` (SPEC.md, `course grade`): the child runs as
// that user and can neither read a reference nor write a result. Needs root
// and a user `nobody`; skips (exit 77) with the reason otherwise.
#include <pwd.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>

#include "tests/grading/grade_support.hpp"

using namespace grade_test;

namespace {

void skip_unless_possible() {
    if (geteuid() != 0) {
        std::printf("SKIP: --run-as needs root; this test runs as uid %u\n", unsigned(geteuid()));
        std::exit(77);
    }
    if (!getpwnam("nobody")) {
        std::printf("SKIP: there is no user 'nobody' to run the child as\n");
        std::exit(77);
    }
}

mode_t mode_of(const std::string& path) {
    struct stat st {};
    stat(path.c_str(), &st);
    return st.st_mode & 07777;
}

}  // namespace

TEST_CASE("course grade --run-as nobody: full marks, references locked away") {
    skip_unless_possible();
    const std::string tree = make_tree(fw::test::out_dir() + "/tree", false);
    const std::string out = fw::test::out_dir() + "/report";
    Graded g = grade("LAB_ROOT=" + tree, "pipeline --run-as nobody", out);
    CHECK(g.exit_code == 0);
    REQUIRE(g.results.is_object());
    CHECK(g.results["score"] == g.results["max_score"]);
    CHECK(mode_of(tree + "/labs/00_pipeline/reference") == 0700);
    CHECK(mode_of(out) == 0755);
    CHECK(mode_of(out + "/pipeline") == 0700);  // it holds copies of the references
}

TEST_CASE("course grade --run-as nobody: the child cannot read a reference or write the report") {
    skip_unless_possible();
    const std::string tree = make_tree(fw::test::out_dir() + "/tree", false);
    const std::string out = fw::test::out_dir() + "/report";
    const std::string reference = tree + "/labs/00_pipeline/reference/order_depth.png";
    REQUIRE(fs::exists(reference));
    Graded g =
        grade("LAB_ROOT=" + tree +
                  " FAKE_LAB_TARGET=pipeline FAKE_LAB_MODE=snoop FAKE_LAB_SNOOP_READ=" + reference +
                  " FAKE_LAB_SNOOP_WRITE=" + out,
              "pipeline --run-as nobody --lab " + fake_lab(), out);
    CHECK(g.exit_code == 1);
    // The fake's own report of what it tried, from the log course prints.
    fw::test::check_mentions(g.output,
                             {"exit status 3", "snoop: read " + reference + ": Permission denied",
                              "snoop: write " + out + "/planted.txt: Permission denied"});
    CHECK(g.output.find("ALLOWED") == std::string::npos);
    CHECK(!fs::exists(out + "/planted.txt"));
}

TEST_CASE("course grade --run-as: an output directory the user could write is refused") {
    skip_unless_possible();
    const std::string tree = make_tree(fw::test::out_dir() + "/tree", false);
    const std::string out = fw::test::out_dir() + "/open";
    fs::remove_all(out);
    fs::create_directories(out);
    chmod(out.c_str(), 0777);
    const fw::test::CommandResult r = fw::test::run_command(
        "LAB_ROOT=" + tree + " " + course() + " grade pipeline --run-as nobody --out " + out);
    CHECK(r.exit_code == 2);
    fw::test::check_mentions(r.output, {"could write the output directory", out});
}
