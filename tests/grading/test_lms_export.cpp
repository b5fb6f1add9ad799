// The import files of Canvas's and Moodle's gradebooks (grading/class/
// lms_export.hpp): the roster read, its students matched to submissions,
// and canvas.csv, moodle.csv and roster_match.csv written from rows made by
// hand and read back with python3's csv module, then imported into a
// gradebook by tests/grading/lms_imports.py, which reads them by Canvas's
// and Moodle's own rules (cited there by file and function); then one run
// of `course grade-class` on a class of two.
#include <fcntl.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <functional>
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

// The gradebook `book` (student -> column -> grade) after Canvas's or
// Moodle's import of `files`, one after the other, as
// tests/grading/lms_imports.py models it; {"refused": why} where the
// import refuses one.
json import_into(const std::string& lms, const json& book, const std::vector<fs::path>& files,
                 const std::string& by = "") {
    std::string command =
        "python3 " + fw::shell_quote(fw::test::source_dir() + "/tests/grading/lms_imports.py") +
        " " + lms + " " + fw::shell_quote(book.dump());
    if (!by.empty()) command += " " + fw::shell_quote(by);
    for (const fs::path& f : files) command += " " + fw::shell_quote(f.string());
    const fw::test::CommandResult r = fw::test::run_command(command + " 2>&1");
    INFO(command << "\n" << r.output);
    REQUIRE(r.exit_code == 0);
    return json::parse(r.output);
}

// What `f` writes on stderr.
std::string stderr_of(const std::function<void()>& f) {
    const std::string file = fw::test::out_dir() + "/lms_export_stderr.txt";
    std::fflush(stderr);
    const int saved = dup(2);
    const int fd = open(file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    REQUIRE(fd >= 0);
    dup2(fd, 2);
    close(fd);
    try {
        f();
    } catch (...) {
        std::fflush(stderr);
        dup2(saved, 2);
        close(saved);
        throw;
    }
    std::fflush(stderr);
    dup2(saved, 2);
    close(saved);
    const std::string text = fw::test::read_text(file);
    fs::remove(file);
    return text;
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

// Moodle's grade export (Grades > Export > Plain text file): the user
// fields Moodle exports by default, a grade item, the course total and the
// time of the export.
const std::string kMoodleRoster =
    "First name,Last name,ID number,Institution,Department,Email address,"
    "Assignment: Lab 1 (Real),Course total (Real),Last downloaded from this course\r\n"
    "Jane,Doe,S1,Uni,CS,jane.doe@uni.edu,-,-,1700000000\r\n"
    "Pat,O'Brien,S2,Uni,CS,pobrien@uni.edu,-,-,1700000000\r\n"
    "Al,Smith,S3,Uni,CS,asmith@uni.edu,-,-,1700000000\r\n";

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
    const grading::cls::Roster r = grading::cls::read_roster(write_roster(dir, kRoster));
    CHECK(r.kind == grading::cls::Roster::Kind::canvas);
    CHECK(r.info_columns == 5);
    CHECK(r.points_possible == std::vector<std::string>{"Points Possible", "", "", "", "", "20",
                                                        "10", "(read only)", "(read only)"});
    REQUIRE(r.students.size() == 5);
    CHECK(r.students[0].name == "Doe, Jane");
    CHECK(r.students[0].email == "jdoe@uni.edu");
    CHECK(r.students[1].name == "O\"Brien, Pat");
    CHECK(r.students[2].info ==
          std::vector<std::string>{"Smith, Al", "1003", "S3", "asmith", "Sec, B"});
    CHECK(r.students[2].email.empty());  // a login that is no email address
    CHECK(r.students[3].sis_user_id.empty());

    // A teacher's semicolons, and a TA's export without SIS User ID.
    const grading::cls::Roster semi = grading::cls::read_roster(
        write_roster(dir, "Student;ID;SIS Login ID;Section;Lab\r\n\"Doe, Jane\";7;jd;A;1,5\r\n"));
    REQUIRE(semi.students.size() == 1);
    CHECK(semi.students[0].sis_login_id == "jd");
    CHECK(semi.students[0].sis_user_id.empty());

    check_mentions(thrown<fw::UsageError>([&] {
                       grading::cls::read_roster(write_roster(dir, "id,name,email\n1,a,b\n"));
                   }),
                   {"roster.csv", "neither Canvas's gradebook export", "nor Moodle's grade export",
                    "found id, name, email"});
    check_mentions(thrown<fw::UsageError>([&] {
                       grading::cls::read_roster(
                           write_roster(dir, "Student,ID,Section\n    Points Possible,,\n"));
                   }),
                   {"no students"});
    check_mentions(
        thrown<fw::UsageError>([&] {
            grading::cls::read_roster(write_roster(dir, "Student,ID,Section\na,1,x\nb,1,y\n"));
        }),
        {"rows 2 and 3", "same ID, 1"});
    check_mentions(thrown<fw::UsageError>([&] { grading::cls::read_roster(dir / "missing.csv"); }),
                   {"missing.csv", "cannot read"});
}

// Every header Canvas's export writes (instructure/canvas-lms
// lib/gradebook_exporter.rb, csv_data: "Student", or "LastName",
// "FirstName" where the gradebook shows them; "ID"; "SIS User ID" with the
// SIS ids; "SIS Login ID"; "Integration ID" and "Root Account" with the SIS
// ids where the account shows them; "Section"; custom columns), and a
// header each of Canvas's import refuses (lib/gradebook_importer.rb,
// header? and update_column_count: "Invalid header row"). lms_imports.py
// reads each roster's canvas.csv as that import does.
TEST_CASE("the roster: each header of Canvas's export taken, each its import refuses refused") {
    const fs::path dir = fresh_dir("roster_headers");
    const std::vector<std::pair<std::string, std::string>> taken = {
        // header, the student row
        {"Student,ID,SIS Login ID,Section", "\"Doe, Jane\",7,jd,A"},
        {"Student,ID,SIS User ID,SIS Login ID,Section", "\"Doe, Jane\",7,S7,jd,A"},
        {"Student,ID,SIS User ID,SIS Login ID,Integration ID,Section",
         "\"Doe, Jane\",7,S7,jd,I7,A"},
        {"Student,ID,SIS User ID,SIS Login ID,Root Account,Section",
         "\"Doe, Jane\",7,S7,jd,uni.edu,A"},
        {"Student,ID,SIS User ID,SIS Login ID,Integration ID,Root Account,Section,Notes",
         "\"Doe, Jane\",7,S7,jd,I7,uni.edu,A,a note"},
        {"LastName,FirstName,ID,SIS Login ID,Section", "Doe,Jane,7,jd,A"},
        {"LastName,FirstName,ID,SIS User ID,SIS Login ID,Integration ID,Root Account,Section",
         "Doe,Jane,7,S7,jd,I7,uni.edu,A"},
        {"Student,ID,Section", "\"Doe, Jane\",7,A"},
    };
    const std::vector<ClassRow> rows = {row("jd", {{"Jane Doe", "", "S7"}}, lab(4, 5), lab(9, 10))};
    for (const auto& [header, student] : taken) {
        INFO(header);
        const fs::path roster =
            write_roster(dir, header + ",Lab (1),Current Score\r\n" + student + ",,\r\n");
        const grading::cls::Roster r = grading::cls::read_roster(roster);
        REQUIRE(r.students.size() == 1);
        CHECK(r.students[0].id == "7");
        CHECK(r.students[0].name == "Doe, Jane");
        CHECK(r.info_columns == size_t(std::count(header.begin(), header.end(), ',') + 1 -
                                       (header.find("Notes") != std::string::npos)));
        LmsExport({roster.string(), {}}, kLabs).write(dir, rows, "");
        CHECK(import_into("canvas", json::object(), {dir / "canvas.csv"}) ==
              json{{"7", {{"pipeline", "4"}, {"transforms", "9"}}}});
    }
    const std::vector<std::string> refused = {
        "Student,ID,SIS User ID,Section",                  // SIS User ID without the login
        "Student,ID,Integration ID,Section",               // Integration ID without SIS ids
        "Student,ID,SIS Login ID,Integration ID,Section",  // likewise
        "Student,ID,SIS Login ID,SIS User ID,Section",     // the SIS ids the other way
        "Student,ID,SIS User ID,SIS Login ID,Root Account,Integration ID,Section",
        "Student,ID,Name,Section",                     // another column before Section
        "Student,SIS Login ID,ID,Section",             // ID not second
        "LastName,FirstName,SIS Login ID,ID,Section",  // ID not third
        "LastName,ID,Section",                         // no FirstName
        "Student,ID,SIS Login ID",                     // no Section
    };
    for (const std::string& header : refused) {
        INFO(header);
        // Canvas's import refuses the file this header would make.
        const fs::path as_canvas = dir / "as_canvas.csv";
        fw::test::write_text(as_canvas.string(), header + ",Lab (1)\r\n");
        CHECK(import_into("canvas", json::object(), {as_canvas}) ==
              json{{"refused", "Invalid header row"}});
        check_mentions(thrown<fw::UsageError>([&] {
                           grading::cls::read_roster(
                               write_roster(dir, header + ",Lab (1)\r\na,1,b,c,d,e,f,g\r\n"));
                       }),
                       {"Canvas's import would refuse", "\"Invalid header row\"",
                        "Student (or LastName, FirstName), ID", "found " + header.substr(0, 7)});
    }
}

TEST_CASE("the roster: Moodle's grade export read, by Email address and ID number") {
    const fs::path dir = fresh_dir("roster_moodle");
    const grading::cls::Roster r = grading::cls::read_roster(write_roster(dir, kMoodleRoster));
    CHECK(r.kind == grading::cls::Roster::Kind::moodle);
    CHECK(r.has_id_number);
    REQUIRE(r.students.size() == 3);
    CHECK(r.students[0].name == "Doe, Jane");
    CHECK(r.students[0].email == "jane.doe@uni.edu");
    CHECK(r.students[2].id_number == "S3");
    check_mentions(
        thrown<fw::UsageError>([&] {
            grading::cls::read_roster(write_roster(dir,
                                                   "First name,Last name,Email address\r\n"
                                                   "A,B,a@uni.edu\r\nC,D,A@uni.edu\r\n"));
        }),
        {"rows 2 and 3", "same Email address"});
    // --canvas-column asks for a file a Moodle roster does not give.
    check_mentions(thrown<fw::UsageError>([&] {
                       LmsExport({write_roster(dir, kMoodleRoster).string(), {"Labs"}}, kLabs);
                   }),
                   {"--canvas-column", "Moodle's grade export"});
}

TEST_CASE("the roster matched to submissions: each pass, and a value naming two left alone") {
    const fs::path dir = fresh_dir("match");
    const grading::cls::Roster r = grading::cls::read_roster(write_roster(dir, kRoster));
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
    const grading::cls::Roster twins = grading::cls::read_roster(write_roster(
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
    fw::test::write_text((dir / "canvas_3.csv").string(), "an earlier run's");
    const LmsExport lms({write_roster(dir, kRoster).string(), {}}, kLabs);
    const std::string said = stderr_of([&] { lms.write(dir, class_rows(), ""); });
    const Table canvas = read_back(dir / "canvas.csv");
    const Table expected = {
        {"Student", "ID", "SIS User ID", "SIS Login ID", "Section", "pipeline", "transforms (102)"},
        {"Points Possible", "", "", "", "", "5", "10"},
        {"Doe, Jane", "1001", "S1", "jdoe@uni.edu", "Sec A", "5", "7"},
        // Pat's pipeline was not graded: her row is in canvas_2.csv.
        {"Smith, Al", "1003", "S3", "asmith", "Sec, B", "0", "3"},
        {"Lee, Kim", "1004", "", "klee", "Sec B", "2.5", "1.25"},
        {"Nobody, Ned", "1005", "S5", "nned", "Sec B", "0", "0"}};
    CHECK(canvas == expected);
    // Canvas's import of canvas.csv alone leaves Pat's pipeline as it is.
    const json pat = {{"1002", {{"pipeline", "1"}, {"transforms (102)", "1"}}}};
    CHECK(import_into("canvas", pat, {dir / "canvas.csv"})["1002"] == pat["1002"]);
    CHECK(read_back(dir / "canvas_2.csv") ==
          Table{{"Student", "ID", "SIS User ID", "SIS Login ID", "Section", "transforms (102)"},
                {"Points Possible", "", "", "", "", "10"},
                {"O\"Brien, Pat", "1002", "S2", "pobrien@uni.edu", "Sec A", "10"}});
    CHECK_FALSE(fs::exists(dir / "canvas_3.csv"));
    check_mentions(said, {"canvas.csv: no row for O\"Brien, Pat (pobrien@uni.edu), whose pipeline "
                          "was not graded; canvas_2.csv has the other columns",
                          "import canvas_2.csv after canvas.csv"});

    // Imported into a gradebook that has a score for everyone in both
    // assignments, Pat's pipeline keeps hers: no file leaves a blank cell.
    json book;
    for (const char* id : {"1001", "1002", "1003", "1004", "1005"})
        book[id] = {{"pipeline", "1"}, {"transforms (102)", "1"}};
    json after = book;
    after["1001"] = {{"pipeline", "5"}, {"transforms (102)", "7"}};
    after["1002"] = {{"pipeline", "1"}, {"transforms (102)", "10"}};
    after["1003"] = {{"pipeline", "0"}, {"transforms (102)", "3"}};
    after["1004"] = {{"pipeline", "2.5"}, {"transforms (102)", "1.25"}};
    after["1005"] = {{"pipeline", "0"}, {"transforms (102)", "0"}};
    CHECK(import_into("canvas", book, {dir / "canvas.csv", dir / "canvas_2.csv"}) == after);

    const Table matches = read_back(dir / "roster_match.csv");
    REQUIRE(matches.size() == 7);
    CHECK(matches[0].back() == "not graded");
    CHECK(matches[2] == std::vector<std::string>{
                            "O\"Brien, Pat", "1002", "S2", "pobrien@uni.edu", "pobrien", "pobrien",
                            "SIS Login ID = email's user name or submission", "pipeline"});
    CHECK(matches[5] == std::vector<std::string>{"Nobody, Ned", "1005", "S5", "nned", "", "",
                                                 "no submission: 0 in canvas.csv", ""});
    CHECK(matches[6] == std::vector<std::string>{"", "", "", "", "stranger", "stranger",
                                                 "not on the roster", ""});
}

TEST_CASE("canvas.csv: a maximum other than the roster's Points Possible is a warning") {
    const fs::path dir = fresh_dir("possible");
    const std::string roster = write_roster(dir, kRoster).string();
    // Lab One is out of 20 in Canvas, pipeline out of 5; transforms (102)
    // is out of 10 in both.
    const LmsExport lms({roster, {"pipeline=Lab One"}}, kLabs);
    const std::string said = stderr_of([&] { lms.write(dir, class_rows(), ""); });
    check_mentions(said, {"warning: canvas.csv: column 'Lab One (101)': the labs are out of 5 "
                          "points, but the roster's Points Possible for it is 20",
                          "5/20"});
    CHECK(said.find("'transforms (102)': the labs") == std::string::npos);
    // In a locale with decimal commas Canvas writes "5,0"; that is 5.
    const std::string comma =
        write_roster(dir,
                     "Student;ID;SIS Login ID;Section;Lab One (101)\r\n"
                     "    Points Possible;;;;5,0\r\n\"Doe, Jane\";1;jdoe@uni.edu;A;\r\n")
            .string();
    const auto write = [&] {
        LmsExport({comma, {"pipeline=Lab One"}}, kLabs).write(dir, class_rows(), "");
    };
    const std::string quiet = stderr_of(write);
    INFO(quiet);
    CHECK(quiet.find("warning: canvas.csv") == std::string::npos);
}

TEST_CASE("canvas.csv's columns: the total, a lab titled as the roster's assignment, bad titles") {
    const fs::path dir = fresh_dir("columns");
    const std::string roster = write_roster(dir, kRoster).string();
    {
        const LmsExport total({roster, {"Labs"}}, kLabs);
        fw::test::write_text((dir / "canvas_2.csv").string(), "an earlier run's");
        total.write(dir, class_rows(), "");
        const Table canvas = read_back(dir / "canvas.csv");
        CHECK(canvas[0].back() == "Labs");
        CHECK(canvas[1].back() == "15");
        CHECK(canvas[2].back() == "12");
        // Pat's total is not known: she is in no file.
        REQUIRE(canvas.size() == 6);
        CHECK(canvas[3][0] == "Smith, Al");
        CHECK_FALSE(fs::exists(dir / "canvas_2.csv"));
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
    check_mentions(refused({roster, {"pipeline=LastName"}}), {"student columns"});
    const std::string twice =
        write_roster(dir, "Student,ID,Section,Lab (1),Lab (2)\na,1,A,,\n").string();
    check_mentions(refused({twice, {"Lab"}}), {"2 assignments titled 'Lab'", "Lab (1), Lab (2)"});
    check_mentions(refused({"", {"Labs"}}), {"--canvas-column", "only --roster writes"});
    // Given as its header, the one to grade is plain.
    CHECK(LmsExport({twice, {"Lab (2)"}}, kLabs).canvas_columns()[0].header == "Lab (2)");
    // A custom column (after Section, no id) is no assignment.
    const std::string notes =
        write_roster(dir, "Student,ID,SIS Login ID,Section,Notes,Lab (1)\na,1,b,A,,\n").string();
    check_mentions(refused({notes, {"pipeline=Notes"}}), {"'Notes' is a custom column", "as text"});
}

TEST_CASE("moodle.csv: by the roster's email address, no blank or '-', no Total unless asked") {
    const fs::path dir = fresh_dir("moodle");
    const LmsExport lms({write_roster(dir, kRoster).string(), {}}, kLabs);
    const std::string said = stderr_of([&] { lms.write(dir, class_rows(), ""); });
    // The roster's SIS Login ID where it is an email address, never
    // Gradescope's (Jane's is JDoe@uni.edu): Moodle's import stops at an
    // address it does not know.
    CHECK(read_back(dir / "moodle.csv") ==
          Table{{"Email address", "pipeline", "transforms"}, {"jdoe@uni.edu", "5", "7"}});
    // Moodle's import of moodle.csv alone leaves Pat's pipeline as it is;
    // it refuses the whole file for an address it does not know.
    const json two = {{"jdoe@uni.edu", json::object()}, {"pobrien@uni.edu", {{"pipeline", "1"}}}};
    CHECK(import_into("moodle", two, {dir / "moodle.csv"}, "Email address")["pobrien@uni.edu"] ==
          two["pobrien@uni.edu"]);
    CHECK(import_into("moodle", {{"pobrien@uni.edu", json::object()}}, {dir / "moodle.csv"},
                      "Email address") == json{{"refused", "usermappingerror: jdoe@uni.edu"}});
    CHECK(read_back(dir / "moodle_2.csv") ==
          Table{{"Email address", "transforms"}, {"pobrien@uni.edu", "10"}});
    CHECK(read_back(dir / "moodle_items.csv") ==
          Table{{"grade item", "maximum grade"}, {"pipeline", "5"}, {"transforms", "10"}});
    check_mentions(said, {"Add grade item, Maximum grade): pipeline 5, transforms 10",
                          "moodle.csv leaves out 2 students with no email address on the roster "
                          "(Smith, Al (asmith), Lee, Kim (klee))"});
    CHECK(said.find("Unlimited grades") == std::string::npos);

    const json book = {{"jdoe@uni.edu", {{"pipeline", "1"}, {"transforms", "1"}}},
                       {"pobrien@uni.edu", {{"pipeline", "1"}, {"transforms", "1"}}}};
    CHECK(
        import_into("moodle", book, {dir / "moodle.csv", dir / "moodle_2.csv"}, "Email address") ==
        json{{"jdoe@uni.edu", {{"pipeline", "5"}, {"transforms", "7"}}},
             {"pobrien@uni.edu", {{"pipeline", "1"}, {"transforms", "10"}}}});

    // --moodle-total: a Total column, on rows that have every lab.
    const LmsExport with_total({write_roster(dir, kRoster).string(), {}, true}, kLabs);
    with_total.write(dir, class_rows(), "");
    CHECK(read_back(dir / "moodle.csv") ==
          Table{{"Email address", "pipeline", "transforms", "Total"},
                {"jdoe@uni.edu", "5", "7", "12"}});
    CHECK(read_back(dir / "moodle_2.csv")[0] ==
          std::vector<std::string>{"Email address", "transforms"});
    CHECK(read_back(dir / "moodle_items.csv").back() == std::vector<std::string>{"Total", "15"});

    // A lab above 100 points: Moodle's import refuses the file unless the
    // site allows it, which stderr says.
    std::vector<ClassRow> big = class_rows();
    big[0].labs["pipeline"] = lab(254, 254);
    const std::string above = stderr_of([&] { lms.write(dir, big, ""); });
    check_mentions(above, {"Unlimited grades", "pipeline (254)"});
    CHECK(import_into("moodle", book, {dir / "moodle.csv"}, "Email address") ==
          json{{"refused", "gradevaluetoobig"}});
}

TEST_CASE("moodle.csv from Moodle's export: its Email address and ID number, no canvas.csv") {
    const fs::path dir = fresh_dir("moodle_roster");
    fw::test::write_text((dir / "canvas.csv").string(), "an earlier run's");
    const LmsExport lms({write_roster(dir, kMoodleRoster).string(), {}}, kLabs);
    const std::string said = stderr_of([&] { lms.write(dir, class_rows(), ""); });
    CHECK_FALSE(fs::exists(dir / "canvas.csv"));
    check_mentions(said, {"no canvas.csv: the roster is Moodle's export"});
    // Jane by name, Pat by her login, Al by his SID = ID number; Al's row
    // has the roster's address, not Gradescope's al@home.org.
    CHECK(read_back(dir / "moodle.csv") ==
          Table{{"Email address", "ID number", "pipeline", "transforms"},
                {"jane.doe@uni.edu", "S1", "5", "7"},
                {"asmith@uni.edu", "S3", "0", "3"}});
    CHECK(read_back(dir / "moodle_2.csv") ==
          Table{{"Email address", "ID number", "transforms"}, {"pobrien@uni.edu", "S2", "10"}});
    const Table matches = read_back(dir / "roster_match.csv");
    CHECK(matches[0] == std::vector<std::string>{"Student", "ID", "ID number", "Email address",
                                                 "submission", "submitted by", "matched by",
                                                 "not graded"});
    CHECK(matches[3][6] == "SIS User ID = SID or submission");

    // Mapped by either identifier, the import changes the graded labs only.
    const std::vector<fs::path> files = {dir / "moodle.csv", dir / "moodle_2.csv"};
    const json by_number = {
        {"S1", {{"pipeline", "1"}}}, {"S2", {{"pipeline", "1"}}}, {"S3", {{"pipeline", "1"}}}};
    CHECK(import_into("moodle", by_number, files, "ID number") ==
          json{{"S1", {{"pipeline", "5"}, {"transforms", "7"}}},
               {"S2", {{"pipeline", "1"}, {"transforms", "10"}}},
               {"S3", {{"pipeline", "0"}, {"transforms", "3"}}}});
    const json by_email = {{"jane.doe@uni.edu", json::object()},
                           {"pobrien@uni.edu", json::object()},
                           {"asmith@uni.edu", json::object()}};
    CHECK(import_into("moodle", by_email, files, "Email address")["asmith@uni.edu"] ==
          json{{"pipeline", "0"}, {"transforms", "3"}});
}

TEST_CASE("without a roster there is neither file; with part of the class, no canvas.csv") {
    const fs::path dir = fresh_dir("no_roster");
    fw::test::write_text((dir / "canvas.csv").string(), "an earlier run's");
    fw::test::write_text((dir / "moodle.csv").string(), "an earlier run's");
    fw::test::write_text((dir / "moodle_2.csv").string(), "an earlier run's");
    const LmsExport lms({"", {}}, kLabs);
    const std::string said = stderr_of([&] { lms.write(dir, class_rows(), ""); });
    check_mentions(said, {"no canvas.csv nor moodle.csv", "--roster"});
    CHECK_FALSE(fs::exists(dir / "canvas.csv"));
    CHECK_FALSE(fs::exists(dir / "moodle.csv"));
    CHECK_FALSE(fs::exists(dir / "moodle_2.csv"));

    const LmsExport with({write_roster(dir, kRoster).string(), {}}, kLabs);
    with.write(dir, class_rows(), "");
    CHECK(fs::exists(dir / "canvas.csv"));
    CHECK(fs::exists(dir / "roster_match.csv"));
    // Interrupted: the students not graded yet would get 0.
    with.write(dir, class_rows(), "the run was interrupted");
    CHECK_FALSE(fs::exists(dir / "canvas.csv"));
    CHECK_FALSE(fs::exists(dir / "canvas_2.csv"));
    CHECK_FALSE(fs::exists(dir / "roster_match.csv"));
    CHECK(read_back(dir / "moodle.csv").size() == 2);  // the header; Jane
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
                     "    Points Possible,,,,,100,(read only)\r\n"
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
          Table{{"Email address", "transforms"}, {"alice@uni.edu", max}});
    // The roster's Lab 1 is out of 100, which Canvas keeps.
    REQUIRE(max != "100");
    check_mentions(r.output, {"warning: canvas.csv: column 'Lab 1 (77)': the labs are out of " +
                              max + " points, but the roster's Points Possible for it is 100"});

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
