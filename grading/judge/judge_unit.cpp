// Judging unit checks: every case's result from the child against course's
// reference, and the failures laid out as the lecture writes values, with
// the usual mistakes named where they explain them.
#include "grading/judge/judge_unit.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exception>
#include <optional>

#include "framework/json_glm.hpp"
#include "framework/text.hpp"
#include "grading/units/mistakes.hpp"

namespace grading {

namespace {

using nlohmann::json;

// Failing cases shown in full; the others are only counted.
constexpr int kShownCases = 3;
// What a value that is not of the reference's form (a malformed result) is
// cut to: it comes from the child and may be huge.
constexpr size_t kRawMax = 400;

const char* const kSameValuesNote =
    "The likely mistakes above give the same values on these cases, so any one of them may be "
    "the cause.";

std::string exact(double v) { return fw::number_text(v, 9); }

std::string tolerance_text(double v) { return fw::number_text(v, 7); }

// A value of unknown form as JSON, cut to kRawMax characters.
std::string raw_text(const json& j) {
    std::string s = j.dump();
    return s.size() > kRawMax ? s.substr(0, kRawMax) + "..." : s;
}

// One argument as the call is written: numbers exactly as evaluated,
// vectors as vecN(x, y, z).
std::string argument_text(const json& a) {
    if (a.is_number_float()) return exact(a.get<double>());
    if (a.is_array() && !a.empty() &&
        std::all_of(a.begin(), a.end(), [](const json& v) { return v.is_number(); }))
        return "vec" + std::to_string(a.size()) + "(" +
               fw::join(a, ", ", [](const json& v) { return argument_text(v); }) + ")";
    return raw_text(a);
}

std::string call_text(const ReferenceUnit& ref, const json& args) {
    if (!args.is_array()) return ref.function.name + "(" + raw_text(args) + ")";
    return ref.function.name + "(" + fw::join(args, ", ", argument_text) + ")";
}

// A value that is neither a matrix nor a vector, or is not of its form.
std::string other_text(const json& v, int decimals) {
    const std::optional<double> x = fw::json_number(v);
    if (x && (v.is_number_float() || v.is_string())) return unit_number(*x, decimals);
    return raw_text(v);
}

std::string value_text(const ValueShape& shape, const json& v, int decimals) {
    if (shape.kind == ValueShape::Kind::Vector) {
        std::string s = vector_text(v, decimals);
        if (!s.empty()) return s;
    }
    return other_text(v, decimals);
}

// Two blocks of lines side by side, each under its label.
std::string side_by_side(const std::string& indent, const std::string& left_label,
                         const std::vector<std::string>& left, const std::string& right_label,
                         const std::vector<std::string>& right) {
    size_t width = left_label.size();
    for (const std::string& l : left) width = std::max(width, l.size());
    width += 4;
    auto line = [&](const std::string& a, const std::string& b) {
        std::string s = indent + a + std::string(width - a.size(), ' ') + b;
        return s.substr(0, s.find_last_not_of(' ') + 1) + "\n";
    };
    std::string out = line(left_label, right_label);
    for (size_t i = 0; i < std::max(left.size(), right.size()); ++i)
        out += line(i < left.size() ? left[i] : "", i < right.size() ? right[i] : "");
    return out;
}

// A matrix's rows, or its raw text when it is not a matrix.
std::vector<std::string> rows_or_raw(const json& m, int decimals) {
    std::vector<std::string> rows = matrix_rows(m, decimals);
    if (rows.empty()) rows.push_back(raw_text(m));
    return rows;
}

std::string single_value(const ValueShape& shape, const json& expected, const json* observed,
                         const std::string& indent, int decimals) {
    if (shape.kind == ValueShape::Kind::Matrix)
        return side_by_side(
            indent, "expected (rows):", rows_or_raw(expected, decimals), "observed (rows):",
            observed ? rows_or_raw(*observed, decimals) : std::vector<std::string>{"none"});
    return indent + "expected: " + value_text(shape, expected, decimals) + "\n" + indent +
           "observed: " + (observed ? value_text(shape, *observed, decimals) : "none") + "\n";
}

std::string element_label(const ReferenceUnit& ref, size_t k) {
    return "[" + std::to_string(k) + "]" +
           (k < ref.element_names.size() ? " " + ref.element_names[k] : "");
}

std::string list_value(const ReferenceUnit& ref, const json& expected, const json* observed,
                       double tolerance, int decimals) {
    const ValueShape& shape = ref.shape;
    const bool paired = observed && observed->is_array() && observed->size() == expected.size();
    std::string out;
    if (shape.kind == ValueShape::Kind::Matrix) {
        // Each differing matrix whole; those that match in one line.
        for (size_t k = 0; k < expected.size(); ++k) {
            const std::string label = "    " + element_label(ref, k);
            if (paired && results_match(expected[k], (*observed)[k], tolerance, nullptr)) {
                out += label + ": as expected\n";
                continue;
            }
            out += label + ":\n";
            if (paired) {
                out += single_value(shape, expected[k], &(*observed)[k], "      ", decimals);
            } else {
                out += side_by_side("      ",
                                    "expected (rows):", rows_or_raw(expected[k], decimals), "", {});
            }
        }
    } else {
        std::vector<std::string> left, right;
        for (size_t k = 0; k < expected.size(); ++k) {
            left.push_back(element_label(ref, k) + " " + value_text(shape, expected[k], decimals));
            if (!paired) continue;
            const bool same = results_match(expected[k], (*observed)[k], tolerance, nullptr);
            right.push_back(value_text(shape, (*observed)[k], decimals) +
                            (same ? "" : "   <- differs"));
        }
        out += side_by_side("    ", "expected:", left, paired ? "observed:" : "", right);
    }
    if (!paired) out += "    observed: " + (observed ? raw_text(*observed) : "none") + "\n";
    return out;
}

// The first difference, as a path of indices: 1 where it is between two
// numbers, 2 where the structures differ, 0 where there is none.
int first_difference(const json& e, const json& o, double tolerance, std::vector<size_t>& path) {
    if (e.is_array()) {
        if (!o.is_array() || o.size() != e.size()) return 2;
        for (size_t i = 0; i < e.size(); ++i) {
            path.push_back(i);
            if (int found = first_difference(e[i], o[i], tolerance, path)) return found;
            path.pop_back();
        }
        return 0;
    }
    if (e.is_number()) {
        const std::optional<double> y = fw::json_number(o);
        if (!y) return 2;
        const double x = e.get<double>();
        return !std::isfinite(*y) || std::fabs(x - *y) > tolerance * std::max(1.0, std::fabs(x))
                   ? 1
                   : 0;
    }
    return o == e ? 0 : 2;
}

// The reference's failure, or the student's, or the missing result, in words.
struct CaseOutcome {
    json expected;
    bool has_expected = false;
    const json* observed = nullptr;
    bool passed = false;
    std::string why;
};

CaseOutcome evaluate(const ReferenceUnit& ref, const UnitCase& c, const json* entry,
                     double tolerance) {
    CaseOutcome out;
    try {
        out.expected = ref.function.call(c.args);
        out.has_expected = true;
    } catch (const std::exception& e) {
        out.why = std::string("course's reference failed: ") + e.what();
        return out;
    }
    if (!entry || !entry->is_object() ||
        (!entry->contains("result") && !entry->contains("error"))) {
        out.why = "no result for this case in units.json";
    } else if (entry->contains("error")) {
        const json& error = (*entry)["error"];
        out.why = "the function failed: " +
                  (error.is_string() ? error.get<std::string>() : raw_text(error));
    } else {
        out.observed = &(*entry)["result"];
        out.passed = results_match(out.expected, *out.observed, tolerance, nullptr);
        if (!out.passed)
            out.why =
                "first difference: " + unit_difference(ref, out.expected, *out.observed, tolerance);
    }
    return out;
}

// A unit check's points: in proportion to the cases passed, rounded down to
// a tenth of a point, so that any failing case costs something.
void verdict(CheckResult& r, size_t passed, size_t cases, const std::string& output) {
    r.passed = cases > 0 && passed == cases;
    r.score = r.passed ? r.max_score : unit_points(r.max_score, passed, cases);
    r.output = output;
}

// A value the child returned, as a number, with what a NaN or an infinity
// usually means.
std::string observed_number(const json& o) {
    const double y = fw::json_number(o).value_or(0.0);
    if (std::isfinite(y)) return exact(y);
    return std::string(fw::non_finite_name(y)) + " (" + non_finite_hint(y) + ")";
}

// The first number in `v` (depth first) that is not finite; 0 when none is.
double first_non_finite(const json& v) {
    if (v.is_array())
        for (const json& x : v)
            if (const double y = first_non_finite(x); y != 0.0) return y;
    const std::optional<double> y = fw::json_number(v);
    return y && !std::isfinite(*y) ? *y : 0.0;
}

}  // namespace

const char* const kMatrixRowsNote =
    "Matrices are printed in rows as in the lecture (row r, column c); GLM stores them by "
    "column, m[c][r].";

std::string unit_difference(const ReferenceUnit& ref, const json& expected, const json& observed,
                            double tolerance) {
    std::vector<size_t> path;
    std::string why;
    if (first_difference(expected, observed, tolerance, path) != 1) {
        results_match(expected, observed, tolerance, &why);
        return why;
    }
    const json* e = &expected;
    const json* o = &observed;
    for (size_t i : path) {
        e = &(*e)[i];
        o = &(*o)[i];
    }
    std::vector<std::string> where;
    size_t at = 0;
    if (ref.shape.list && at < path.size()) where.push_back(element_label(ref, path[at++]));
    const size_t left = path.size() - at;
    if (ref.shape.kind == ValueShape::Kind::Matrix && left == 2) {
        const std::string c = std::to_string(path[at]), r = std::to_string(path[at + 1]);
        where.push_back("row " + r + ", column " + c + " (GLM m[" + c + "][" + r + "])");
    } else if (ref.shape.kind == ValueShape::Kind::Vector && left == 1) {
        const size_t c = path[at];
        where.push_back("component " + (c < ref.component_names.size() ? ref.component_names[c]
                                        : c < 4                        ? std::string(1, "xyzw"[c])
                                                                       : std::to_string(c)));
    } else {
        for (; at < path.size(); ++at) where.push_back("[" + std::to_string(path[at]) + "]");
    }
    return fw::join(where, ", ") + (where.empty() ? "" : ": ") + "expected " +
           exact(e->get<double>()) + ", got " + observed_number(*o);
}

std::string unit_case_text(const ReferenceUnit& ref, const json& args, bool edge,
                           const json& expected, const json* observed, const std::string& why,
                           double tolerance) {
    const int decimals = unit_decimals(tolerance);
    std::string out = "  " + call_text(ref, args) + (edge ? " [edge case]" : "") + "\n";
    if (ref.shape.list && expected.is_array())
        out += list_value(ref, expected, observed, tolerance, decimals);
    else
        out += single_value(ref.shape, expected, observed, "    ", decimals);
    if (!why.empty()) out += "    " + why + "\n";
    return out;
}

namespace {

// Every case against the reference: how many passed, the first failures as
// the report shows them, and those with a result for recognising mistakes.
struct CaseTally {
    size_t passed = 0;
    std::string first_case, shown;
    double non_finite = 0.0;            // the first NaN or infinity returned, else 0
    std::vector<UnitFailure> failures;  // those with a result, for recognising mistakes
};

CaseTally tally_cases(const ReferenceUnit& ref, const UnitPlan& plan, const json& units, double tol,
                      const std::string& starting) {
    CaseTally t;
    int shown_count = 0;
    for (const UnitCase& c : plan.cases) {
        const json* entry = units.contains(c.id) ? &units[c.id] : nullptr;
        CaseOutcome outcome = evaluate(ref, c, entry, tol);
        if (outcome.passed) {
            ++t.passed;
            continue;
        }
        // A part still at its starting code: its first difference only,
        // not the whole expected value, which would be the answer.
        const std::string text =
            starting.empty() ? unit_case_text(ref, c.args, c.edge, outcome.expected,
                                              outcome.observed, outcome.why, tol)
                             : "  " + call_text(ref, c.args) + (c.edge ? " [edge case]" : "") +
                                   "\n    " + outcome.why + "\n";
        if (shown_count++ == 0) t.first_case = text;
        if (shown_count <= kShownCases) t.shown += text;
        if (outcome.observed && t.non_finite == 0.0)
            t.non_finite = first_non_finite(*outcome.observed);
        if (outcome.observed && t.failures.size() < kMistakeCases)
            t.failures.push_back({c.args, std::move(outcome.expected), *outcome.observed});
    }
    return t;
}

}  // namespace

void judge_unit(const LabData& lab, const UnitCheck& check, const UnitPlan& plan, unsigned seed,
                const json* units, const std::string& units_why, CheckResult& r,
                const std::string& starting) {
    const ReferenceUnit& ref = find_reference(lab.id, check.function);
    const double tol = check.tolerance.value_or(ref.tolerance);
    size_t edges = 0;
    for (const UnitCase& c : plan.cases) edges += c.edge ? 1 : 0;
    r.title = "unit " + ref.function.name + " (" + std::to_string(plan.cases.size()) + " cases)";
    // Recorded cases (a student's copy) are the same in every run.
    const std::string source = ref.recorded ? ref.recorded_cases
                                            : "seed " + std::to_string(seed) +
                                                  " (COURSE_SEED=" + std::to_string(seed) +
                                                  " repeats these cases)";
    std::string head =
        source + ": " + std::to_string(plan.cases.size() - edges) + " random and " +
        std::to_string(edges) + " edge cases; tolerance " + tolerance_text(tol) +
        " (relative where |expected| > 1)\nExpected: every case equal to course's reference\n";
    if (!units)
        return verdict(r, 0, plan.cases.size(), head + "Observed: no results: " + units_why);
    const CaseTally tally = tally_cases(ref, plan, *units, tol, starting);
    const size_t passed = tally.passed;
    const std::vector<UnitFailure>& failures = tally.failures;
    const std::string& shown = tally.shown;
    const double non_finite = tally.non_finite;
    r.first_case = tally.first_case;
    std::string out = head + "Observed: " + std::to_string(passed) + " of " +
                      std::to_string(plan.cases.size()) + " cases passed";
    if (!shown.empty()) {
        const Recognised recognised = recognise_mistakes(ref, failures, tol);
        std::vector<std::string> diagnosis;
        for (const Explanation& e : recognised.mistakes)
            diagnosis.push_back(likely_mistake(ref, e));
        if (recognised.coincide) diagnosis.push_back(kSameValuesNote);
        if (!starting.empty()) diagnosis = {starting};
        if (non_finite != 0.0)
            diagnosis.push_back("Your function returned " +
                                std::string(fw::non_finite_name(non_finite)) + ": " +
                                non_finite_hint(non_finite));
        r.diagnosis = fw::join(diagnosis, "\n");
        if (!diagnosis.empty()) out += "\n" + r.diagnosis;
        out += "\nFirst failures:\n";
        if (ref.shape.kind == ValueShape::Kind::Matrix && starting.empty())
            out += std::string(kMatrixRowsNote) + "\n";
        out += shown;
    }
    verdict(r, passed, plan.cases.size(), out);
}

}  // namespace grading
