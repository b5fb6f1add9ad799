// roster_match.csv: which submission each roster student was matched to.
#include <cstdio>

#include "framework/text.hpp"
#include "grading/class/import_files.hpp"

namespace grading::cls {

namespace {

// A submission's student as messages and roster_match.csv name them.
std::string who_text(const std::vector<ClassRow>& rows, const SubmissionStudent& s) {
    const Student* st = student_of(rows, s);
    if (!st) return rows[s.row].submission.key;
    std::string t = st->name.empty() ? st->email : st->name;
    if (!st->name.empty() && !st->email.empty()) t += " <" + st->email + ">";
    return t;
}

}  // namespace

// roster_match.csv, for the staff: each roster student's submission, how it
// was found and which labs were not graded, then the submissions' students
// no roster row names. Each line is said on stderr too.
std::string roster_match_text(const Roster& roster, const RosterMatch& match,
                              const std::vector<ClassRow>& rows,
                              const std::vector<std::string>& labs) {
    const bool canvas = roster.kind == Roster::Kind::canvas;
    const std::string none = canvas ? "no submission: 0 in canvas.csv" : "no submission";
    std::string text = line_of({"Student", "ID", canvas ? "SIS User ID" : "ID number",
                                canvas ? "SIS Login ID" : "Email address", "submission",
                                "submitted by", "matched by", "not graded"});
    for (size_t i = 0; i < roster.students.size(); ++i) {
        const RosterStudent& st = roster.students[i];
        const RosterMatch::Found& f = match.of_student[i];
        std::vector<std::string> fields = {st.name, st.id, st.sis_user_id, st.sis_login_id};
        if (f.matched) {
            std::vector<std::string> not_graded;
            for (const std::string& id : labs)
                if (!lab_score(rows[f.who.row], id)) not_graded.push_back(id);
            fields.insert(fields.end(), {rows[f.who.row].submission.key, who_text(rows, f.who),
                                         f.by, fw::join(not_graded, " ")});
        } else {
            fields.insert(fields.end(), {"", "", none, ""});
            std::fprintf(stderr, "grade-class: no submission from %s%s%s\n", roster_who(st).c_str(),
                         st.id.empty() ? "" : (" ID " + st.id).c_str(),
                         canvas ? ": 0 in canvas.csv" : "");
        }
        text += line_of(fields, csv_field);
    }
    for (const SubmissionStudent& s : match.not_on_roster) {
        const std::string who = s.student < 0 ? "" : " (" + who_text(rows, s) + ")";
        std::fprintf(stderr, "grade-class: submission %s%s is on no row of the roster%s\n",
                     rows[s.row].submission.key.c_str(), who.c_str(),
                     canvas ? ": not in canvas.csv" : "");
        text += line_of({"", "", "", "", rows[s.row].submission.key, who_text(rows, s),
                         "not on the roster", ""},
                        csv_field);
    }
    for (const std::string& a : match.ambiguous)
        std::fprintf(stderr, "grade-class: roster: %s, so none of them was matched by it\n",
                     a.c_str());
    return text;
}

}  // namespace grading::cls
