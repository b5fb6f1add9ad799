// `course grade-class` and `course merge-class` on real classes: folders,
// archives, git repositories and Gradescope's export of lab 1's file, with
// submissions that do not build, hang or attack beside good ones; the
// gradebook read back with Python's csv module; resumption; shards merged.
#include <doctest/doctest.h>

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <string>

#include "framework/text.hpp"
#include "tests/grading/grade_support.hpp"
#include "tests/support/test_support.hpp"

namespace {

namespace fs = std::filesystem;
using grade_test::course;
using nlohmann::json;

const char* const kFile = "labs/01_transforms/transforms_math.cpp";
const char* const kArmFile = "labs/02_robot_arm/arm.cpp";

std::string solution() { return fw::test::read_text(fw::test::source_dir() + "/" + kFile); }

// The solution with `find` (once in it) replaced.
std::string changed(const std::string& find, const std::string& replace) {
    std::string text = solution();
    const size_t at = text.find(find);
    REQUIRE(at != std::string::npos);
    return text.replace(at, find.size(), replace);
}

fw::test::CommandResult run(const std::string& command) {
    const fw::test::CommandResult r = fw::test::run_command(command);
    MESSAGE(command << ": exit " << r.exit_code << "\n" << r.output);
    return r;
}

std::string q(const fs::path& p) { return fw::shell_quote(p.string()); }

// python3 -c SCRIPT ARGS...: archives made by Python's own zipfile and tarfile.
std::string python(const std::string& script, const std::vector<std::string>& args) {
    std::string command = "python3 -c " + fw::shell_quote(script);
    for (const std::string& a : args) command += " " + fw::shell_quote(a);
    return command;
}

// grades.csv as Python's csv module reads it: one map per row.
std::vector<std::map<std::string, std::string>> read_csv(const fs::path& file) {
    const fw::test::CommandResult r = fw::test::run_command(
        "python3 -c 'import csv, json, sys; "
        "print(json.dumps(list(csv.DictReader(open(sys.argv[1], newline=\"\")))))' " +
        q(file));
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    std::vector<std::map<std::string, std::string>> rows;
    for (const json& row : json::parse(r.output)) rows.push_back(row);
    return rows;
}

std::map<std::string, std::string> row_of(const fs::path& out, const std::string& submission) {
    for (const auto& row : read_csv(out / "grades.csv"))
        if (row.at("submission") == submission) return row;
    FAIL("no row for " << submission);
    return {};
}

std::string grade_class(const fs::path& subs, const fs::path& out, const std::string& more,
                        int expected_exit) {
    const fw::test::CommandResult r = run(course() + " grade-class " + q(subs) + " --out " +
                                          q(out) + " --labs transforms --jobs 2 " + more);
    CHECK(r.exit_code == expected_exit);
    return r.output;
}

// A git repository at `dir` with one commit per text of kFile, each at its time.
void git_repository(const fs::path& dir,
                    const std::vector<std::pair<std::string, std::string>>& commits) {
    fs::create_directories(dir);
    REQUIRE(run("git -C " + q(dir) + " init -q").exit_code == 0);
    for (const auto& [time, text] : commits) {
        fw::test::write_text((dir / kFile).string(), text);
        const std::string env = "GIT_AUTHOR_DATE=" + time + " GIT_COMMITTER_DATE=" + time +
                                " GIT_AUTHOR_NAME=s GIT_AUTHOR_EMAIL=s@example.org "
                                "GIT_COMMITTER_NAME=s GIT_COMMITTER_EMAIL=s@example.org ";
        REQUIRE(run(env + "git -C " + q(dir) + " add -A && " + env + "git -C " + q(dir) +
                    " commit -qm work")
                    .exit_code == 0);
    }
}

std::string head_of(const fs::path& repo, const std::string& rev) {
    std::string id = fw::test::run_command("git -C " + q(repo) + " rev-parse " + rev).output;
    while (!id.empty() && (id.back() == '\n' || id.back() == ' ')) id.pop_back();
    return id;
}

}  // namespace

TEST_CASE("grade-class: every layout, with submissions that fail beside good ones") {
    const fs::path root = fw::test::out_dir(), subs = root / "subs", work = root / "work";
    fs::remove_all(root / "subs");
    fs::remove_all(work);
    // alice: a folder with the solution at its repository path.
    fw::test::write_text((subs / "alice" / kFile).string(), solution());
    // bob: a zip of a folder holding the file alone (uploads may be flat).
    fw::test::write_text(
        (work / "bob" / "transforms_math.cpp").string(),
        changed("return from_rows(s.x, 0, 0, 0,", "return from_rows(s.y, 0, 0, 0,"));
    REQUIRE(
        run(python(
                "import shutil, sys; shutil.make_archive(sys.argv[1], 'zip', sys.argv[2], 'bob')",
                {(subs / "bob").string(), work.string()}))
            .exit_code == 0);
    // carol: a .tar.gz whose file does not compile.
    fw::test::write_text((work / "carol" / "transforms_math.cpp").string(),
                         changed("return from_rows(s.x, 0, 0, 0,", "return from_rows(s.x, 0, 0,"));
    REQUIRE(run(python("import shutil, sys; shutil.make_archive(sys.argv[1], 'gztar', sys.argv[2], "
                       "'carol')",
                       {(subs / "carol").string(), work.string()}))
                .exit_code == 0);
    // dan: a git repository, right before the deadline, broken after it.
    git_repository(subs / "dan",
                   {{"2026-01-01T10:00:00Z", solution()}, {"2026-01-02T10:00:00Z", "not C++\n"}});
    // eve: hangs in scale().
    fw::test::write_text((subs / "eve" / "transforms_math.cpp").string(),
                         changed("return from_rows(s.x, 0, 0, 0,",
                                 "for (volatile int i = 0; i >= 0; i = i * 0) {\n    }\n"
                                 "    return from_rows(s.x, 0, 0, 0,"));
    // mallory: a link to a file outside, and an archive that climbs out.
    fs::create_directories(subs / "mallory");
    fs::create_symlink("/etc/passwd", subs / "mallory" / "transforms_math.cpp");
    REQUIRE(run(python("import sys, zipfile; z = zipfile.ZipFile(sys.argv[1], 'w'); "
                       "z.writestr('trudy/transforms_math.cpp', 'int x;'); "
                       "z.writestr('../../deep/evil.cpp', 'int escaped;'); z.close()",
                       {(subs / "trudy.zip").string()}))
                .exit_code == 0);

    const fs::path out = root / "out";
    fs::remove_all(out);
    const std::string said =
        grade_class(subs, out, "--timeout 5 --deadline 2026-01-01T12:00:00Z", 1);
    CHECK(said.find("7 of 7 submissions") != std::string::npos);

    const auto alice = row_of(out, "alice");
    const std::string full = alice.at("max");
    CHECK(std::stod(full) > 0);
    CHECK(alice.at("transforms") == full);
    CHECK(alice.at("status") == "graded");
    CHECK(alice.at("late") == "no");
    // bob's scale is wrong: what the same file gets alone.
    const auto bob = row_of(out, "bob");
    const fs::path alone = root / "alone";
    fs::remove_all(alone);
    fs::create_directories(alone / "bob");
    fs::copy_file(work / "bob" / "transforms_math.cpp", alone / "bob" / "transforms_math.cpp");
    grade_class(alone, root / "alone-out", "", 0);
    CHECK(bob.at("transforms") == row_of(root / "alone-out", "bob").at("transforms"));
    CHECK(std::stod(bob.at("transforms")) < std::stod(full));
    CHECK(std::stod(bob.at("transforms")) > 0);
    // carol: the compiler's first error, at the student's own path.
    const auto carol = row_of(out, "carol");
    CHECK(carol.at("transforms") == "0");
    CHECK(carol.at("status").rfind("does not build: " + std::string(kFile) + ":", 0) == 0);
    CHECK(fw::test::read_text((out / "students/carol/transforms/summary.txt").string())
              .find("does not build") != std::string::npos);
    // dan: the commit before the deadline, and late for the one after.
    const auto dan = row_of(out, "dan");
    CHECK(dan.at("transforms") == full);
    CHECK(dan.at("graded") == head_of(subs / "dan", "HEAD~1"));
    CHECK(dan.at("late") == "yes");
    // eve: her own timeout, nobody else's.
    CHECK(row_of(out, "eve").at("status") == "transforms: timed out after 5 s");
    // mallory's link is not followed: the starting version stands for it.
    const auto mallory = row_of(out, "mallory");
    CHECK(mallory.at("missing") == "1");
    CHECK(fw::test::read_text((out / "students/mallory/files.txt").string())
              .find("missing: the release's starting version graded") != std::string::npos);
    // trudy's archive is refused whole, and nothing escaped.
    const auto trudy = row_of(out, "trudy");
    CHECK(trudy.at("status").find("a path outside its own folder") != std::string::npos);
    CHECK(trudy.at("transforms") == "0");
    CHECK(!fs::exists(out / ".class" / "deep"));
    CHECK(!fs::exists(out / ".class" / "work" / "deep"));
    CHECK(!fs::exists(out / "deep"));
}

TEST_CASE("grade-class: Gradescope's export, its groups and late submissions") {
    const fs::path root = fw::test::out_dir(), subs = root / "export", out = root / "out";
    fs::remove_all(subs);
    fs::remove_all(out);
    fw::test::write_text((subs / "submission_101" / kFile).string(), solution());
    fw::test::write_text((subs / "submission_102" / "transforms_math.cpp").string(), solution());
    fw::test::write_text((subs / "submission_metadata.yml").string(),
                         "submission_101:\n"
                         "  :submitters:\n"
                         "  - :name: Ada Lovelace, Countess\n"
                         "    :sid: '1001'\n"
                         "    :email: ada@example.org\n"
                         "  - :name: Charles \"C\" Babbage\n"
                         "    :sid: '1002'\n"
                         "    :email: charles@example.org\n"
                         "  :created_at: 2026-01-01 10:00:00.123456000 +01:00\n"
                         "  :score: 0.0\n"
                         "submission_102:\n"
                         "  :submitters:\n"
                         "  - :name: '=cmd|calc'\n"
                         "    :sid: '1003'\n"
                         "    :email: grace@example.org\n"
                         "  :created_at: 2026-01-02 10:00:00.000000000 +00:00\n");
    grade_class(subs, out, "--deadline 2026-01-01T12:00:00Z", 0);
    const auto rows = read_csv(out / "grades.csv");
    REQUIRE(rows.size() == 3);  // a row per student: the group's two share theirs
    CHECK(rows[0].at("id") == "1001");
    CHECK(rows[0].at("name") == "Ada Lovelace, Countess");
    CHECK(rows[1].at("name") == "Charles \"C\" Babbage");
    CHECK(rows[1].at("submission") == "submission_101");
    CHECK(rows[1].at("transforms") == rows[1].at("max"));
    CHECK(rows[0].at("late") == "no");
    // A spreadsheet would run it as a formula: kept as text.
    CHECK(rows[2].at("name") == "'=cmd|calc");
    CHECK(rows[2].at("late") == "yes");
    CHECK(rows[2].at("transforms") == rows[2].at("max"));
}

TEST_CASE("grade-class: a second run grades only what changed; shards merge to one run") {
    const fs::path root = fw::test::out_dir(), subs = root / "subs", out = root / "out";
    fs::remove_all(subs);
    fs::remove_all(out);
    for (const char* name : {"ann", "ben", "cat"})
        fw::test::write_text((subs / name / kFile).string(), solution());
    fw::test::write_text((subs / "ben" / kArmFile).string(),
                         fw::test::read_text(fw::test::source_dir() + "/" + kArmFile));
    auto labs = [&](const fs::path& to, const std::string& more) {
        return run(course() + " grade-class " + q(subs) + " --out " + q(to) +
                   " --labs transforms,robot-arm --jobs 2 " + more);
    };
    REQUIRE(labs(out, "").exit_code == 0);
    const std::string first = fw::test::read_text((out / "grades.csv").string());
    const auto kept = fs::last_write_time(out / "students/ann/transforms/class.json");
    // Nothing changed: nothing graded.
    fw::test::CommandResult again = labs(out, "");
    CHECK(again.output.find("(0 graded, 3 unchanged)") != std::string::npos);
    CHECK(fw::test::read_text((out / "grades.csv").string()) == first);
    // ann's arm changes: her robot-arm alone is graded again.
    fw::test::write_text((subs / "ann" / kArmFile).string(),
                         fw::test::read_text(fw::test::source_dir() + "/" + kArmFile) + "\n");
    again = labs(out, "");
    CHECK(again.output.find("(1 graded, 2 unchanged)") != std::string::npos);
    CHECK(fs::last_write_time(out / "students/ann/transforms/class.json") == kept);
    CHECK(fs::last_write_time(out / "students/ann/robot-arm/class.json") > kept);
    const std::string single = fw::test::read_text((out / "grades.csv").string());

    // Three slices at once, as three machines would run them, merged.
    const std::string slices = "for k in 1 2 3; do " + course() + " grade-class " + q(subs) +
                               " --out " + q(root) +
                               "/slice$k --labs transforms,robot-arm "
                               "--jobs 1 --shard $k/3 & done; wait";
    for (int k = 1; k <= 3; ++k) fs::remove_all(root / ("slice" + std::to_string(k)));
    run(slices);
    const fw::test::CommandResult merged =
        run(course() + " merge-class " + q(root / "merged") + " " + q(root / "slice1") + " " +
            q(root / "slice2") + " " + q(root / "slice3"));
    CHECK(merged.exit_code == 0);
    CHECK(fw::test::read_text((root / "merged/grades.csv").string()) == single);
    CHECK(fs::exists(root / "merged/students/cat/robot-arm/summary.txt"));
    // A slice given twice is refused.
    CHECK(run(course() + " merge-class " + q(root / "twice") + " " + q(root / "slice1") + " " +
              q(root / "slice1"))
              .exit_code == 2);
}

TEST_CASE("grade-class: a lab whose file does not compile costs that lab alone") {
    const fs::path root = fw::test::out_dir(), subs = root / "subs", out = root / "out";
    fs::remove_all(subs);
    fs::remove_all(out);
    const std::string arm = fw::test::read_text(fw::test::source_dir() + "/" + kArmFile);
    // both: the two labs' solutions; broken: lab 1's file does not compile.
    fw::test::write_text((subs / "both" / kFile).string(), solution());
    fw::test::write_text((subs / "both" / kArmFile).string(), arm);
    fw::test::write_text((subs / "broken" / kFile).string(),
                         changed("return from_rows(s.x, 0, 0, 0,", "return from_rows(s.x, 0, 0,"));
    fw::test::write_text((subs / "broken" / kArmFile).string(), arm);
    auto labs = [&](int expected_exit) {
        const fw::test::CommandResult r = run(course() + " grade-class " + q(subs) + " --out " +
                                              q(out) + " --labs transforms,robot-arm --jobs 2");
        CHECK(r.exit_code == expected_exit);
        return r.output;
    };
    labs(1);
    const auto both = row_of(out, "both"), broken = row_of(out, "broken");
    CHECK(both.at("status") == "graded");
    CHECK(std::stod(both.at("robot-arm")) > 0);
    // 0 for the lab that does not compile, with the compiler's first error...
    CHECK(broken.at("transforms") == "0");
    CHECK(broken.at("status").rfind("does not build: " + std::string(kFile) + ":", 0) == 0);
    CHECK(fw::test::read_text((out / "students/broken/transforms/summary.txt").string())
              .find("this lab does not build") != std::string::npos);
    const json results = json::parse(
        fw::test::read_text((out / "students/broken/transforms/results.json").string()));
    fw::test::check_mentions(results.value("output", ""), {kFile, "error"});
    // ...and the other lab's points as the solution's: graded with lab 1 at its starting code.
    CHECK(broken.at("robot-arm") == both.at("robot-arm"));
    CHECK(json::parse(fw::test::read_text(
              (out / "students/broken/robot-arm/class.json").string()))["status"] == "graded");
    // Fixed, the lab is graded again alone; the other lab's grade stands.
    const auto kept = fs::last_write_time(out / "students/broken/robot-arm/class.json");
    fw::test::write_text((subs / "broken" / kFile).string(), solution());
    CHECK(labs(0).find("(1 graded, 1 unchanged)") != std::string::npos);
    CHECK(row_of(out, "broken").at("transforms") == both.at("transforms"));
    CHECK(fs::last_write_time(out / "students/broken/robot-arm/class.json") == kept);
}
