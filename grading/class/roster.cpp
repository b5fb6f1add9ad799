#include "grading/class/roster.hpp"

#include <csv.h>

#include <algorithm>
#include <cctype>
#include <map>
#include <optional>
#include <regex>
#include <set>

#include "framework/error.hpp"
#include "framework/text.hpp"
#include "grading/release/release.hpp"

namespace grading::cls {

namespace fs = std::filesystem;

namespace {

// libcsv's callbacks: a field, then the end of its record.
struct Records {
    std::vector<std::vector<std::string>> done;
    std::vector<std::string> current;
};

void on_field(void* text, size_t length, void* data) {
    auto* r = static_cast<Records*>(data);
    r->current.emplace_back(length ? std::string(static_cast<const char*>(text), length) : "");
}

void on_record(int, void* data) {
    auto* r = static_cast<Records*>(data);
    r->done.push_back(std::move(r->current));
    r->current.clear();
}

std::string trim(const std::string& s) {
    const size_t a = s.find_first_not_of(" \t\r\n");
    if (a == std::string::npos) return "";
    return s.substr(a, s.find_last_not_of(" \t\r\n") - a + 1);
}

// Case and runs of spaces ignored.
std::string normal(const std::string& s) {
    std::string out;
    bool space = false;
    for (unsigned char ch : trim(s)) {
        if (std::isspace(ch)) {
            space = true;
            continue;
        }
        if (space) out += ' ';
        space = false;
        out += char(std::tolower(ch));
    }
    return out;
}

// The file's records, with Canvas's byte-order mark dropped and ';' as the
// delimiter where the header has no ',' but ';' (Canvas's export in a
// locale that writes decimal commas).
std::vector<std::vector<std::string>> read_records(const fs::path& file, const std::string& what) {
    std::string text;
    try {
        text = read_file(file);
    } catch (const fw::Error&) {
        throw fw::UsageError(what + ": cannot read it");
    }
    if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);
    const std::vector<std::vector<std::string>> first =
        parse_csv(text.substr(0, text.find('\n')), ',', what);
    const bool semicolons =
        !first.empty() && first[0].size() == 1 && first[0][0].find(';') != std::string::npos;
    return parse_csv(text, semicolons ? ';' : ',', what);
}

bool holds(const std::vector<std::string>& h, size_t i, const char* text) {
    return i < h.size() && h[i].find(text) != std::string::npos;
}

bool holds(const std::vector<std::string>& h, size_t i, const std::regex& re) {
    return i < h.size() && std::regex_search(h[i], re);
}

// Where Canvas's import finds a student's details in a header of its
// export (lib/gradebook_importer.rb, row_has_student_headers? and
// update_column_count): the name in one column ("Student") or two
// ("LastName", "FirstName"), then "ID", then either "SIS Login ID" or "SIS
// User ID", "SIS Login ID", ["Integration ID",] ["Root Account"], and the
// column after them must be "Section" (header? refuses the file otherwise).
// Custom columns follow Section, before the assignments.
struct CanvasLayout {
    bool last_first = false;
    size_t id = 1;
    long sis_user = -1, sis_login = -1;
    size_t info_columns = 0;  // Student to Section
};

std::optional<CanvasLayout> canvas_layout(const std::vector<std::string>& h) {
    static const std::regex login(R"(SIS\s+Login\s+ID)"), user(R"(SIS\s+User\s+ID)"),
        integration(R"(Integration\s+ID)"), root(R"(Root\s+Account)");
    CanvasLayout l;
    l.last_first = h.size() > 2 && h[0] == "LastName" && h[1] == "FirstName";
    if (!l.last_first && !(holds(h, 0, "Student") && holds(h, 1, "ID"))) return std::nullopt;
    if (l.last_first && !holds(h, 2, "ID")) return std::nullopt;
    const size_t n = l.last_first ? 4 : 3;
    l.id = n - 2;
    l.info_columns = n;
    if (holds(h, n - 1, login)) {
        l.sis_login = long(n - 1);
        l.info_columns += 1;
    } else if (holds(h, n - 1, user) && holds(h, n, login)) {
        const size_t i = holds(h, n + 1, integration) ? 1 : 0;
        l.sis_user = long(n - 1);
        l.sis_login = long(n);
        l.info_columns += 2 + i + (holds(h, n + 1 + i, root) ? 1 : 0);
    }
    if (!holds(h, l.info_columns - 1, "Section")) return std::nullopt;
    return l;
}

std::string first_cells(const std::vector<std::string>& h, size_t n) {
    const std::vector<std::string> some(h.begin(), h.begin() + long(std::min(h.size(), n)));
    return fw::join(some, ", ") + (h.size() > n ? ", ..." : "");
}

// The rows that describe the assignments rather than a student: their
// points possible, and which are muted or posted by hand.
bool describes_assignments(const std::vector<std::string>& row) {
    static const std::regex posting(R"(\s*(Muted|Manual Posting.*)?\s*)", std::regex::icase);
    return row.empty() || trim(row[0]).find("Points Possible") != std::string::npos ||
           std::all_of(row.begin(), row.end(),
                       [](const std::string& c) { return std::regex_match(c, posting); });
}

// The values the matching passes compare, by name.
using Fields = std::map<std::string, std::string>;

std::string user_name(const std::string& email) {
    const size_t at = email.find('@');
    return at == std::string::npos ? std::string() : email.substr(0, at);
}

// "Last, First" as "First Last"; "" for a name of another form.
std::string first_last(const std::string& name) {
    const size_t comma = name.find(',');
    if (comma == std::string::npos || name.find(',', comma + 1) != std::string::npos) return "";
    return trim(name.substr(comma + 1)) + " " + trim(name.substr(0, comma));
}

Fields roster_fields(const RosterStudent& s) {
    return {{"login", s.sis_login_id},
            {"login user", user_name(s.sis_login_id)},
            {"sis user", s.sis_user_id},
            {"id", s.id},
            {"name", s.name},
            {"first last", first_last(s.name)}};
}

Fields submission_fields(const std::vector<ClassRow>& rows, const SubmissionStudent& w) {
    static const Student kNone;
    const Student* named = student_of(rows, w);
    const Student& st = named ? *named : kNone;
    std::string key_name = rows[w.row].submission.key;
    std::replace(key_name.begin(), key_name.end(), '_', ' ');
    return {{"email", st.email}, {"email user", user_name(st.email)},
            {"sid", st.sid},     {"key", rows[w.row].submission.key},
            {"name", st.name},   {"key name", key_name}};
}

struct Pass {
    const char* by;
    std::vector<const char*> roster, submission;
};
// The order of docs/contract.md, `course grade-class`, Canvas and Moodle.
const Pass kPasses[] = {
    {"SIS Login ID = email", {"login"}, {"email"}},
    {"SIS Login ID = email's user name or submission",
     {"login", "login user"},
     {"email user", "key"}},
    {"SIS User ID = SID or submission", {"sis user"}, {"sid", "key"}},
    {"ID = submission", {"id"}, {"key"}},
    {"name", {"name", "first last"}, {"name", "key name"}},
};

// Value -> those on one side not yet matched that have it in one of `fields`.
std::map<std::string, std::set<size_t>> by_value(const std::vector<Fields>& side,
                                                 const std::vector<bool>& done,
                                                 const std::vector<const char*>& fields) {
    std::map<std::string, std::set<size_t>> found;
    for (size_t i = 0; i < side.size(); ++i)
        for (const char* f : fields)
            if (!done[i] && !normal(side[i].at(f)).empty()) found[normal(side[i].at(f))].insert(i);
    return found;
}

}  // namespace

std::vector<SubmissionStudent> submission_students(const std::vector<ClassRow>& rows) {
    std::vector<SubmissionStudent> all;
    for (size_t r = 0; r < rows.size(); ++r) {
        const size_t n = rows[r].submission.students.size();
        if (n == 0) all.push_back({r, -1});
        for (size_t i = 0; i < n; ++i) all.push_back({r, int(i)});
    }
    return all;
}

const Student* student_of(const std::vector<ClassRow>& rows, const SubmissionStudent& s) {
    return s.student < 0 ? nullptr : &rows[s.row].submission.students[size_t(s.student)];
}

std::vector<std::vector<std::string>> parse_csv(const std::string& text, char delimiter,
                                                const std::string& what) {
    csv_parser parser;
    if (csv_init(&parser, CSV_STRICT | CSV_STRICT_FINI) != 0)
        throw fw::Error("libcsv could not start a parser (out of memory)");
    csv_set_delim(&parser, static_cast<unsigned char>(delimiter));
    Records r;
    const size_t parsed = csv_parse(&parser, text.data(), text.size(), on_field, on_record, &r);
    std::string error;
    if (parsed != text.size()) {
        const long line = 1 + std::count(text.begin(), text.begin() + long(parsed), '\n');
        error = "line " + std::to_string(line) + ": " + csv_strerror(csv_error(&parser)) +
                " (a quote inside a field that does not start with one?)";
    } else if (csv_fini(&parser, on_field, on_record, &r) != 0) {
        error = "it ends inside a quoted field (a quote never closed)";
    }
    csv_free(&parser);
    if (!error.empty()) throw fw::UsageError(what + " is not CSV as RFC 4180 writes it: " + error);
    return std::move(r.done);
}

namespace {

// A row's field, blank where the row is short.
std::string cell(const std::vector<std::string>& row, long i) {
    return i >= 0 && size_t(i) < row.size() ? trim(row[size_t(i)]) : "";
}

bool is_email(const std::string& s) {
    const size_t at = s.find('@');
    return at != std::string::npos && at > 0 && at + 1 < s.size() &&
           s.find_first_of(" \t,;") == std::string::npos;
}

bool blank_row(const std::vector<std::string>& row) {
    return std::all_of(row.begin(), row.end(),
                       [](const std::string& c) { return trim(c).empty(); });
}

// Two students of one identifier are an error: Canvas and Moodle would give
// both the grades of one.
void check_unique(std::map<std::string, size_t>& seen, const std::string& value, size_t line,
                  const std::string& column, const std::string& what) {
    if (value.empty()) return;
    const auto [it, fresh] = seen.emplace(normal(value), line);
    if (!fresh)
        throw fw::UsageError(what + ": rows " + std::to_string(it->second) + " and " +
                             std::to_string(line) + " have the same " + column + ", " + value);
}

void read_canvas(Roster& roster, const CanvasLayout& l,
                 const std::vector<std::vector<std::string>>& records, const std::string& what) {
    roster.info_columns = l.info_columns;
    std::map<std::string, size_t> row_of_id;
    for (size_t i = 1; i < records.size(); ++i) {
        const std::vector<std::string>& row = records[i];
        if (!row.empty() && trim(row[0]).find("Points Possible") != std::string::npos)
            for (const std::string& c : row) roster.points_possible.push_back(trim(c));
        if (describes_assignments(row)) continue;
        RosterStudent s;
        for (size_t c = 0; c < l.info_columns; ++c) s.info.push_back(c < row.size() ? row[c] : "");
        // Canvas's import names a LastName, FirstName student "First Last";
        // "Last, First" is its sortable name, which it matches too.
        s.name = l.last_first ? cell(row, 0) + ", " + cell(row, 1) : cell(row, 0);
        s.id = cell(row, long(l.id));
        s.sis_user_id = cell(row, l.sis_user);
        s.sis_login_id = cell(row, l.sis_login);
        if (is_email(s.sis_login_id)) s.email = s.sis_login_id;
        check_unique(row_of_id, s.id, i + 1, "ID", what);
        roster.students.push_back(std::move(s));
    }
}

void read_moodle(Roster& roster, const std::vector<std::vector<std::string>>& records,
                 const std::string& what) {
    roster.kind = Roster::Kind::moodle;
    const std::vector<std::string>& h = roster.header;
    const auto column = [&](const char* name) -> long {
        const auto it = std::find(h.begin(), h.end(), name);
        return it == h.end() ? -1 : long(it - h.begin());
    };
    const long first = column("First name"), last = column("Last name"),
               email = column("Email address"), id_number = column("ID number");
    roster.has_id_number = id_number >= 0;
    std::map<std::string, size_t> row_of_email, row_of_number;
    for (size_t i = 1; i < records.size(); ++i) {
        const std::vector<std::string>& row = records[i];
        if (blank_row(row)) continue;
        RosterStudent s;
        const std::string f = cell(row, first), l = cell(row, last);
        s.name = !f.empty() && !l.empty() ? l + ", " + f : f + l;
        s.email = s.sis_login_id = cell(row, email);
        s.id_number = s.sis_user_id = cell(row, id_number);
        check_unique(row_of_email, s.email, i + 1, "Email address", what);
        check_unique(row_of_number, s.id_number, i + 1, "ID number", what);
        roster.students.push_back(std::move(s));
    }
}

}  // namespace

Roster read_roster(const fs::path& file) {
    const std::string what = "--roster '" + file.string() + "'";
    const std::vector<std::vector<std::string>> records = read_records(file, what);
    if (records.empty()) throw fw::UsageError(what + ": the file is empty");
    Roster roster;
    roster.file = file.string();
    for (const std::string& h : records[0]) roster.header.push_back(trim(h));
    const std::vector<std::string>& h = roster.header;
    const bool canvas_like = holds(h, 0, "Student") || holds(h, 0, "LastName");
    if (const std::optional<CanvasLayout> l = canvas_layout(h)) {
        read_canvas(roster, *l, records, what);
    } else if (canvas_like) {
        throw fw::UsageError(
            what +
            ": Canvas's import would refuse a file with this header (\"Invalid header row\"): "
            "it takes Student (or LastName, FirstName), ID, then SIS Login ID, or SIS User ID, "
            "SIS Login ID[, Integration ID][, Root Account], then Section, in that order, as "
            "Canvas's gradebook export (Grades > Export) writes them; found " +
            first_cells(h, 8));
    } else if (std::find(h.begin(), h.end(), "Email address") != h.end()) {
        read_moodle(roster, records, what);
    } else {
        throw fw::UsageError(
            what +
            ": its first row is the header of neither Canvas's gradebook export (Grades > "
            "Export: Student, ID, [SIS User ID,] SIS Login ID, Section, then the assignments) "
            "nor Moodle's grade export (Export > Plain text file: First name, Last name, ID "
            "number, ..., Email address, then the grade items); found " +
            first_cells(h, 6));
    }
    if (roster.students.empty()) throw fw::UsageError(what + ": no students in it");
    return roster;
}

RosterMatch match_roster(const Roster& roster, const std::vector<ClassRow>& rows) {
    std::vector<Fields> listed, submitted;
    for (const RosterStudent& s : roster.students) listed.push_back(roster_fields(s));
    const std::vector<SubmissionStudent> who = submission_students(rows);
    for (const SubmissionStudent& w : who) submitted.push_back(submission_fields(rows, w));

    RosterMatch m;
    m.of_student.resize(roster.students.size());
    std::vector<bool> matched(listed.size(), false), taken(who.size(), false);
    for (const Pass& pass : kPasses) {
        const auto on_roster = by_value(listed, matched, pass.roster);
        const auto submitting = by_value(submitted, taken, pass.submission);
        for (const auto& [value, students] : on_roster) {
            const auto subs = submitting.find(value);
            if (subs == submitting.end()) continue;
            if (students.size() > 1 || subs->second.size() > 1) {
                m.ambiguous.push_back(std::string(pass.by) + ": '" + value + "' names " +
                                      std::to_string(students.size()) + " roster rows and " +
                                      std::to_string(subs->second.size()) + " submission students");
                continue;
            }
            const size_t i = *students.begin(), j = *subs->second.begin();
            if (matched[i] || taken[j]) continue;
            m.of_student[i] = {true, who[j], pass.by};
            matched[i] = taken[j] = true;
        }
    }
    for (size_t j = 0; j < who.size(); ++j)
        if (!taken[j]) m.not_on_roster.push_back(who[j]);
    return m;
}

}  // namespace grading::cls
