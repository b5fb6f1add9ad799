// The class's grades as Canvas's and Moodle's gradebooks import them
// (docs/contract.md, `course grade-class`, Canvas and Moodle), from the
// roster, Canvas's or Moodle's own gradebook export (--roster):
// - DIR/canvas.csv (Canvas's roster only): its student columns as they
//   are, an assignment column per lab (or one for the total,
//   --canvas-column), the Points Possible row, and a row per student on the
//   roster, 0 for one with no submission;
// - DIR/moodle.csv: the roster's Email address (and ID number, where it has
//   one) of each student with a submission, then a column per lab (and the
//   total, --moodle-total); DIR/moodle_items.csv: each column's maximum;
// - DIR/roster_match.csv: which submission each roster student was matched
//   to and how, and the submissions with no roster row.
// No file has a blank cell: a student with a lab not graded is left out of
// canvas.csv (moodle.csv), and canvas_2.csv (moodle_2.csv), ... hold the
// columns such students have, since both imports take a blank cell for "no
// grade" and erase the grade they have.
// The roster is read and matched in roster.hpp.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "grading/class/roster.hpp"

namespace grading::cls {

struct LmsOptions {
    std::string roster;  // Canvas's gradebook export; empty: no canvas.csv
    // Empty: an assignment column per lab, titled by the lab's id; "NAME":
    // one column, the total; "LAB=NAME"...: the columns of those labs titled
    // NAME. A NAME that is the title of one of the roster's assignments
    // ("Title (id)") is written as that column's header.
    std::vector<std::string> canvas_columns;
    bool moodle_total = false;  // moodle.csv has a Total column
};

// Reads the roster and checks the column names when made, before anything
// is graded, so that a bad roster stops grade-class at once.
class LmsExport {
public:
    LmsExport(const LmsOptions& options,
              const std::vector<std::pair<std::string, std::string>>& labs);

    // With a roster, writes DIR/moodle.csv and DIR/moodle_items.csv, and
    // DIR/canvas.csv and DIR/roster_match.csv, saying on stderr who has no
    // submission, which submissions are not on the roster and where a
    // maximum differs from Canvas's Points Possible. `partial`: why `rows`
    // are not the whole class ("" when they are), which leaves canvas.csv
    // and roster_match.csv out.
    void write(const std::filesystem::path& out, const std::vector<ClassRow>& rows,
               const std::string& partial) const;

    // An assignment column of canvas.csv: its header and the labs it adds up.
    struct Column {
        std::string header;
        std::vector<std::string> labs;
    };
    const std::vector<Column>& canvas_columns() const { return columns_; }

private:
    std::vector<std::pair<std::string, std::string>> labs_;
    bool moodle_total_ = false;
    bool has_roster_ = false;
    Roster roster_;
    std::vector<Column> columns_;
};

}  // namespace grading::cls
