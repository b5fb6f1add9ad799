#include "grading/results/results.hpp"

#include <algorithm>
#include <cmath>

#include "framework/error.hpp"

namespace grading {

const char* name_of(CheckKind kind) {
    switch (kind) {
        case CheckKind::Image:
            return "image";
        case CheckKind::Probe:
            return "probe";
        case CheckKind::Stat:
            return "stat";
        case CheckKind::Unit:
            return "unit";
        case CheckKind::Forbidden:
            return "forbidden";
        case CheckKind::Buffer:
            return "buffer";
        case CheckKind::Portable:
            return "portable";
        case CheckKind::State:
            return "state";
    }
    return "?";
}

const char* name_of(Visibility visibility) {
    return visibility == Visibility::Hidden ? "hidden" : "visible";
}

Visibility visibility_named(const std::string& name) {
    if (name == name_of(Visibility::Visible)) return Visibility::Visible;
    if (name == name_of(Visibility::Hidden)) return Visibility::Hidden;
    throw fw::Error("visibility \"" + name + "\"; a checkpoint's visibility is visible or hidden");
}

LabStatus LabStatus::failed(std::string why) {
    LabStatus s;
    s.why_ = why.empty() ? "failed" : std::move(why);
    return s;
}

const std::string& LabStatus::text() const {
    static const std::string kOk = "ok";
    return ok() ? kOk : why_;
}

double rounded_points(double sum) { return std::round(sum * 1e6) / 1e6; }

double LabResult::score() const {
    double s = 0.0;
    for (const CheckResult& c : checks) s += c.score;
    return rounded_points(s);
}

double LabResult::max_score() const {
    double s = 0.0;
    for (const CheckResult& c : checks) s += c.max_score;
    return s;
}

// A lab whose child failed has failed even when it has no checks to fail.
bool LabResult::passed() const {
    return status.ok() &&
           std::all_of(checks.begin(), checks.end(), [](const CheckResult& c) { return c.passed; });
}

double GradeRun::score() const {
    double s = 0.0;
    for (const LabResult& l : labs) s += l.score();
    return rounded_points(s);
}

double GradeRun::max_score() const {
    double s = 0.0;
    for (const LabResult& l : labs) s += l.max_score();
    return s;
}

bool GradeRun::passed() const {
    return std::all_of(labs.begin(), labs.end(), [](const LabResult& l) { return l.passed(); });
}

namespace {

// The count and points of what each lab left out, summed: the state checks'
// where `state`, else the hidden checkpoints'.
GradeRun::LeftOut summed(const std::vector<LabResult>& labs, bool state) {
    GradeRun::LeftOut out;
    for (const LabResult& lab : labs) {
        out.checkpoints += state ? lab.state_left_out : lab.hidden_left_out;
        out.points += state ? lab.state_points_left_out : lab.hidden_points_left_out;
    }
    out.points = rounded_points(out.points);
    return out;
}

}  // namespace

GradeRun::LeftOut GradeRun::hidden_left_out() const { return summed(labs, false); }

GradeRun::LeftOut GradeRun::state_left_out() const { return summed(labs, true); }

}  // namespace grading
