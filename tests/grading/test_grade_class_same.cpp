// Same files, same points: a class whose submissions earn partial credit on
// unit checks (random cases drawn from the course's seed and the checkpoint's
// name, grading/judge/course_seed.hpp) graded twice, in three layouts
// (folders, zip archives, git repositories) and in three shards merged: every
// grades.csv is the same bytes, and so is each student's report of the lab.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "framework/text.hpp"
#include "tests/grading/grade_support.hpp"
#include "tests/support/test_support.hpp"

namespace {

namespace fs = std::filesystem;
using grade_test::course;

const char* const kFile = "labs/01_transforms/transforms_math.cpp";

std::string q(const fs::path& p) { return fw::shell_quote(p.string()); }

fw::test::CommandResult run(const std::string& command) {
    const fw::test::CommandResult r = fw::test::run_command(command);
    MESSAGE(command << ": exit " << r.exit_code << "\n" << r.output);
    return r;
}

// The solution with `find` (once in it) replaced.
std::string changed(const std::string& find, const std::string& replace) {
    std::string text = fw::test::read_text(fw::test::source_dir() + "/" + kFile);
    const size_t at = text.find(find);
    REQUIRE(at != std::string::npos);
    return text.replace(at, find.size(), replace);
}

// The class: each student's file. ann and ben lose some of their unit
// checks' random cases (a sign dropped: about half of them), cid none.
std::map<std::string, std::string> class_files() {
    return {{"ann", changed("return from_rows(1, 0, 0, t.x,",
                            "return from_rows(1, 0, 0, std::fabs(t.x),")},
            {"ben", changed("                     0, s.y, 0, 0,",
                            "                     0, std::fabs(s.y), 0, 0,")},
            {"cid", changed("", "")}};
}

// summary.txt without the seconds it measured (the lab table's last column,
// the Total line's time, the CPU line), which are the machine's, not the grade's.
std::string without_seconds(const std::string& text) {
    static const std::regex table_row("^(\\S+ +\\S+/\\S+ +\\S+/\\S+ +.*\\S) +[0-9.]+$");
    static const std::regex total_time(", [0-9.]+ s\\b");
    std::stringstream lines(text);
    std::string out;
    for (std::string line; std::getline(lines, line);)
        if (line.rfind("CPU: ", 0) != 0)
            out += std::regex_replace(std::regex_replace(line, table_row, "$1"), total_time, "") +
                   "\n";
    return out;
}

// The files of a graded class that must not change from run to run: its
// grades.csv and each student's summary.txt of the lab, without seconds.
std::map<std::string, std::string> graded(const fs::path& out) {
    std::map<std::string, std::string> files;
    files["grades.csv"] = fw::test::read_text((out / "grades.csv").string());
    for (const char* student : {"ann", "ben", "cid"})
        files[std::string(student) + "/summary.txt"] = without_seconds(fw::test::read_text(
            (out / "students" / student / "transforms" / "summary.txt").string()));
    return files;
}

std::string grade_class(const fs::path& subs, const fs::path& out, const std::string& more = "") {
    fs::remove_all(out);
    const fw::test::CommandResult r = run(course() + " grade-class " + q(subs) + " --out " +
                                          q(out) + " --labs transforms --jobs 2 " + more);
    CHECK((r.exit_code == 0 || r.exit_code == 1));  // 1: a check failed
    return r.output;
}

}  // namespace

TEST_CASE("grade-class: the same files get the same points in every run, layout and shard") {
    const fs::path root = fw::test::out_dir();
    const std::map<std::string, std::string> files = class_files();
    // Folders, with the file at its repository path.
    const fs::path folders = root / "folders";
    fs::remove_all(folders);
    for (const auto& [student, text] : files)
        fw::test::write_text((folders / student / kFile).string(), text);
    // Zip archives of the same folders.
    const fs::path zips = root / "zips";
    fs::remove_all(zips);
    fs::create_directories(zips);
    for (const auto& [student, text] : files)
        REQUIRE(run("python3 -c " +
                    fw::shell_quote("import shutil, sys; shutil.make_archive(sys.argv[1], 'zip', "
                                    "sys.argv[2], sys.argv[3])") +
                    " " + q(zips / student) + " " + q(folders) + " " + student)
                    .exit_code == 0);
    // Git repositories, one commit each.
    const fs::path repos = root / "repos";
    fs::remove_all(repos);
    for (const auto& [student, text] : files) {
        const fs::path repo = repos / student;
        fw::test::write_text((repo / kFile).string(), text);
        const std::string env =
            "GIT_AUTHOR_DATE=2026-01-01T10:00:00Z GIT_COMMITTER_DATE=2026-01-01T10:00:00Z "
            "GIT_AUTHOR_NAME=s GIT_AUTHOR_EMAIL=s@example.org GIT_COMMITTER_NAME=s "
            "GIT_COMMITTER_EMAIL=s@example.org ";
        REQUIRE(run("git -C " + q(repo) + " init -q && " + env + "git -C " + q(repo) +
                    " add -A && " + env + "git -C " + q(repo) + " commit -qm work")
                    .exit_code == 0);
    }

    grade_class(folders, root / "first");
    const std::map<std::string, std::string> first = graded(root / "first");
    // Partial credit, so that a case drawn differently would show.
    const std::string csv = first.at("grades.csv");
    INFO(csv);
    // Each row: id,name,email,submission,transforms,total,max,... ann and
    // ben lose part of a unit check's points (a fraction of its random
    // cases), cid none.
    std::map<std::string, std::pair<double, double>> points;  // total, max
    std::stringstream rows(csv);
    std::string row;
    std::getline(rows, row);  // the header
    while (std::getline(rows, row)) {
        std::vector<std::string> f;
        std::stringstream fields(row);
        for (std::string x; std::getline(fields, x, ',');) f.push_back(x);
        REQUIRE(f.size() > 6);
        points[f[0]] = {std::stod(f[5]), std::stod(f[6])};
    }
    REQUIRE(points.size() == 3);
    for (const char* partial : {"ann", "ben"}) {
        CHECK(points[partial].first > 0);
        CHECK(points[partial].first < points[partial].second);
        CHECK(points[partial].first != std::floor(points[partial].first));  // a tenth of a point
    }
    CHECK(points["cid"].first == points["cid"].second);

    grade_class(folders, root / "second");
    CHECK(graded(root / "second") == first);
    for (const fs::path& subs : {zips, repos}) {
        grade_class(subs, root / "layout");
        const std::map<std::string, std::string> other = graded(root / "layout");
        // The reports are the same; grades.csv's points too (its `graded`
        // column names what was graded: a commit, an archive).
        for (const auto& [name, text] : first)
            if (name != "grades.csv") CHECK_MESSAGE(other.at(name) == text, name);
    }
    // Three shards, merged: the class's grades.csv, byte for byte.
    for (int k = 1; k <= 3; ++k) fs::remove_all(root / ("slice" + std::to_string(k)));
    run("for k in 1 2 3; do " + course() + " grade-class " + q(folders) + " --out " + q(root) +
        "/slice$k --labs transforms --jobs 1 --shard $k/3 & done; wait");
    fs::remove_all(root / "merged");
    REQUIRE(run(course() + " merge-class " + q(root / "merged") + " " + q(root / "slice1") + " " +
                q(root / "slice2") + " " + q(root / "slice3"))
                .exit_code == 0);
    CHECK(graded(root / "merged") == first);
}
