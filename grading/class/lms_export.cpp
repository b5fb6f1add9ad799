#include "grading/class/lms_export.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <optional>
#include <regex>
#include <set>

#include "framework/error.hpp"
#include "framework/text.hpp"
#include "grading/class/gradebook.hpp"
#include "grading/class/import_files.hpp"

namespace grading::cls {

namespace fs = std::filesystem;

namespace {

// Canvas's own form of an assignment's header, "Title (12345)": the title,
// else "" (Canvas's importer reads it with the same pattern).
std::string title_of(const std::string& header) {
    static const std::regex with_id(R"(^(.*)\s\((\d+)\)$)");
    std::smatch m;
    return std::regex_match(header, m, with_id) ? m[1].str() : "";
}

// The columns Canvas's importer takes for students' details or read-only
// totals, never for an assignment: a title holding one of these phrases
// would not be imported.
const char* const kNotAssignments[] = {"Current Score",  "Current Points", "Current Grade",
                                       "Final Score",    "Final Points",   "Final Grade",
                                       "Override Score", "Override Grade", "Override Status"};
const char* const kStudentColumns[] = {"Student",      "ID",       "SIS User ID",
                                       "SIS Login ID", "Section",  "Integration ID",
                                       "Root Account", "LastName", "FirstName"};

void check_title(const std::string& title, const std::string& option) {
    if (title.find_first_not_of(" \t") == std::string::npos)
        throw fw::UsageError(option + ": the column's title is empty");
    for (const char* s : kStudentColumns)
        if (title == s)
            throw fw::UsageError(option + ": '" + title +
                                 "' is one of the student columns of Canvas's gradebook; give "
                                 "the assignment another title");
    for (const char* s : kNotAssignments)
        if (title.find(s) != std::string::npos)
            throw fw::UsageError(option + ": Canvas's import drops a column whose title holds '" +
                                 s + "' (it takes it for a read-only total); give another title");
}

std::string points(double v) { return import_points(v); }

std::optional<double> sum_score(const ClassRow& r, const std::vector<std::string>& labs) {
    double sum = 0;
    for (const std::string& lab : labs) {
        const std::optional<double> s = lab_score(r, lab);
        if (!s) return std::nullopt;
        sum += *s;
    }
    return sum;
}

// The most a submission could score in each lab, from the rows graded.
std::map<std::string, double> lab_maxima(const std::vector<ClassRow>& rows) {
    std::map<std::string, double> max;
    for (const ClassRow& r : rows)
        for (const auto& [id, g] : r.labs)
            if (g.status != "not graded") max[id] = std::max(max[id], g.max_score);
    return max;
}

// canvas.csv's columns as --canvas-column asks for them (LmsOptions).
std::vector<LmsExport::Column> columns_asked(const std::vector<std::string>& asked,
                                             const std::vector<std::string>& ids) {
    const bool renames = std::any_of(asked.begin(), asked.end(), [](const std::string& c) {
        return c.find('=') != std::string::npos;
    });
    if (asked.size() == 1 && !renames) return {{asked[0], ids}};
    std::vector<LmsExport::Column> columns;
    for (const std::string& id : ids) columns.push_back({id, {id}});
    std::set<std::string> renamed;
    for (const std::string& c : asked) {
        const size_t eq = c.find('=');
        if (eq == std::string::npos)
            throw fw::UsageError("--canvas-column '" + c +
                                 "': give either one NAME (a column for the total of the "
                                 "labs) or LAB=NAME for each lab to title");
        const std::string lab = c.substr(0, eq);
        const auto it = std::find(ids.begin(), ids.end(), lab);
        if (it == ids.end())
            throw fw::UsageError("--canvas-column '" + c + "': '" + lab +
                                 "' is not one of the labs graded (" + fw::join(ids, ", ") + ")");
        if (!renamed.insert(lab).second)
            throw fw::UsageError("--canvas-column: lab '" + lab + "' is titled twice");
        columns[size_t(it - ids.begin())].header = c.substr(eq + 1);
    }
    return columns;
}

// A title that is one of the roster's assignments, as its header says it,
// "Title (id)", so that Canvas grades that assignment by its id; any other
// title as it is.
std::string roster_header(const Roster& roster, const std::string& title) {
    const std::vector<std::string>& h = roster.header;
    if (std::find(h.begin() + long(roster.info_columns), h.end(), title) != h.end()) {
        // Canvas's export titles every assignment "Title (id)"
        // (lib/gradebook_exporter.rb, csv_data: title_with_id); a header
        // after Section without an id is a custom column, whose cells
        // Canvas's import takes as its text (process_custom_column_headers).
        if (title_of(title).empty())
            throw fw::UsageError("--canvas-column '" + title + "': '" + title +
                                 "' is a custom column of the roster's gradebook, not an "
                                 "assignment: Canvas's import would write the points into it as "
                                 "text; give the assignment's title");
        return title;
    }
    std::vector<std::string> same;
    for (size_t i = roster.info_columns; i < h.size(); ++i)
        if (title_of(h[i]) == title) same.push_back(h[i]);
    if (same.size() > 1)
        throw fw::UsageError("--roster '" + roster.file + "' has " + std::to_string(same.size()) +
                             " assignments titled '" + title + "' (" + fw::join(same, ", ") +
                             "): name the one to grade with --canvas-column, as its header "
                             "says it");
    return same.empty() ? title : same[0];
}

}  // namespace

LmsExport::LmsExport(const LmsOptions& o,
                     const std::vector<std::pair<std::string, std::string>>& labs)
    : labs_(labs), moodle_total_(o.moodle_total) {
    if (o.roster.empty() && !o.canvas_columns.empty())
        throw fw::UsageError(
            "--canvas-column titles canvas.csv's columns, which only --roster writes: give "
            "Canvas's gradebook export with --roster");
    if (!o.roster.empty()) {
        roster_ = read_roster(o.roster);
        has_roster_ = true;
        if (roster_.kind == Roster::Kind::moodle && !o.canvas_columns.empty())
            throw fw::UsageError("--canvas-column titles canvas.csv's columns, and --roster '" +
                                 o.roster +
                                 "' is Moodle's grade export, from which no canvas.csv is "
                                 "written");
    }
    std::vector<std::string> ids;
    for (const auto& [id, dir] : labs) ids.push_back(id);
    columns_ = columns_asked(o.canvas_columns, ids);
    std::set<std::string> headers;
    for (Column& col : columns_) {
        check_title(col.header, "--canvas-column '" + col.header + "'");
        if (has_roster_ && roster_.kind == Roster::Kind::canvas)
            col.header = roster_header(roster_, col.header);
        if (!headers.insert(col.header).second)
            throw fw::UsageError("--canvas-column: two columns are titled '" + col.header + "'");
    }
}

namespace {

std::vector<std::optional<std::string>> lab_cells(const ClassRow& r,
                                                  const std::vector<std::string>& labs,
                                                  bool total) {
    std::vector<std::optional<std::string>> cells;
    for (const std::string& id : labs) {
        const std::optional<double> v = lab_score(r, id);
        cells.push_back(v ? std::optional<std::string>(points(*v)) : std::nullopt);
    }
    if (total) {
        const std::optional<double> v = sum_score(r, labs);
        cells.push_back(v ? std::optional<std::string>(points(*v)) : std::nullopt);
    }
    return cells;
}

// moodle.csv: each matched roster student by the roster's identifiers, the
// Email address (Moodle's "Identify user by" Email address) and, where the
// roster has one for every such student, the ID number. A student the
// roster gives no email address is left out (Moodle gives a row with a
// blank identifier the grades of the row before: load_data.php,
// map_user_data_with_value skips the blank value), said in `no_email`.
ImportTable moodle_table(const Roster& roster, const RosterMatch& match,
                         const std::vector<ClassRow>& rows, const std::vector<std::string>& labs,
                         bool total, std::vector<std::string>& no_email) {
    std::vector<size_t> kept;
    size_t without_number = 0;
    for (size_t i = 0; i < roster.students.size(); ++i) {
        if (!match.of_student[i].matched) continue;
        if (roster.students[i].email.empty()) {
            no_email.push_back(roster_who(roster.students[i]));
            continue;
        }
        kept.push_back(i);
        without_number += roster.students[i].id_number.empty();
    }
    const bool numbers = roster.has_id_number && without_number == 0;
    if (roster.has_id_number && without_number)
        std::fprintf(stderr,
                     "grade-class: moodle.csv has no ID number column: %zu of its students have "
                     "none on the roster\n",
                     without_number);
    ImportTable t;
    t.lead = {"Email address"};
    if (numbers) t.lead.push_back("ID number");
    t.columns = labs;
    if (total) t.columns.push_back("Total");
    for (size_t i : kept) {
        const RosterStudent& st = roster.students[i];
        ImportTable::Row r;
        r.lead = {st.email};
        if (numbers) r.lead.push_back(st.id_number);
        r.values = lab_cells(rows[match.of_student[i].who.row], labs, total);
        r.who = roster_who(st);
        t.rows.push_back(std::move(r));
    }
    return t;
}

// canvas.csv: the roster's student columns as Canvas wrote them, so that
// its importer finds each student by ID (then SIS User ID, SIS Login ID,
// name); the Points Possible row; then each roster student's points, 0 for
// one with no submission, none for a lab not graded (write_split leaves
// that cell out of the file).
ImportTable canvas_table(const Roster& roster, const RosterMatch& match,
                         const std::vector<LmsExport::Column>& columns,
                         const std::vector<ClassRow>& rows,
                         const std::map<std::string, double>& max) {
    ImportTable t;
    t.lead.assign(roster.header.begin(), roster.header.begin() + long(roster.info_columns));
    t.possible_lead.assign(roster.info_columns, "");
    t.possible_lead[0] = "Points Possible";
    for (const LmsExport::Column& col : columns) {
        t.columns.push_back(col.header);
        double sum = 0;
        bool known = true;
        for (const std::string& lab : col.labs) {
            const auto m = max.find(lab);
            known = known && m != max.end() && m->second > 0;
            if (m != max.end()) sum += m->second;
        }
        t.possible.push_back(known ? points(sum) : "");
        if (!known) {
            std::fprintf(stderr,
                         "grade-class: canvas.csv: no submission was graded in every lab of "
                         "'%s', so its Points Possible is left blank\n",
                         col.header.c_str());
            continue;
        }
        // Canvas's import sets Points Possible only on an assignment it
        // creates (process_pp; an existing one keeps its own), so the
        // roster's is the maximum the points are read against.
        const auto at = std::find(roster.header.begin(), roster.header.end(), col.header);
        const size_t j = size_t(at - roster.header.begin());
        const std::optional<double> theirs = j < roster.points_possible.size()
                                                 ? canvas_number(roster.points_possible[j])
                                                 : std::nullopt;
        if (at != roster.header.end() && theirs && std::abs(*theirs - sum) >= 0.005)
            std::fprintf(stderr,
                         "grade-class: warning: canvas.csv: column '%s': the labs are out of %s "
                         "points, but the roster's Points Possible for it is %s, which Canvas "
                         "keeps: full marks would show as %s/%s; set the assignment's points to "
                         "%s in Canvas before importing\n",
                         col.header.c_str(), points(sum).c_str(), points(*theirs).c_str(),
                         points(sum).c_str(), points(*theirs).c_str(), points(sum).c_str());
    }
    for (size_t i = 0; i < roster.students.size(); ++i) {
        const RosterMatch::Found& f = match.of_student[i];
        ImportTable::Row r;
        r.lead = roster.students[i].info;
        r.who = roster_who(roster.students[i]);
        for (const LmsExport::Column& col : columns) {
            const std::optional<double> v = f.matched ? sum_score(rows[f.who.row], col.labs) : 0.0;
            r.values.push_back(v ? std::optional<std::string>(points(*v)) : std::nullopt);
        }
        t.rows.push_back(std::move(r));
    }
    return t;
}

// Says which roster students moodle.csv leaves out for want of an email.
void say_no_email(const std::vector<std::string>& no_email) {
    if (no_email.empty()) return;
    const std::vector<std::string> some(
        no_email.begin(), no_email.begin() + long(std::min<size_t>(no_email.size(), 5)));
    std::fprintf(stderr,
                 "grade-class: moodle.csv leaves out %zu students with no email address on "
                 "the roster (%s%s)\n",
                 no_email.size(), fw::join(some, ", ").c_str(),
                 no_email.size() > some.size() ? ", ..." : "");
}

}  // namespace

void LmsExport::write(const fs::path& out, const std::vector<ClassRow>& rows,
                      const std::string& partial) const {
    size_t not_graded = 0;
    for (const ClassRow& r : rows)
        for (const auto& [id, dir] : labs_) not_graded += !lab_score(r, id);
    if (not_graded)
        std::fprintf(stderr,
                     "grade-class: %zu labs of submissions were not graded (grades.csv says "
                     "why): no score for them in canvas.csv and moodle.csv\n",
                     not_graded);
    if (!has_roster_) {
        remove_all_stale(out, {"canvas", "moodle", "moodle_items", "roster_match"});
        std::fprintf(stderr,
                     "grade-class: no canvas.csv nor moodle.csv: each names a student by the "
                     "identifiers of the gradebook's own export; give Canvas's or Moodle's with "
                     "--roster\n");
        return;
    }
    const RosterMatch match = match_roster(roster_, rows);
    const std::map<std::string, double> max = lab_maxima(rows);
    std::vector<std::string> ids, no_email;
    for (const auto& [id, dir] : labs_) ids.push_back(id);
    write_split(out, "moodle", moodle_table(roster_, match, rows, ids, moodle_total_, no_email));
    write_moodle_items(out, ids, moodle_total_, max);
    say_no_email(no_email);

    const bool canvas = roster_.kind == Roster::Kind::canvas;
    if (!partial.empty() || !canvas) {
        remove_all_stale(out, {"canvas"});
        if (!canvas)
            std::fprintf(stderr,
                         "grade-class: no canvas.csv: the roster is Moodle's export, and "
                         "Canvas's import names each student by the IDs of its own\n");
        else
            std::fprintf(stderr,
                         "grade-class: no canvas.csv: %s, and the roster's other students "
                         "would get 0\n",
                         partial.c_str());
    }
    if (!partial.empty()) {
        remove_all_stale(out, {"roster_match"});
        return;
    }
    write_whole(out / "roster_match.csv", roster_match_text(roster_, match, rows, ids));
    if (!canvas) return;
    write_split(out, "canvas", canvas_table(roster_, match, columns_, rows, max));
    const size_t found =
        size_t(std::count_if(match.of_student.begin(), match.of_student.end(),
                             [](const RosterMatch::Found& f) { return f.matched; }));
    std::fprintf(stderr,
                 "grade-class: canvas.csv: %zu students on the roster, %zu with a submission, "
                 "%zu with none (0); roster_match.csv says how each was matched\n",
                 roster_.students.size(), found, roster_.students.size() - found);
}

}  // namespace grading::cls
