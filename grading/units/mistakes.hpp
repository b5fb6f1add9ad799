// Recognising the usual mistakes behind a failing unit check: the student's
// result is compared with values course computes itself, from the expected
// result (its transpose, its inverse, its translation moved into the bottom
// row, the direction left unnormalised) and from the reference (called with
// an angle negated or mixed up between degrees and radians, and the
// alternatives it declares, such as the product in reverse order). Nothing
// here comes from lab code. Pure functions on JSON values, as the child
// reports them (a matrix is an array of GLM's columns, m[c][r]).
#pragma once

#include <cstddef>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "grading/units/reference.hpp"

namespace grading {

// The mistake's stable name, as the report prints it: "transpose",
// "inverse", "reversed-product", "radians-for-degrees",
// "degrees-for-radians", "flipped-angle", "translation-in-bottom-row",
// "not-normalised", "flipped-axis", "last-column-for-diagonal",
// "length-squared", "off-by-one".
std::string_view mistake_id(Mistake mistake);

// One failing case of a unit check.
struct UnitFailure {
    nlohmann::json args;      // the argument list
    nlohmann::json expected;  // course's reference on it
    nlohmann::json observed;  // what the student's function returned
};

// A mistake that explains a failing case.
struct Explanation {
    Mistake mistake = Mistake::Transpose;
    int element = -1;   // a list result's first element that differs; -1: not a list
    int argument = -1;  // an angle mistake's argument (from 0); -1: every angle argument
    int rows = 0;       // FlippedAxis: bit r set for each row r negated
};

// The mistakes that explain one case: for each, a value course computes
// matches `observed` within `tolerance` (as results_match() compares) while
// differing from `expected`. An alternative equal to the expected value
// (a symmetric matrix's transpose, an angle of 0 negated) explains nothing.
// For a list, the first element that differs is the one explained. Empty
// when `observed` matches `expected` or has another structure.
std::vector<Explanation> explain_failure(const ReferenceUnit& ref, const UnitFailure& failure,
                                         double tolerance);

// How many failing cases recognise_mistakes() examines at most (the first).
constexpr std::size_t kMistakeCases = 100;

struct Recognised {
    // In the order of enum Mistake, each once; the element and argument are
    // those of most of the cases it explains.
    std::vector<Explanation> mistakes;
    // More than one mistake named, and every one explains the same cases
    // (a rotation's transpose is its inverse and its opposite angle).
    bool coincide = false;
};
// The mistakes that each explain more than half of the failing cases examined.
Recognised recognise_mistakes(const ReferenceUnit& ref, const std::vector<UnitFailure>& failures,
                              double tolerance);

// The report's line for a recognised mistake: "Likely mistake (ID): " and one
// sentence saying what the result looks like and where to look.
std::string likely_mistake(const ReferenceUnit& ref, const Explanation& explanation);

// The largest difference between two values of the same structure, number
// by number (infinite where the structures differ).
double largest_difference(const nlohmann::json& a, const nlohmann::json& b);

// Transformations of a square matrix given as GLM's columns (JSON [c][r]);
// nullopt when `m` is not one (or, for the inverse, is singular).
std::optional<nlohmann::json> transposed(const nlohmann::json& m);
std::optional<nlohmann::json> inverted(const nlohmann::json& m);
// The last column's entries above the corner moved into the bottom row's
// first entries (where a matrix typed for row vectors keeps its translation),
// the last column left (0, ..., 0, corner). For 3x3 and larger.
std::optional<nlohmann::json> translation_in_bottom_row(const nlohmann::json& m);
// The rows in `rows` (bit r for row r, above the bottom row) negated: whole
// (`with_last`) or all but their last entry. For 3x3 and larger.
std::optional<nlohmann::json> rows_negated(const nlohmann::json& m, int rows, bool with_last);
// The diagonal entries above the corner moved into the last column (row r's
// to m[n-1][r]), the diagonal left 1: a scale typed as a translation.
std::optional<nlohmann::json> diagonal_in_last_column(const nlohmann::json& m);

}  // namespace grading
