#include "grading/class/lms_export.hpp"

#include <algorithm>
#include <cstdio>
#include <map>
#include <optional>
#include <regex>
#include <set>

#include "framework/error.hpp"
#include "framework/text.hpp"
#include "grading/class/gradebook.hpp"

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

std::string points(double v) { return fw::trimmed_decimals(v, 2); }

// A lab's score as an import should take it: none where it was not graded
// (the submission could not be read, or course grade failed: grades.csv
// says why), whatever the student's code did otherwise.
std::optional<double> lab_score(const ClassRow& r, const std::string& lab) {
    const auto g = r.labs.find(lab);
    if (g == r.labs.end() || g->second.status == "not graded") return std::nullopt;
    return g->second.score;
}

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

// One CSV record, CRLF-ended. The import files are quoted as RFC 4180
// alone: an apostrophe before a leading '=' would change the very
// identifiers Canvas and Moodle match on.
std::string line_of(const std::vector<std::string>& fields,
                    std::string (*quote)(const std::string&) = csv_quoted) {
    std::string line;
    for (size_t i = 0; i < fields.size(); ++i) line += (i ? "," : "") + quote(fields[i]);
    return line + "\r\n";
}

// A submission's student as messages and roster_match.csv name them.
std::string who_text(const std::vector<ClassRow>& rows, const SubmissionStudent& s) {
    const Student* st = student_of(rows, s);
    if (!st) return rows[s.row].submission.key;
    std::string t = st->name.empty() ? st->email : st->name;
    if (!st->name.empty() && !st->email.empty()) t += " <" + st->email + ">";
    return t;
}

bool is_email(const std::string& s) {
    const size_t at = s.find('@');
    return at != std::string::npos && at > 0 && at + 1 < s.size() &&
           s.find_first_of(" \t,;") == std::string::npos;
}

// Removes an earlier run's file that this run does not write; says so.
void remove_stale(const fs::path& file) {
    std::error_code ec;
    if (fs::remove(file, ec))
        std::fprintf(stderr, "grade-class: removed %s, an earlier run's\n", file.c_str());
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
    if (std::find(h.begin() + long(roster.info_columns), h.end(), title) != h.end()) return title;
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
    : labs_(labs) {
    if (o.roster.empty() && !o.canvas_columns.empty())
        throw fw::UsageError(
            "--canvas-column titles canvas.csv's columns, which only --roster writes: give "
            "Canvas's gradebook export with --roster");
    if (!o.roster.empty()) {
        roster_ = read_canvas_roster(o.roster);
        has_roster_ = true;
    }
    std::vector<std::string> ids;
    for (const auto& [id, dir] : labs) ids.push_back(id);
    columns_ = columns_asked(o.canvas_columns, ids);
    std::set<std::string> headers;
    for (Column& col : columns_) {
        check_title(col.header, "--canvas-column '" + col.header + "'");
        if (has_roster_) col.header = roster_header(roster_, col.header);
        if (!headers.insert(col.header).second)
            throw fw::UsageError("--canvas-column: two columns are titled '" + col.header + "'");
    }
}

namespace {

// moodle.csv: the email address identifies the user (Moodle's "Identify
// user by": Email address to useremail). A row without one would take the
// grades of the row before it (Moodle keeps the last user found), so such a
// student is left out and named in `no_email`.
std::string moodle_text(const std::vector<ClassRow>& rows, const std::vector<std::string>& labs,
                        const std::map<std::pair<size_t, int>, std::string>& roster_email,
                        std::vector<std::string>& no_email) {
    std::vector<std::string> header = {"Email address"};
    header.insert(header.end(), labs.begin(), labs.end());
    header.push_back("Total");
    std::string text = line_of(header);
    std::map<std::string, std::string> seen;
    for (const SubmissionStudent& w : submission_students(rows)) {
        const Student* st = student_of(rows, w);
        const std::string& key = rows[w.row].submission.key;
        std::string email = st ? st->email : "";
        const auto listed = roster_email.find({w.row, w.student});
        if (email.empty() && listed != roster_email.end()) email = listed->second;
        if (email.empty() && is_email(key)) email = key;
        if (email.empty()) {
            no_email.push_back(who_text(rows, w));
            continue;
        }
        const auto [first, fresh] = seen.emplace(email, key);
        if (!fresh)
            std::fprintf(stderr,
                         "grade-class: moodle.csv: %s is in submissions %s and %s; Moodle "
                         "keeps the later row's grades\n",
                         email.c_str(), first->second.c_str(), key.c_str());
        // "-" is Moodle's "no grade", for a new grade item as for one it has.
        std::vector<std::string> fields = {email};
        for (const std::string& id : labs) {
            const std::optional<double> v = lab_score(rows[w.row], id);
            fields.push_back(v ? points(*v) : "-");
        }
        const std::optional<double> total = sum_score(rows[w.row], labs);
        fields.push_back(total ? points(*total) : "-");
        text += line_of(fields);
    }
    return text;
}

// roster_match.csv, for the staff: each roster student's submission and how
// it was found, then the submissions' students no roster row names. Each
// line is said on stderr too.
std::string roster_match_text(const Roster& roster, const RosterMatch& match,
                              const std::vector<ClassRow>& rows) {
    std::string text = line_of({"Student", "ID", "SIS User ID", "SIS Login ID", "submission",
                                "submitted by", "matched by"});
    for (size_t i = 0; i < roster.students.size(); ++i) {
        const RosterStudent& st = roster.students[i];
        const RosterMatch::Found& f = match.of_student[i];
        std::vector<std::string> fields = {st.name, st.id, st.sis_user_id, st.sis_login_id};
        if (f.matched) {
            fields.insert(fields.end(),
                          {rows[f.who.row].submission.key, who_text(rows, f.who), f.by});
        } else {
            fields.insert(fields.end(), {"", "", "no submission: 0 in canvas.csv"});
            std::fprintf(
                stderr, "grade-class: no submission from %s (ID %s%s): 0 in canvas.csv\n",
                st.name.c_str(), st.id.c_str(),
                st.sis_login_id.empty() ? "" : (", SIS Login ID " + st.sis_login_id).c_str());
        }
        text += line_of(fields, csv_field);
    }
    for (const SubmissionStudent& s : match.not_on_roster) {
        const std::string who = s.student < 0 ? "" : " (" + who_text(rows, s) + ")";
        std::fprintf(stderr,
                     "grade-class: submission %s%s is on no row of the roster: not in "
                     "canvas.csv\n",
                     rows[s.row].submission.key.c_str(), who.c_str());
        text += line_of(
            {"", "", "", "", rows[s.row].submission.key, who_text(rows, s), "not on the roster"},
            csv_field);
    }
    for (const std::string& a : match.ambiguous)
        std::fprintf(stderr, "grade-class: roster: %s, so none of them was matched by it\n",
                     a.c_str());
    return text;
}

// canvas.csv: the roster's student columns as Canvas wrote them, so that
// its importer finds each student by ID (then SIS User ID, SIS Login ID,
// name); the Points Possible row; then each roster student's points, 0 for
// one with no submission, none for a lab not graded.
std::string canvas_text(const Roster& roster, const RosterMatch& match,
                        const std::vector<LmsExport::Column>& columns,
                        const std::vector<ClassRow>& rows) {
    const std::map<std::string, double> max = lab_maxima(rows);
    std::vector<std::string> head(roster.header.begin(),
                                  roster.header.begin() + long(roster.info_columns));
    std::vector<std::string> possible(roster.info_columns, "");
    possible[0] = "Points Possible";
    for (const LmsExport::Column& col : columns) {
        head.push_back(col.header);
        double sum = 0;
        bool known = true;
        for (const std::string& lab : col.labs) {
            const auto m = max.find(lab);
            known = known && m != max.end() && m->second > 0;
            if (m != max.end()) sum += m->second;
        }
        possible.push_back(known ? points(sum) : "");
        if (!known)
            std::fprintf(stderr,
                         "grade-class: canvas.csv: no submission was graded in every lab of "
                         "'%s', so its Points Possible is left blank\n",
                         col.header.c_str());
    }
    std::string text = line_of(head) + line_of(possible);
    for (size_t i = 0; i < roster.students.size(); ++i) {
        const RosterMatch::Found& f = match.of_student[i];
        std::vector<std::string> fields = roster.students[i].info;
        for (const LmsExport::Column& col : columns) {
            const std::optional<double> v = f.matched ? sum_score(rows[f.who.row], col.labs) : 0.0;
            fields.push_back(v ? points(*v) : "");
        }
        text += line_of(fields);
    }
    return text;
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

    std::optional<RosterMatch> match;
    std::map<std::pair<size_t, int>, std::string> roster_email;
    if (has_roster_) {
        match = match_roster(roster_, rows);
        for (size_t i = 0; i < match->of_student.size(); ++i) {
            const RosterMatch::Found& f = match->of_student[i];
            if (f.matched && is_email(roster_.students[i].sis_login_id))
                roster_email[{f.who.row, f.who.student}] = roster_.students[i].sis_login_id;
        }
    }
    std::vector<std::string> ids, no_email;
    for (const auto& [id, dir] : labs_) ids.push_back(id);
    write_whole(out / "moodle.csv", moodle_text(rows, ids, roster_email, no_email));
    if (!no_email.empty()) {
        const std::vector<std::string> some(
            no_email.begin(), no_email.begin() + long(std::min<size_t>(no_email.size(), 5)));
        std::fprintf(stderr,
                     "grade-class: moodle.csv leaves out %zu submission students with no email "
                     "address (%s%s)\n",
                     no_email.size(), fw::join(some, ", ").c_str(),
                     no_email.size() > some.size() ? ", ..." : "");
    }

    if (!has_roster_ || !partial.empty()) {
        remove_stale(out / "canvas.csv");
        remove_stale(out / "roster_match.csv");
        if (!has_roster_)
            std::fprintf(stderr,
                         "grade-class: no canvas.csv: Canvas's import names each student by "
                         "the IDs of its own gradebook export; give that file with --roster\n");
        else
            std::fprintf(stderr,
                         "grade-class: no canvas.csv: %s, and the roster's other students "
                         "would get 0\n",
                         partial.c_str());
        return;
    }
    write_whole(out / "roster_match.csv", roster_match_text(roster_, *match, rows));
    write_whole(out / "canvas.csv", canvas_text(roster_, *match, columns_, rows));
    const size_t found =
        size_t(std::count_if(match->of_student.begin(), match->of_student.end(),
                             [](const RosterMatch::Found& f) { return f.matched; }));
    std::fprintf(stderr,
                 "grade-class: canvas.csv: %zu students on the roster, %zu with a submission, "
                 "%zu with none (0); roster_match.csv says how each was matched\n",
                 roster_.students.size(), found, roster_.students.size() - found);
}

}  // namespace grading::cls
