#include "grading/results.hpp"

#include <algorithm>

namespace grading {

double LabResult::score() const {
    double s = 0.0;
    for (const CheckResult& c : checks) s += c.score;
    return s;
}

double LabResult::max_score() const {
    double s = 0.0;
    for (const CheckResult& c : checks) s += c.max_score;
    return s;
}

// A lab whose child failed has failed even when it has no checks to fail.
bool LabResult::passed() const {
    return status == "ok" &&
           std::all_of(checks.begin(), checks.end(), [](const CheckResult& c) { return c.passed; });
}

double GradeRun::score() const {
    double s = 0.0;
    for (const LabResult& l : labs) s += l.score();
    return s;
}

double GradeRun::max_score() const {
    double s = 0.0;
    for (const LabResult& l : labs) s += l.max_score();
    return s;
}

bool GradeRun::passed() const {
    return std::all_of(labs.begin(), labs.end(), [](const LabResult& l) { return l.passed(); });
}

}  // namespace grading
