#include "grading/class/import_files.hpp"

#include <algorithm>
#include <cstdio>
#include <regex>

#include "framework/text.hpp"

namespace grading::cls {

namespace fs = std::filesystem;

std::string import_points(double v) { return fw::trimmed_decimals(v, 2); }

// A lab's score as an import should take it: none where it was not graded
// (the submission could not be read, or course grade failed: grades.csv
// says why), whatever the student's code did otherwise.
std::optional<double> lab_score(const ClassRow& r, const std::string& lab) {
    const auto g = r.labs.find(lab);
    if (g == r.labs.end() || g->second.status == "not graded") return std::nullopt;
    return g->second.score;
}

// A roster student as messages name them.
std::string roster_who(const RosterStudent& st) {
    const std::string& key = !st.sis_login_id.empty() ? st.sis_login_id : st.id_number;
    return st.name + (key.empty() ? "" : " (" + key + ")");
}

namespace {

std::string points(double v) { return import_points(v); }

// The columns of `t` that `present` keeps, as one file's text.
std::string table_text(const ImportTable& t, const std::vector<bool>& present,
                       const std::vector<const ImportTable::Row*>& rows) {
    const auto kept = [&](std::vector<std::string> fields,
                          const std::vector<std::optional<std::string>>& cells) {
        for (size_t c = 0; c < cells.size(); ++c)
            if (present[c]) fields.push_back(cells[c].value_or(""));
        return line_of(fields);
    };
    const auto all = [](const std::vector<std::string>& v) {
        return std::vector<std::optional<std::string>>(v.begin(), v.end());
    };
    std::string text = kept(t.lead, all(t.columns));
    if (!t.possible_lead.empty()) text += kept(t.possible_lead, all(t.possible));
    for (const ImportTable::Row* r : rows) text += kept(r->lead, r->values);
    return text;
}

}  // namespace

// One CSV record, CRLF-ended. The import files are quoted as RFC 4180
// alone: an apostrophe before a leading '=' would change the very
// identifiers Canvas and Moodle match on.
std::string line_of(const std::vector<std::string>& fields,
                    std::string (*quote)(const std::string&)) {
    std::string line;
    for (size_t i = 0; i < fields.size(); ++i) line += (i ? "," : "") + quote(fields[i]);
    return line + "\r\n";
}

// Removes an earlier run's file that this run does not write; says so.
void remove_stale(const fs::path& file) {
    std::error_code ec;
    if (fs::remove(file, ec))
        std::fprintf(stderr, "grade-class: removed %s, an earlier run's\n", file.c_str());
}

// Removes BASE_N.csv from an earlier run for each N >= `from`.
void remove_stale_parts(const fs::path& out, const std::string& base, size_t from) {
    const std::regex part(base + R"(_(\d+)\.csv)");
    std::error_code ec;
    std::vector<fs::path> stale;
    for (const fs::directory_entry& e : fs::directory_iterator(out, ec)) {
        std::smatch m;
        const std::string name = e.path().filename().string();
        if (std::regex_match(name, m, part) && std::stoul(m[1].str()) >= from)
            stale.push_back(e.path());
    }
    std::sort(stale.begin(), stale.end());
    for (const fs::path& f : stale) remove_stale(f);
}

// Writes BASE.csv with every column and the rows that have a value in each,
// then BASE_2.csv, BASE_3.csv, ... for the other rows: one file per set of
// columns they have values in, holding only those columns. Neither import
// leaves a grade alone for a blank cell (Canvas: lib/gradebook_importer.rb,
// no_change_to_value? takes a blank under a score for a change, to no score;
// Moodle: grade/import/csv/classes/load_data.php, update_grade_item makes ''
// and '-' a null grade, which grade/import/lib.php, grade_import_commit,
// writes over the one it has), while a student or a column that the file
// does not have keeps the grade it has. Says on stderr who is not in
// BASE.csv, and where the rest of their points are.
void write_split(const fs::path& out, const std::string& base, const ImportTable& t) {
    const size_t n = t.columns.size();
    std::vector<std::vector<bool>> sets = {std::vector<bool>(n, true)};
    std::vector<std::vector<const ImportTable::Row*>> parts(1);
    for (const ImportTable::Row& r : t.rows) {
        std::vector<bool> present(n);
        std::vector<std::string> missing;
        for (size_t c = 0; c < n; ++c) {
            present[c] = r.values[c].has_value();
            if (!present[c]) missing.push_back(t.columns[c]);
        }
        if (missing.size() == n) {
            std::fprintf(stderr, "grade-class: %s.csv: no row for %s, whose %s not graded\n",
                         base.c_str(), r.who.c_str(),
                         (fw::join(missing, ", ") + (n > 1 ? " were" : " was")).c_str());
            continue;
        }
        const size_t k = size_t(std::find(sets.begin(), sets.end(), present) - sets.begin());
        if (k == sets.size()) {
            sets.push_back(present);
            parts.emplace_back();
        }
        parts[k].push_back(&r);
        if (k > 0)
            std::fprintf(
                stderr,
                "grade-class: %s.csv: no row for %s, whose %s not graded; %s_%zu.csv "
                "has the other columns\n",
                base.c_str(), r.who.c_str(),
                (fw::join(missing, ", ") + (missing.size() > 1 ? " were" : " was")).c_str(),
                base.c_str(), k + 1);
    }
    for (size_t k = 0; k < sets.size(); ++k)
        write_whole(out / (k ? base + "_" + std::to_string(k + 1) + ".csv" : base + ".csv"),
                    table_text(t, sets[k], parts[k]));
    remove_stale_parts(out, base, sets.size() + 1);
    if (sets.size() > 1) {
        const std::string last = base + "_" + std::to_string(sets.size()) + ".csv";
        std::fprintf(stderr,
                     "grade-class: import %s_2.csv%s after %s.csv: a student or a column that a "
                     "file leaves out keeps the grade the gradebook has, while a blank cell "
                     "would erase it\n",
                     base.c_str(), sets.size() > 2 ? (" to " + last).c_str() : "", base.c_str());
    }
}

// DIR/moodle_items.csv: the grade item to make for each column of
// moodle.csv, with its maximum; the same on stderr, and where a maximum is
// above 100, what Moodle's import needs for it.
void write_moodle_items(const fs::path& out, const std::vector<std::string>& labs, bool total,
                        const std::map<std::string, double>& max) {
    std::string text = line_of({"grade item", "maximum grade"});
    std::vector<std::string> said, above;
    double sum = 0;
    bool known = true;
    const auto item = [&](const std::string& name, std::optional<double> m) {
        text += line_of({name, m ? points(*m) : ""});
        said.push_back(name + " " + (m ? points(*m) : "?"));
        if (m && *m > 100) above.push_back(name + " (" + points(*m) + ")");
    };
    for (const std::string& id : labs) {
        const auto m = max.find(id);
        known = known && m != max.end();
        if (m != max.end()) sum += m->second;
        item(id, m == max.end() ? std::nullopt : std::optional<double>(m->second));
    }
    if (total) item("Total", known ? std::optional<double>(sum) : std::nullopt);
    write_whole(out / "moodle_items.csv", text);
    std::fprintf(stderr,
                 "grade-class: moodle.csv: before importing, give each column a grade item with "
                 "its maximum (Gradebook setup > Add grade item, Maximum grade): %s "
                 "(moodle_items.csv); a grade item the import makes is out of 100\n",
                 fw::join(said, ", ").c_str());
    if (!above.empty())
        std::fprintf(stderr,
                     "grade-class: moodle.csv: Moodle's import refuses the whole file for a "
                     "grade above 100 unless the site allows it (Site administration > Grades "
                     "> General settings: Unlimited grades, and Grade point maximum at least "
                     "the points): %s\n",
                     fw::join(above, ", ").c_str());
}

// A number as Canvas's import reads a cell (lib/gradebook_importer.rb, the
// decimal_comma_to_period converter: the last ',' or '.' is the decimal
// point, the others are dropped); none for another text.
std::optional<double> canvas_number(const std::string& cell) {
    static const std::regex number(R"(-?[0-9.,]+)");
    if (!std::regex_match(cell, number)) return std::nullopt;
    const size_t point = cell.find_last_of(".,");
    std::string digits;
    for (size_t i = 0; i < cell.size(); ++i)
        if (i == point)
            digits += '.';
        else if (cell[i] != '.' && cell[i] != ',')
            digits += cell[i];
    try {
        return std::stod(digits);
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

void remove_all_stale(const fs::path& out, const std::vector<std::string>& bases) {
    for (const std::string& base : bases) {
        remove_stale(out / (base + ".csv"));
        remove_stale_parts(out, base, 2);
    }
}

}  // namespace grading::cls
