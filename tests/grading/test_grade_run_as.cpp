// `course grade --run-as USER` (docs/contract.md, `course grade`): the child runs as
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
    struct stat st = {};
    stat(path.c_str(), &st);
    return st.st_mode & 07777;
}

}  // namespace

TEST_CASE("course grade --run-as nobody: full marks, references locked away") {
    skip_unless_possible();
    const Staged st = stage_for_run_as();
    const std::string tree = make_tree(st.dir + "/tree", false);
    const std::string out = st.dir + "/report";
    Graded g = grade(st.env + " LAB_ROOT=" + tree, "pipeline --run-as nobody --lab " + st.lab, out);
    CHECK(g.exit_code == 0);
    REQUIRE(g.results.is_object());
    CHECK(g.results["score"] == g.results["extra_data"]["max_score"]);
    CHECK(mode_of(tree + "/labs/00_pipeline/reference") == 0700);
    CHECK(mode_of(out) == 0755);
    CHECK(mode_of(out + "/pipeline") == 0700);  // it holds copies of the references
}

TEST_CASE("course grade --run-as nobody: the child cannot read a reference or write the report") {
    skip_unless_possible();
    const Staged st = stage_for_run_as();
    const std::string tree = make_tree(st.dir + "/tree", false);
    const std::string out = st.dir + "/report";
    const std::string reference = tree + "/labs/00_pipeline/reference/order_depth.png";
    REQUIRE(fs::exists(reference));
    Graded g =
        grade(st.env + " LAB_ROOT=" + tree +
                  " FAKE_LAB_TARGET=pipeline FAKE_LAB_MODE=snoop FAKE_LAB_SNOOP_READ=" + reference +
                  " FAKE_LAB_SNOOP_WRITE=" + out,
              "pipeline --run-as nobody --lab " + st.fake, out);
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
    const Staged st = stage_for_run_as();
    const std::string tree = make_tree(st.dir + "/tree", false);
    const std::string out = st.dir + "/open";
    fs::remove_all(out);
    fs::create_directories(out);
    chmod(out.c_str(), 0777);
    const fw::test::CommandResult r =
        fw::test::run_command(st.env + " LAB_ROOT=" + tree + " " + course() +
                              " grade pipeline --run-as nobody --lab " + st.lab + " --out " + out);
    CHECK(r.exit_code == 2);
    fw::test::check_mentions(r.output, {"could write the output directory", out});
}

TEST_CASE("course grade --run-as nobody --shader-cache: each lab gets its own writable copy") {
    skip_unless_possible();
    const Staged st = stage_for_run_as();
    const std::string tree = make_tree(st.dir + "/tree", false);
    const std::string cache = st.dir + "/shader-cache";
    const fw::test::CommandResult warm =
        fw::test::run_command(st.env + " LAB_ROOT=" + tree + " " + course() + " warm-cache " +
                              cache + " pipeline --lab " + st.lab);
    INFO(warm.output);
    REQUIRE(warm.exit_code == 0);
    fw::test::check_mentions(warm.output, {"warmed pipeline", "shader cache in " + cache});
    chmod(cache.c_str(), 0700);  // root's, as grading/platforms/gradescope/setup.sh leaves it
    int seeded = 0;
    for (const auto& e : fs::recursive_directory_iterator(cache)) seeded += e.is_regular_file();
    REQUIRE(seeded > 0);

    const std::string out = st.dir + "/report";
    const std::string said = st.dir + "/said/cache.txt";  // where the fake, as nobody, may write
    fs::create_directories(st.dir + "/said");
    chmod((st.dir + "/said").c_str(), 0777);
    Graded g = grade(st.env + " LAB_ROOT=" + tree + " FAKE_LAB_REAL_COPY=" + st.lab +
                         " FAKE_LAB_TARGET=pipeline FAKE_LAB_MODE=cache FAKE_LAB_REPORT=" + said,
                     "pipeline --run-as nobody --lab " + st.fake + " --shader-cache " + cache, out);
    CHECK(g.exit_code == 0);
    REQUIRE(g.results.is_object());
    CHECK(g.results["score"] == g.results["extra_data"]["max_score"]);
    // The child's cache is a copy inside its own work directory, every file
    // of it the user's to write; what it planted there never reaches the seed.
    const std::string report = fw::test::read_text(said);
    fw::test::check_mentions(
        report, {"inside the work directory", "cache: " + std::to_string(seeded) + " of " +
                                                  std::to_string(seeded) + " files writable"});
    CHECK(!fs::exists(cache + "/planted.txt"));
    int after = 0;
    for (const auto& e : fs::recursive_directory_iterator(cache)) after += e.is_regular_file();
    CHECK(after == seeded);
}
