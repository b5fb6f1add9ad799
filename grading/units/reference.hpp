// Reference implementations for `unit` checks, in `course`'s own code (GLM or
// a closed form), never the lab's. Each lab keeps its references in its own
// folder (labs/NN_name/grading/*.cpp, compiled into `course` only) and
// registers them with one line each, for the lab of that folder:
//
//   COURSE_REFERENCE(translate, &ref_translate, {grading::vec(3, -10, 10)});
//
// For a unit check {"kind": "unit", "function": "translate", "random": 1000,
// "edge": [[[0, 0, 0]], ...]}, `course` draws `random` fresh argument lists from
// the domains (the seed is printed; COURSE_SEED fixes it), adds the edge
// cases, has the `lab` child evaluate the student's function on all of them,
// and compares each result with the reference's within the tolerance.
#pragma once

#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "framework/units.hpp"

namespace grading {

// Where one argument's random values come from.
struct ArgDomain {
    enum class Kind { Scalar, Integer, Vector, UnitVector, Bool } kind = Kind::Scalar;
    int size = 1;  // components, for vectors
    double lo = -1.0, hi = 1.0;
};
inline ArgDomain scalar(double lo, double hi) { return {ArgDomain::Kind::Scalar, 1, lo, hi}; }
inline ArgDomain integer(int lo, int hi) {
    return {ArgDomain::Kind::Integer, 1, double(lo), double(hi)};
}
inline ArgDomain vec(int n, double lo, double hi) { return {ArgDomain::Kind::Vector, n, lo, hi}; }
inline ArgDomain unit_vec(int n) { return {ArgDomain::Kind::UnitVector, n, -1.0, 1.0}; }
inline ArgDomain boolean() { return {ArgDomain::Kind::Bool, 1, 0.0, 1.0}; }

struct ReferenceUnit {
    std::string lab;                 // lab id, e.g. "transforms"
    fw::UnitFunction function;       // name + JSON call, as in the lab
    std::vector<ArgDomain> domains;  // one per argument
    double tolerance = 1e-4;         // default; a check may set its own
};

// Registers `unit` for the lab in folder `lab_dir` ("01_transforms"), which
// fills in unit.lab.
bool register_reference(std::string_view lab_dir, ReferenceUnit unit);
// Course's reference for a lab's unit function; throws fw::Error listing the
// lab's references when there is none by that name. The registry owns every
// reference for the life of the program; the names are taken as views so that
// temporary arguments cannot look like what the result points into.
const ReferenceUnit& find_reference(std::string_view lab, std::string_view function);

// One random argument list for `unit` (a JSON array, one element per argument).
nlohmann::json random_arguments(const ReferenceUnit& unit, std::mt19937& rng);

// Compares two results number by number (nested arrays of numbers, or
// bools); true when every number is within tolerance * max(1, |expected|).
// `why` gets the first difference, e.g. "[2][1]: expected 0.5, got 0.4999".
bool results_match(const nlohmann::json& expected, const nlohmann::json& observed, double tolerance,
                   std::string* why);

}  // namespace grading

#ifndef FW_LAB_DIR
#define FW_LAB_DIR ""  // only labs/NN_name/grading/*.cpp get the folder
#endif

#define COURSE_REFERENCE_CAT2(a, b) a##b
#define COURSE_REFERENCE_CAT(a, b) COURSE_REFERENCE_CAT2(a, b)
// COURSE_REFERENCE(function_name, &reference_fn, {domains...}[, tolerance])
#define COURSE_REFERENCE(NAME, FN, ...)                                                           \
    namespace {                                                                                   \
    static_assert(sizeof(FW_LAB_DIR) > 1,                                                         \
                  "COURSE_REFERENCE is only for files in labs/NN_name/grading/");                 \
    const bool COURSE_REFERENCE_CAT(course_reference_, __LINE__) = ::grading::register_reference( \
        FW_LAB_DIR, {"", ::fw::unit_function(#NAME, FN), __VA_ARGS__});                           \
    }
