#include "grading/class/class_rows.hpp"

#include <algorithm>
#include <cstdio>
#include <nlohmann/json.hpp>

#include "framework/error.hpp"
#include "grading/class/class_page.hpp"
#include "grading/class/gradebook.hpp"
#include "grading/release/release.hpp"
#include "grading/report/report_text.hpp"

namespace grading::cls {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

void write_json(const fs::path& file, const json& j) {
    const fs::path partial = file.string() + ".part";
    report::write_text_file(partial.string(), j.dump(2) + "\n");
    fs::rename(partial, file);
}

json row_json(const ClassRow& r) {
    json students = json::array();
    for (const Student& s : r.submission.students)
        students.push_back({{"name", s.name}, {"email", s.email}, {"sid", s.sid}});
    json labs = json::object();
    for (const auto& [id, g] : r.labs)
        labs[id] = {{"status", g.status},
                    {"score", g.score},
                    {"max_score", g.max_score},
                    {"reason", g.reason}};
    return {{"key", r.submission.key},  {"students", students}, {"graded", r.graded},
            {"late", r.late},           {"error", r.error},     {"first_error", r.first_error},
            {"missing", r.missing},     {"extra", r.extra},     {"labs", labs},
            {"build_cpu", r.build_cpu}, {"seconds", r.seconds}};
}

ClassRow row_of(const json& j) {
    ClassRow r;
    r.submission.key = j.at("key");
    for (const json& s : j.at("students"))
        r.submission.students.push_back({s.at("name"), s.at("email"), s.at("sid")});
    r.graded = j.at("graded");
    r.late = j.at("late");
    r.error = j.at("error");
    r.first_error = j.at("first_error");
    r.missing = j.at("missing").get<std::vector<std::string>>();
    r.extra = j.at("extra").get<std::vector<std::string>>();
    for (const auto& [id, g] : j.at("labs").items()) r.labs[id] = lab_grade_of(g);
    r.build_cpu = j.at("build_cpu");
    r.seconds = j.at("seconds");
    return r;
}

}  // namespace

LabGrade lab_grade_of(const json& j) {
    LabGrade g;
    g.status = j.at("status");
    g.score = j.at("score");
    g.max_score = j.at("max_score");
    g.reason = j.at("reason");
    g.resumed = true;
    return g;
}

void write_row(const fs::path& out, const ClassRow& row) {
    const fs::path dir = out / "students" / row.submission.key;
    fs::create_directories(dir);
    write_json(dir / "row.json", row_json(row));
}

void write_class_file(const fs::path& out, const LabList& labs) {
    json list = json::array();
    for (const auto& [id, dir] : labs) list.push_back({{"lab", id}, {"folder", dir}});
    write_json(out / "class.json", {{"labs", list}});
}

ClassResult read_class(const fs::path& dir) {
    ClassResult result;
    const fs::path file = dir / "class.json";
    try {
        const json doc = json::parse(read_file(file));
        for (const json& l : doc.at("labs")) {
            result.labs.emplace_back(l.at("lab"), l.at("folder"));
        }
    } catch (const std::exception& e) {
        throw fw::UsageError(file.string() + ": " + e.what() +
                             " (is it a folder that grade-class --out wrote?)");
    }
    std::error_code ec;
    for (const auto& e : fs::directory_iterator(dir / "students", ec)) {
        const fs::path row = e.path() / "row.json";
        if (!fs::exists(row)) continue;  // interrupted before its first lab
        try {
            result.rows.push_back(row_of(json::parse(read_file(row))));
        } catch (const std::exception& ex) {
            throw fw::UsageError(row.string() + ": " + ex.what());
        }
    }
    std::sort(result.rows.begin(), result.rows.end(), [](const ClassRow& a, const ClassRow& b) {
        return a.submission.key < b.submission.key;
    });
    return result;
}

int merge_class_command(const std::string& out, const std::vector<std::string>& dirs,
                        const LmsOptions& lms) {
    if (dirs.empty()) throw fw::UsageError("merge-class needs the folders of the slices");
    ClassResult all;
    for (const std::string& d : dirs) {
        ClassResult slice = read_class(d);
        if (&d != &dirs.front() && slice.labs != all.labs)
            throw fw::UsageError("'" + d + "' graded other labs than '" + dirs.front() +
                                 "': merge only slices of one assignment");
        all.labs = slice.labs;
        for (ClassRow& r : slice.rows) {
            for (const ClassRow& seen : all.rows)
                if (seen.submission.key == r.submission.key)
                    throw fw::UsageError("'" + r.submission.key +
                                         "' is in two slices: were they cut with the same N?");
            const fs::path to = fs::path(out) / "students" / r.submission.key;
            std::error_code ec;
            fs::remove_all(to, ec);
            fs::create_directories(to.parent_path());
            fs::copy(fs::path(d) / "students" / r.submission.key, to, fs::copy_options::recursive);
            all.rows.push_back(std::move(r));
        }
    }
    std::sort(all.rows.begin(), all.rows.end(), [](const ClassRow& a, const ClassRow& b) {
        return a.submission.key < b.submission.key;
    });
    write_class_file(out, all.labs);
    write_grades_csv(fs::path(out) / "grades.csv", all.rows, all.labs);
    size_t failed = 0;
    double seconds = 0;  // the slices' grading, added up
    for (const ClassRow& r : all.rows) {
        failed += r.failed();
        seconds += r.seconds;
    }
    write_class_page(out, all.rows, all.labs, seconds);
    LmsExport(lms, all.labs).write(out, all.rows, "");
    std::printf("merge-class: %zu submissions from %zu slices, %zu not fully graded; %s\n",
                all.rows.size(), dirs.size(), failed, (fs::path(out) / "grades.csv").c_str());
    return failed ? 1 : 0;
}

}  // namespace grading::cls
