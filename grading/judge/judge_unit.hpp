// Judging a unit check (docs/contract.md, Checks): the child's results for
// every argument list against course's reference, and the report's text for
// the failures: values in math layout (matrices as rows), the first
// difference, and the usual mistakes that explain them (units/mistakes.hpp).
// Internal to `course`; the functions that lay values out are here for the
// tests.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "grading/judge/checks.hpp"
#include "grading/results/results.hpp"
#include "grading/units/reference.hpp"

namespace grading {

// One unit check of `lab`: `units` is the child's units.json (null when it
// could not be read, `units_why` saying why). `starting`, when not empty, is
// the sentence saying that a part the checkpoint needs still has its starting
// code (grading/diagnosis/starting_code.hpp): a failing check says it in place
// of the mistakes it would name, which such a result is no evidence of.
void judge_unit(const LabData& lab, const UnitCheck& check, const UnitPlan& plan, unsigned seed,
                const nlohmann::json* units, const std::string& units_why, CheckResult& r,
                const std::string& starting = "");

// A unit check's points when `passed` of `cases` cases passed: `max_score`
// in proportion, rounded down to a tenth of a point (1008 of 1009 cases of
// 4 points give 3.9); all of them only when every case passed.
double unit_points(double max_score, size_t passed, size_t cases);

// The line a unit check's report prints once above matrices.
extern const char* const kMatrixRowsNote;

// How many decimals show a difference of `tolerance`: 5 for 1e-4, 6 for 1e-5.
int unit_decimals(double tolerance);
// A number with at most `decimals` decimals, trailing zeros dropped: "0.5",
// "-1", "0.70711", "0" for a -0.000001 rounded away; "NaN", "Infinity",
// "-Infinity" as such.
std::string unit_number(double value, int decimals);
// A matrix given as GLM's columns (JSON [c][r]) as its rows, one string
// each, every column right-aligned: {"[ 1  0  2.5 ]", ...}. Empty when `m`
// is not a matrix of numbers.
std::vector<std::string> matrix_rows(const nlohmann::json& m, int decimals);
// A vector of numbers as "(x, y, z)"; empty when `v` is not one.
std::string vector_text(const nlohmann::json& v, int decimals);
// One failing case as the report prints it: the call with its arguments,
// expected and observed values whole (matrices in rows, side by side), and
// `why` (the first difference, or why there is no result). `observed` is
// null when the child gave none.
std::string unit_case_text(const ReferenceUnit& ref, const nlohmann::json& args, bool edge,
                           const nlohmann::json& expected, const nlohmann::json* observed,
                           const std::string& why, double tolerance);
// Where `observed` first differs from `expected` beyond `tolerance`, in the
// value's own terms: "[1] J, row 0, column 3 (GLM m[3][0]): expected 1.5,
// got 2"; results_match()'s text where the structures differ.
std::string unit_difference(const ReferenceUnit& ref, const nlohmann::json& expected,
                            const nlohmann::json& observed, double tolerance);

}  // namespace grading
