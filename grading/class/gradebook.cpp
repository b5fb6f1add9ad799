#include "grading/class/gradebook.hpp"

#include "framework/text.hpp"
#include "grading/report/report_text.hpp"

namespace grading::cls {

namespace fs = std::filesystem;

namespace {

std::string in_quotes(const std::string& text) {
    std::string q = "\"";
    for (char ch : text) q += ch == '"' ? std::string("\"\"") : std::string(1, ch);
    return q + "\"";
}

std::string points(double v) { return fw::trimmed_decimals(v, 2); }

std::string status_of(const ClassRow& r) {
    if (!r.error.empty()) return "not graded: " + r.error;
    if (r.interrupted) return "interrupted: run grade-class again to finish";
    for (const auto& [id, lab] : r.labs)
        if (lab.status == "not built")
            return "does not build" + (r.first_error.empty() ? "" : ": " + r.first_error);
    for (const auto& [id, lab] : r.labs)
        if (lab.status != "graded")
            return id +
                   (lab.status == "not graded" ? " not graded: " + lab.reason : ": " + lab.status);
    return "graded";
}

}  // namespace

std::string csv_quoted(const std::string& text) {
    return text.find_first_of(",\"\r\n") == std::string::npos ? text : in_quotes(text);
}

std::string csv_field(const std::string& text) {
    if (!text.empty() && std::string("=+-@").find(text[0]) != std::string::npos)
        return in_quotes("'" + text);
    return csv_quoted(text);
}

void write_whole(const fs::path& file, const std::string& text) {
    const fs::path partial = file.string() + ".part";
    report::write_text_file(partial.string(), text);
    fs::rename(partial, file);
}

void write_grades_csv(const fs::path& file, const std::vector<ClassRow>& rows,
                      const std::vector<std::pair<std::string, std::string>>& labs) {
    std::string out = "id,name,email,submission";
    for (const auto& [id, dir] : labs) out += "," + csv_field(id);
    out += ",total,max,graded,late,missing,status\r\n";
    for (const ClassRow& r : rows) {
        std::vector<Student> students = r.submission.students;
        if (students.empty()) students.push_back({"", "", ""});
        double total = 0, max = 0;
        std::string labs_text;
        for (const auto& [id, dir] : labs) {
            const auto g = r.labs.find(id);
            labs_text += "," + (g == r.labs.end() ? std::string() : points(g->second.score));
            if (g != r.labs.end()) {
                total += g->second.score;
                max += g->second.max_score;
            }
        }
        for (const Student& s : students) {
            const std::string id = !s.sid.empty()     ? s.sid
                                   : !s.email.empty() ? s.email
                                                      : r.submission.key;
            out += csv_field(id) + "," + csv_field(s.name) + "," + csv_field(s.email) + "," +
                   csv_field(r.submission.key) + labs_text + "," + points(total) + "," +
                   points(max) + "," + csv_field(r.graded) + "," + (r.late ? "yes" : "no") + "," +
                   std::to_string(r.missing.size()) + "," + csv_field(status_of(r)) + "\r\n";
        }
    }
    write_whole(file, out);
}

}  // namespace grading::cls
