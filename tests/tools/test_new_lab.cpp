// docs/staff.md, Adding a lab, taken at its word: in a copy of this repository,
// lab 0 is copied under a new number and name (labs/90_warmup/ and
// shaders/90_warmup/, its C++ namespace renamed so that both labs link into
// one `lab`), and nothing else is touched. The new lab must then list,
// render, grade with full marks, appear in the student release and pass its
// own tests. The copy builds a tree of its own (minutes), so the test has
// the label `newlab`.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "framework/text.hpp"
#include "tests/grading/tree_support.hpp"
#include "tests/support/test_support.hpp"

namespace fs = std::filesystem;

namespace {

using fw::shell_quote;
using fw::test::read_text;

// Runs `command`, logging its time and exit status, and its output's tail
// when it fails.
fw::test::CommandResult run(const std::string& command) {
    const auto start = std::chrono::steady_clock::now();
    fw::test::CommandResult r = fw::test::run_command(command);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::printf("[%5.1f s] exit %d: %s\n", seconds, r.exit_code, command.c_str());
    std::fflush(stdout);
    if (r.exit_code != 0)
        MESSAGE("output (tail):\n"
                << r.output.substr(r.output.size() > 6000 ? r.output.size() - 6000 : 0));
    return r;
}

// What git says has changed in `tree` since its commit, one line per path.
std::string changes(const fs::path& tree) {
    const fw::test::CommandResult r = run("git -C " + shell_quote(tree.string()) +
                                          " status --porcelain --untracked-files=normal");
    REQUIRE(r.exit_code == 0);
    return r.output;
}

// A copy of this repository's files (tracked, and new ones git does not
// ignore), committed, so that `git status` shows whatever is touched later.
void copy_repository(const fs::path& tree) {
    fs::remove_all(tree);
    fs::create_directories(tree);
    const std::string src = shell_quote(fw::test::source_dir());
    REQUIRE(run("git -C " + src +
                " ls-files -z --cached --others --exclude-standard | "
                "tar -C " +
                src + " --null -T - -cf - | tar -C " + shell_quote(tree.string()) + " -xf -")
                .exit_code == 0);
    const std::string git =
        "git -C " + shell_quote(tree.string()) + " -c user.name=test -c user.email=test@localhost ";
    REQUIRE(run(git + "init -q && " + git + "add -A && " + git + "commit -q -m copy").exit_code ==
            0);
    REQUIRE(changes(tree).empty());
}

// Copies lab 0 to labs/90_warmup and shaders/90_warmup, renaming its C++
// namespace: the only edit a course's staff makes to a copied lab.
void copy_lab(const fs::path& tree) {
    const std::string t = shell_quote(tree.string());
    REQUIRE(run("cd " + t +
                " && cp -r labs/00_pipeline labs/90_warmup && "
                "cp -r shaders/00_pipeline shaders/90_warmup && "
                "find labs/90_warmup -name '*.cpp' -o -name '*.hpp' | xargs sed -i "
                "-e 's/namespace pipeline/namespace warmup/g' -e 's/pipeline::/warmup::/g'")
                .exit_code == 0);
}

}  // namespace

TEST_CASE("new lab: a copy of lab 0 as labs/90_warmup lists, renders, grades, releases, tests") {
    const fs::path out = fw::test::out_dir();
    const fs::path tree = out / "tree";
    fw::test::remove_when_passed(out.string());
    copy_repository(tree);
    copy_lab(tree);
    // Only the two new folders: no other file names the lab.
    CHECK(changes(tree) == "?? labs/90_warmup/\n?? shaders/90_warmup/\n");
    tree_test::build_tree(tree, "lab course test_warmup");
    const std::string bin = shell_quote((tree / "build/bin").string()) + "/";

    // Listed, with its number and id from the folder's name.
    const fw::test::CommandResult list = run(bin + "lab list --json");
    REQUIRE(list.exit_code == 0);
    const nlohmann::json labs = nlohmann::json::parse(list.output);
    bool listed = false;
    for (const nlohmann::json& lab : labs)
        listed = listed || (lab.value("number", -1) == 90 && lab.value("name", "") == "warmup");
    CHECK_MESSAGE(listed, "lab list: " << list.output);

    // Renders its checkpoints exactly as the lab it was copied from.
    for (const char* lab : {"warmup", "pipeline"})
        CHECK(run(bin + "lab render " + lab + " --checkpoint flat -o " +
                  shell_quote((out / (std::string(lab) + ".png")).string()))
                  .exit_code == 0);
    CHECK(read_text((out / "warmup.png").string()) == read_text((out / "pipeline.png").string()));

    // Grades with full marks against its own references and checkpoints.
    const fs::path grade = out / "grade";
    const fw::test::CommandResult graded =
        run("LAB_ROOT=" + shell_quote(tree.string()) + " " + bin + "course grade warmup --out " +
            shell_quote(grade.string()));
    CHECK(graded.exit_code == 0);
    const nlohmann::json results =
        nlohmann::json::parse(read_text((grade / "results.json").string()));
    CHECK(results.at("score") == results.at("extra_data").at("max_score"));
    CHECK(results.at("extra_data").at("max_score").get<double>() > 0);

    // Not released while git does not track it, and the release says so...
    const fs::path release = out / "release";
    fs::remove_all(release);
    const std::string release_command = "cd " + shell_quote(tree.string()) + " && " + bin +
                                        "course release --out " + shell_quote(release.string());
    const fw::test::CommandResult untracked = run(release_command);
    CHECK(untracked.exit_code == 0);
    CHECK(untracked.output.find("labs/90_warmup/pipeline.cpp") != std::string::npos);
    CHECK(untracked.output.find("git does not track it") != std::string::npos);
    CHECK_FALSE(fs::exists(release / "labs/90_warmup"));

    // ...and released to students, without its solutions, once added.
    const std::string git = "git -C " + shell_quote(tree.string()) + " ";
    REQUIRE(run(git + "add labs/90_warmup shaders/90_warmup").exit_code == 0);
    fs::remove_all(release);
    CHECK(run(release_command).exit_code == 0);
    const std::string student = read_text((release / "labs/90_warmup/pipeline.cpp").string());
    CHECK(student.find("TODO") != std::string::npos);
    CHECK(student.find("BEGIN SOLUTION") == std::string::npos);
    CHECK(read_text((release / "labs/90_warmup/pipeline_lab.cpp").string())
              .find("FW_LAB(PipelineLab)") != std::string::npos);
    CHECK(fs::exists(release / "shaders/90_warmup/pipeline.vert"));

    // Passes its own tests (those found in labs/90_warmup/tests/).
    CHECK(run("ctest --test-dir " + shell_quote((tree / "build").string()) +
              " -R '^warmup\\.' --output-on-failure")
              .exit_code == 0);

    // Building, grading and releasing wrote nothing into the tree's files:
    // git shows only the new lab's files, added.
    const std::string after = changes(tree);
    CHECK(!after.empty());
    std::istringstream lines(after);
    for (std::string line; std::getline(lines, line);) {
        CAPTURE(line);
        CHECK((line.empty() || line.rfind("A  labs/90_warmup/", 0) == 0 ||
               line.rfind("A  shaders/90_warmup/", 0) == 0));
    }
}
