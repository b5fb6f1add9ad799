// The roster of `course grade-class --roster`: Canvas's gradebook export,
// read with libcsv, and its students matched to the submissions' students
// (docs/contract.md, `course grade-class`, Canvas and Moodle).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "grading/class/class_submission.hpp"

namespace grading::cls {

// The records of a CSV text, each as its fields: RFC 4180 (quoted fields may
// hold the delimiter, quotes doubled and line breaks), with `delimiter`
// between fields. Throws fw::UsageError naming `what` and the record where
// the text is not CSV (a quote inside an unquoted field, a quoted field
// never closed).
std::vector<std::vector<std::string>> parse_csv(const std::string& text, char delimiter,
                                                const std::string& what);

// One student of the roster.
struct RosterStudent {
    std::vector<std::string> info;  // Canvas's student columns, Student to Section, as read
    // Canvas's Student ("Last, First"; from LastName and FirstName where the
    // export has those), ID, SIS User ID, SIS Login ID. From Moodle's export:
    // "Last name, First name", no ID, ID number as SIS User ID, Email
    // address as SIS Login ID.
    std::string name, id, sis_user_id, sis_login_id;
    // What moodle.csv identifies the student by: the Email address (Canvas:
    // the SIS Login ID where it is an email address), the ID number (Moodle's
    // export only).
    std::string email, id_number;
};

// Canvas's gradebook export (Grades > Export), its header as Canvas's import
// (lib/gradebook_importer.rb, update_column_count) takes it: "Student" or
// "LastName", "FirstName"; "ID"; then "SIS Login ID", or "SIS User ID",
// "SIS Login ID", ["Integration ID",] ["Root Account"]; then "Section"; then
// custom columns, assignments ("Title (id)") and read-only totals. A "Points
// Possible" row, and a "Muted" or "Manual Posting" row, before the students.
// Or Moodle's grade export (Grades > Export > Plain text file): "First
// name", "Last name", ["ID number",] ..., "Email address", then grade items.
struct Roster {
    enum class Kind { canvas, moodle };
    Kind kind = Kind::canvas;
    std::string file;
    std::vector<std::string> header;
    size_t info_columns = 0;                   // Canvas: Student to Section
    std::vector<std::string> points_possible;  // Canvas: the Points Possible row, as read
    bool has_id_number = false;                // Moodle: an ID number column
    std::vector<RosterStudent> students;
};

// Throws fw::UsageError naming the file and what is wrong: unreadable, not
// CSV, or a header of neither form; a Canvas header that Canvas's own import
// refuses ("Invalid header row") is refused with that reason.
Roster read_roster(const std::filesystem::path& file);

// A submission's student: the row's students[student], or the submission
// alone (student -1) where the layout names none.
struct SubmissionStudent {
    size_t row = 0;
    int student = -1;
};

// Every submission's students, in the rows' order.
std::vector<SubmissionStudent> submission_students(const std::vector<ClassRow>& rows);
// The student's name, email and SID; null for a submission alone.
const Student* student_of(const std::vector<ClassRow>& rows, const SubmissionStudent& s);

// Each roster student's submission, and how it was found; the submissions'
// students no roster row names.
struct RosterMatch {
    struct Found {
        bool matched = false;
        SubmissionStudent who;
        std::string by;  // "SIS Login ID = email", ...
    };
    std::vector<Found> of_student;  // per roster student
    std::vector<SubmissionStudent> not_on_roster;
    std::vector<std::string> ambiguous;  // values that name several on one side, left unmatched
};

// Matches in passes, each over those not yet matched, a pair matched only
// where the value names one roster student and one submission student
// (case and spacing ignored):
//   1. SIS Login ID = the student's email;
//   2. SIS Login ID, or its part before '@' = the email's part before '@',
//      or the submission's key;
//   3. SIS User ID = the student's SID, or the submission's key;
//   4. ID (Canvas's user id) = the submission's key;
//   5. Student (either "Last, First" or as written) = the student's name,
//      or the key with '_' as spaces.
RosterMatch match_roster(const Roster& roster, const std::vector<ClassRow>& rows);

}  // namespace grading::cls
