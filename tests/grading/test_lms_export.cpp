// The import files of Canvas's and Moodle's gradebooks (grading/class/
// lms_export.hpp): the roster read, its students matched to submissions,
// and canvas.csv, moodle.csv and roster_match.csv written from rows made by
// hand and read back with python3's csv module; then one run of `course
// grade-class` on a class of two.
#include <filesystem>
#include <nlohmann/json.hpp>

#include "framework/text.hpp"
#include "grading/class/lms_export.hpp"
#include "tests/support/test_support.hpp"

namespace fs = std::filesystem;
using fw::test::check_mentions;
using fw::test::thrown;
using grading::cls::ClassRow;
using grading::cls::LabGrade;
using grading::cls::LmsExport;
using nlohmann::json;
using Table = std::vector<std::vector<std::string>>;

namespace {

const std::vector<std::pair<std::string, std::string>> kLabs = {{"pipeline", "00_pipeline"},
                                                                {"transforms", "01_transforms"}};

// A file as python3's csv module reads it.
Table read_back(const fs::path& file) {
    const fw::test::CommandResult r = fw::test::run_command(
        "python3 -c 'import csv, json, sys; "
        "print(json.dumps(list(csv.reader(open(sys.argv[1], newline=\"\", "
        "encoding=\"utf-8\")))))' " +
        fw::shell_quote(file.string()) + " 2>&1");
    INFO("python3 on " << file << ":\n" << r.output);
    REQUIRE(r.exit_code == 0);
    return json::parse(r.output).get<Table>();
}

fs::path fresh_dir(const std::string& name) {
    const fs::path dir = fs::path(fw::test::out_dir()) / name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    fw::test::remove_when_passed(dir.string());
    return dir;
}

fs::path write_roster(const fs::path& dir, const std::string& text) {
    const fs::path file = dir / "roster.csv";
    fw::test::write_text(file.string(), text);
    return file;
}

LabGrade lab(double score, double max, const std::string& status = "graded") {
    LabGrade g;
    g.status = status;
    g.score = score;
    g.max_score = max;
    return g;
}

ClassRow row(const std::string& key, std::vector<grading::cls::Student> students, LabGrade pipeline,
             LabGrade transforms) {
    ClassRow r;
    r.submission.key = key;
    r.submission.students = std::move(students);
    r.labs = {{"pipeline", pipeline}, {"transforms", transforms}};
    return r;
}

// Canvas's export as a teacher downloads it: a byte-order mark, the
// students' columns, two assignments (one titled by a lab), read-only
// totals, the Manual Posting and Points Possible rows, names with commas
// and quotes.
const std::string kRoster =
    "\xEF\xBB\xBF"
    "Student,ID,SIS User ID,SIS Login ID,Section,Lab One (101),transforms (102),Current Score,"
    "Final Score\r\n"
    ",,,,,Manual Posting,,,\r\n"
    "    Points Possible,,,,,20,10,(read only),(read only)\r\n"
    "\"Doe, Jane\",1001,S1,jdoe@uni.edu,Sec A,,,0,0\r\n"
    "\"O\"\"Brien, Pat\",1002,S2,pobrien@uni.edu,Sec A,,,0,0\r\n"
    "\"Smith, Al\",1003,S3,asmith,\"Sec, B\",,,0,0\r\n"
    "\"Lee, Kim\",1004,,klee,Sec B,,,0,0\r\n"
    "\"Nobody, Ned\",1005,S5,nned,Sec B,,,0,0\r\n";

// The class: Jane by email (Gradescope's metadata), Pat by folder name (her
// login's user name; one lab not graded), Al by SID, Kim by name, Ned with
// no submission, and a stranger on no roster row.
std::vector<ClassRow> class_rows() {
    return {
        row("submission_1", {{"Jane Doe", "JDoe@uni.edu", ""}}, lab(5, 5), lab(7, 10)),
        row("pobrien", {}, lab(0, 5, "not graded"), lab(10, 10)),
        row("submission_3", {{"Al Smith", "al@home.org", "S3"}}, lab(0, 5, "not built"),
            lab(3, 10, "not built")),
        row("submission_4", {{"Kim Lee", "kim@other.org", ""}}, lab(2.5, 5), lab(1.25, 10)),
        row("stranger", {}, lab(5, 5), lab(10, 10)),
    };
}

}  // namespace

TEST_CASE("parse_csv reads RFC 4180 and names where a file is not CSV") {
    const Table t = grading::cls::parse_csv("a,\"b, c\",\"say \"\"hi\"\"\"\r\n\"two\nlines\",,x\n",
                                            ',', "test");
    CHECK(t == Table{{"a", "b, c", "say \"hi\""}, {"two\nlines", "", "x"}});
    CHECK(grading::cls::parse_csv("a;b,c\n", ';', "test") == Table{{"a", "b,c"}});
    check_mentions(
        thrown<fw::UsageError>([] { grading::cls::parse_csv("a,b\nc,d\"e\n", ',', "F"); }),
        {"F is not CSV", "line 2"});
    check_mentions(thrown<fw::UsageError>([] { grading::cls::parse_csv("a,\"b\n", ',', "F"); }),
                   {"F is not CSV", "quote never closed"});
}

TEST_CASE("the roster: Canvas's export read, its non-student rows left out") {
    const fs::path dir = fresh_dir("roster");
    const grading::cls::Roster r = grading::cls::read_canvas_roster(write_roster(dir, kRoster));
    CHECK(r.info_columns == 5);
    REQUIRE(r.students.size() == 5);
    CHECK(r.students[0].name == "Doe, Jane");
    CHECK(r.students[1].name == "O\"Brien, Pat");
    CHECK(r.students[2].info ==
          std::vector<std::string>{"Smith, Al", "1003", "S3", "asmith", "Sec, B"});
    CHECK(r.students[3].sis_user_id.empty());

    // A teacher's semicolons, and a TA's export without SIS User ID.
    const grading::cls::Roster semi = grading::cls::read_canvas_roster(
        write_roster(dir, "Student;ID;SIS Login ID;Section;Lab\r\n\"Doe, Jane\";7;jd;A;1,5\r\n"));
    REQUIRE(semi.students.size() == 1);
    CHECK(semi.students[0].sis_login_id == "jd");
    CHECK(semi.students[0].sis_user_id.empty());

    check_mentions(
        thrown<fw::UsageError>(
            [&] { grading::cls::read_canvas_roster(write_roster(dir, "id,name,email\n1,a,b\n")); }),
        {"roster.csv", "not the header of Canvas's gradebook export",
         "Student, ID, [SIS User ID,] [SIS Login ID,] Section", "found id, name, email"});
    check_mentions(thrown<fw::UsageError>([&] {
                       grading::cls::read_canvas_roster(
                           write_roster(dir, "Student,ID,Section\n    Points Possible,,\n"));
                   }),
                   {"no students"});
    check_mentions(thrown<fw::UsageError>([&] {
                       grading::cls::read_canvas_roster(
                           write_roster(dir, "Student,ID,Section\na,1,x\nb,1,y\n"));
                   }),
                   {"rows 2 and 3", "same ID, 1"});
    check_mentions(
        thrown<fw::UsageError>([&] { grading::cls::read_canvas_roster(dir / "missing.csv"); }),
        {"missing.csv", "cannot read"});
}

TEST_CASE("the roster matched to submissions: each pass, and a value naming two left alone") {
    const fs::path dir = fresh_dir("match");
    const grading::cls::Roster r = grading::cls::read_canvas_roster(write_roster(dir, kRoster));
    const std::vector<ClassRow> rows = class_rows();
    const grading::cls::RosterMatch m = grading::cls::match_roster(r, rows);
    REQUIRE(m.of_student.size() == 5);
    const std::vector<std::pair<size_t, std::string>> expected = {
        {0, "SIS Login ID = email"},
        {1, "SIS Login ID = email's user name or submission"},
        {2, "SIS User ID = SID or submission"},
        {3, "name"}};
    for (size_t i = 0; i < expected.size(); ++i) {
        INFO("roster student " << r.students[i].name);
        CHECK(m.of_student[i].matched);
        CHECK(m.of_student[i].who.row == expected[i].first);
        CHECK(m.of_student[i].by == expected[i].second);
    }
    CHECK_FALSE(m.of_student[4].matched);
    REQUIRE(m.not_on_roster.size() == 1);
    CHECK(rows[m.not_on_roster[0].row].submission.key == "stranger");

    // Two roster rows of one name, one submission of it: neither is matched.
    const grading::cls::Roster twins = grading::cls::read_canvas_roster(write_roster(
        dir, "Student,ID,Section\n\"Lee, Kim\",1,A\n\"Lee, Kim\",2,B\n\"Doe, Jane\",3,A\n"));
    const grading::cls::RosterMatch t = grading::cls::match_roster(twins, rows);
    CHECK_FALSE(t.of_student[0].matched);
    CHECK_FALSE(t.of_student[1].matched);
    CHECK(t.of_student[2].matched);
    REQUIRE(t.ambiguous.size() == 1);
    check_mentions(t.ambiguous[0], {"name", "kim lee", "2 roster rows and 1 submission"});
}

TEST_CASE("canvas.csv: the roster's columns, Points Possible, 0 for no submission, quoting") {
    const fs::path dir = fresh_dir("canvas");
    const LmsExport lms({write_roster(dir, kRoster).string(), {}}, kLabs);
    lms.write(dir, class_rows(), "");
    const Table canvas = read_back(dir / "canvas.csv");
    const Table expected = {
        {"Student", "ID", "SIS User ID", "SIS Login ID", "Section", "pipeline", "transforms (102)"},
        {"Points Possible", "", "", "", "", "5", "10"},
        {"Doe, Jane", "1001", "S1", "jdoe@uni.edu", "Sec A", "5", "7"},
        // Pat's pipeline was not graded: no score, not 0.
        {"O\"Brien, Pat", "1002", "S2", "pobrien@uni.edu", "Sec A", "", "10"},
        {"Smith, Al", "1003", "S3", "asmith", "Sec, B", "0", "3"},
        {"Lee, Kim", "1004", "", "klee", "Sec B", "2.5", "1.25"},
        {"Nobody, Ned", "1005", "S5", "nned", "Sec B", "0", "0"}};
    CHECK(canvas == expected);

    const Table matches = read_back(dir / "roster_match.csv");
    REQUIRE(matches.size() == 7);
    CHECK(matches[5] == std::vector<std::string>{"Nobody, Ned", "1005", "S5", "nned", "", "",
                                                 "no submission: 0 in canvas.csv"});
    CHECK(matches[6] ==
          std::vector<std::string>{"", "", "", "", "stranger", "stranger", "not on the roster"});
}

TEST_CASE("canvas.csv's columns: the total, a lab titled as the roster's assignment, bad titles") {
    const fs::path dir = fresh_dir("columns");
    const std::string roster = write_roster(dir, kRoster).string();
    {
        const LmsExport total({roster, {"Labs"}}, kLabs);
        total.write(dir, class_rows(), "");
        const Table canvas = read_back(dir / "canvas.csv");
        CHECK(canvas[0].back() == "Labs");
        CHECK(canvas[1].back() == "15");
        CHECK(canvas[2].back() == "12");
        CHECK(canvas[3].back() == "");  // a lab not graded: no total
    }
    const LmsExport renamed({roster, {"pipeline=Lab One"}}, kLabs);
    REQUIRE(renamed.canvas_columns().size() == 2);
    CHECK(renamed.canvas_columns()[0].header == "Lab One (101)");
    CHECK(renamed.canvas_columns()[1].header == "transforms (102)");

    // The usage error of LmsExport with these options.
    const auto refused = [&](const grading::cls::LmsOptions& options) {
        return thrown<fw::UsageError>([&] { LmsExport(options, kLabs); });
    };
    check_mentions(refused({roster, {"shading=X"}}),
                   {"'shading' is not one of the labs graded", "pipeline, transforms"});
    check_mentions(refused({roster, {"Labs", "pipeline=X"}}), {"either one NAME", "LAB=NAME"});
    check_mentions(refused({roster, {"Lab Final Score"}}), {"Final Score", "read-only total"});
    check_mentions(refused({roster, {"pipeline=Section"}}), {"student columns"});
    const std::string twice =
        write_roster(dir, "Student,ID,Section,Lab (1),Lab (2)\na,1,A,,\n").string();
    check_mentions(refused({twice, {"Lab"}}), {"2 assignments titled 'Lab'", "Lab (1), Lab (2)"});
    check_mentions(refused({"", {"Labs"}}), {"--canvas-column", "only --roster writes"});
    // Given as its header, the one to grade is plain.
    CHECK(LmsExport({twice, {"Lab (2)"}}, kLabs).canvas_columns()[0].header == "Lab (2)");
}

TEST_CASE("moodle.csv: an email address on every row, a column per lab and the total") {
    const fs::path dir = fresh_dir("moodle");
    const LmsExport lms({write_roster(dir, kRoster).string(), {}}, kLabs);
    lms.write(dir, class_rows(), "");
    const Table moodle = read_back(dir / "moodle.csv");
    const Table expected = {{"Email address", "pipeline", "transforms", "Total"},
                            {"JDoe@uni.edu", "5", "7", "12"},
                            // From the roster's SIS Login ID; "-" is Moodle's "no grade".
                            {"pobrien@uni.edu", "-", "10", "-"},
                            {"al@home.org", "0", "3", "3"},
                            {"kim@other.org", "2.5", "1.25", "3.75"}};
    CHECK(moodle == expected);
}

TEST_CASE("without a roster, or with part of the class, there is no canvas.csv") {
    const fs::path dir = fresh_dir("no_roster");
    fw::test::write_text((dir / "canvas.csv").string(), "an earlier run's");
    const LmsExport lms({"", {}}, kLabs);
    lms.write(dir, class_rows(), "");
    CHECK_FALSE(fs::exists(dir / "canvas.csv"));
    CHECK(read_back(dir / "moodle.csv").size() == 4);  // the header; Jane, Al and Kim

    const LmsExport with({write_roster(dir, kRoster).string(), {}}, kLabs);
    with.write(dir, class_rows(), "");
    CHECK(fs::exists(dir / "canvas.csv"));
    CHECK(fs::exists(dir / "roster_match.csv"));
    // Interrupted: the students not graded yet would get 0.
    with.write(dir, class_rows(), "the run was interrupted");
    CHECK_FALSE(fs::exists(dir / "canvas.csv"));
    CHECK_FALSE(fs::exists(dir / "roster_match.csv"));
    CHECK(read_back(dir / "moodle.csv").size() == 5);  // and Pat, by the roster's login
}

TEST_CASE("course grade-class --roster: canvas.csv and moodle.csv of a class of two" *
          doctest::skip()) {
    const fs::path t = fresh_dir("class");
    const std::string lab1 = fw::test::source_dir() + "/labs/01_transforms/transforms_math.cpp";
    fs::create_directories(t / "subs/alice");
    fs::create_directories(t / "subs/bob");
    fs::copy_file(lab1, t / "subs/alice/transforms_math.cpp");
    // Bob's copy does not build.
    std::string broken = fw::test::read_text(lab1);
    broken.insert(broken.find("return"), "not C++ ");
    fw::test::write_text((t / "subs/bob/transforms_math.cpp").string(), broken);
    const fs::path roster =
        write_roster(t,
                     "Student,ID,SIS User ID,SIS Login ID,Section,Lab 1 (77),Current Score\r\n"
                     "    Points Possible,,,,,98,(read only)\r\n"
                     "\"Liddell, Alice\",11,A1,alice@uni.edu,S1,,\r\n"
                     "\"Carroll, Carol\",12,C1,carol@uni.edu,S1,,\r\n");
    const fw::test::CommandResult r = fw::test::run_command(
        fw::test::bin_dir() + "/course grade-class " + fw::shell_quote((t / "subs").string()) +
        " --out " + fw::shell_quote((t / "out").string()) +
        " --labs transforms --jobs 2 --canvas-column 'transforms=Lab 1' --roster " +
        fw::shell_quote(roster.string()));
    INFO(r.output);
    CHECK(r.exit_code == 1);  // bob's does not build
    check_mentions(r.output, {"no submission from Carroll, Carol", "submission bob is on no row"});

    const Table grades = read_back(t / "out/grades.csv");
    REQUIRE(grades.size() == 3);
    const std::string max = grades[1][6];  // alice's max
    CHECK(grades[1][4] == max);            // the solution scores full marks
    CHECK(read_back(t / "out/canvas.csv") ==
          Table{{"Student", "ID", "SIS User ID", "SIS Login ID", "Section", "Lab 1 (77)"},
                {"Points Possible", "", "", "", "", max},
                {"Liddell, Alice", "11", "A1", "alice@uni.edu", "S1", max},
                {"Carroll, Carol", "12", "C1", "carol@uni.edu", "S1", "0"}});
    CHECK(read_back(t / "out/moodle.csv") ==
          Table{{"Email address", "transforms", "Total"}, {"alice@uni.edu", max, max}});

    // In two slices: none writes canvas.csv (each would give the other's
    // students 0); merge-class writes the one run's, byte for byte.
    const std::string options = " --labs transforms --canvas-column 'transforms=Lab 1' --roster " +
                                fw::shell_quote(roster.string());
    for (const char* k : {"1", "2"}) {
        const fw::test::CommandResult slice = fw::test::run_command(
            fw::test::bin_dir() + "/course grade-class " + fw::shell_quote((t / "subs").string()) +
            " --out " + fw::shell_quote((t / ("slice" + std::string(k))).string()) + " --shard " +
            k + "/2" + options);
        INFO(slice.output);
        check_mentions(slice.output, {"no canvas.csv: --shard grades a slice"});
        CHECK_FALSE(fs::exists(t / ("slice" + std::string(k)) / "canvas.csv"));
    }
    const fw::test::CommandResult merged = fw::test::run_command(
        fw::test::bin_dir() + "/course merge-class " + fw::shell_quote((t / "merged").string()) +
        " " + fw::shell_quote((t / "slice1").string()) + " " +
        fw::shell_quote((t / "slice2").string()) + options.substr(options.find(" --canvas")));
    INFO(merged.output);
    CHECK(fw::test::read_text((t / "merged/canvas.csv").string()) ==
          fw::test::read_text((t / "out/canvas.csv").string()));
    CHECK(fw::test::read_text((t / "merged/moodle.csv").string()) ==
          fw::test::read_text((t / "out/moodle.csv").string()));
}
