// Where a grading's time went, lab by lab (reports.hpp, time_table).
#include <cstdio>
#include <string>

#include "grading/report/report_text.hpp"
#include "grading/report/reports.hpp"

namespace grading {

namespace {

// One row: the lab's id and its columns, each 7 wide with 3 decimals.
std::string row(const std::string& name, const std::vector<double>& columns) {
    char head[32];
    std::snprintf(head, sizeof head, "%-18.18s", name.c_str());
    std::string line = head;
    for (double c : columns) {
        char cell[16];
        std::snprintf(cell, sizeof cell, " %7.3f", c);
        line += cell;
    }
    return line + "\n";
}

std::vector<double> columns(const LabResult& lab) {
    const LabTime& t = lab.time;
    return {lab.seconds,    t.plan,        t.child_units, t.child_start,  t.child_render,
            t.child_record, t.child_usage, t.judge_units, t.judge_frames, t.report};
}

}  // namespace

std::string time_table(const GradeRun& run, double reports_seconds) {
    std::string out =
        "Time (seconds): each lab's child from its start to its end (child), course's plan of "
        "its job (plan), the child's unit calls, context and init, and renders (of which the "
        "per-draw record and the usage checks), and course's judging of the unit checks, of "
        "the other checks, and the report's images of its frames\n";
    out +=
        "lab                  child    plan   units   start  render  record   usage"
        " j.units  j.other  images\n";
    std::vector<double> total(10, 0.0);
    for (const LabResult& lab : run.labs) {
        const std::vector<double> c = columns(lab);
        for (size_t i = 0; i < c.size(); ++i) total[i] += c[i];
        out += row(lab.lab, c);
    }
    out += row("all labs", total);
    out += "The reports (summary.txt, results.json, junit.xml, index.html): " +
           report::fixed(reports_seconds, 3) + " s\n";
    return out;
}

}  // namespace grading
