// Reference implementations for `unit` checks, in `course`'s own code (GLM or
// a closed form), never the lab's. Each lab keeps its references in its own
// folder (labs/NN_name/grading/*.cpp, compiled into `course` only) and
// registers them with one line each, for the lab of that folder:
//
//   COURSE_REFERENCE(translate, &ref_translate, {grading::vec(3, -10, 10)})
//   COURSE_REFERENCE(rotateZ, &ref_rotate_z, {grading::degrees(-720, 720)})
//   COURSE_REFERENCE(compose, &ref_compose, {...domains},
//                    grading::reversed_product(&ref_compose_reversed))
//
// For a unit check {"kind": "unit", "function": "translate", "random": 1000,
// "edge": [[[0, 0, 0]], ...]}, `course` draws `random` fresh argument lists from
// the domains (the seed is printed; COURSE_SEED fixes it), adds the edge
// cases, has the `lab` child evaluate the student's function on all of them,
// and compares each result with the reference's within the tolerance.
//
// When cases fail, the report names the usual mistakes that explain them
// (grading/units/mistakes.hpp): it compares the student's results with
// transformations of the expected one (transpose, inverse, translation in
// the bottom row, a vector of another length) and with the reference called on
// changed arguments. What it may change comes from the registration, after
// the domains and in any order:
//   - an argument whose domain is grading::degrees() is an angle in degrees:
//     the reference is also called with it negated, read as radians
//     (times 180/pi) and converted twice (times pi/180);
//   - grading::reversed_product(&fn): fn computes the result with the
//     product(s) in the other order (several may be given);
//   - grading::not_normalised(&fn): fn computes it without normalising a
//     direction the function must normalise;
//   - grading::length_squared(&fn): fn divides that direction by its length
//     squared instead of its length;
//   - grading::off_by_one("words"): a number result 1 more or 1 less than
//     expected is a mistake worth naming for this function (a level or a
//     count that starts at 1 where it starts at 0), said in these words, the
//     function's own; without it a difference of 1 names nothing (an index
//     in a sorted order that is 1 off is no mistake of counting);
//   - grading::element_names({"a", "b", ...}): names for the elements of a
//     std::vector result, for the report (an aggregate's fields are named
//     by the lab's fw::FieldsOf, units.hpp);
//   - grading::component_names({"r", "g", "b", "depth"}): what each
//     component of a vector result means, for the report's "first
//     difference" (without them: x, y, z, w);
//   - grading::perspective_depth(&fn): fn computes the result with the depth
//     interpolated perspective-correctly (divided by w like the colours)
//     where window depth is affine in the window;
//   - a number: the tolerance (default 1e-4; a check may set its own);
//   - grading::redraw_when(&fn): fn(arguments) true means a drawn argument
//     list is drawn again (a degenerate triangle the function is not defined
//     for).
// A domain may be put on a grid, grading::on_grid(grading::vec(2, 0, 8),
// 1.0 / 16): every drawn number is then a multiple of the step, as GL snaps
// window coordinates to its sub-pixel grid. A decision the reference makes
// exactly (a pixel centre on an edge or not) then cannot turn on the last
// bit of a float computation that is right.
// These alternatives are course's code like the reference, never the lab's.
#pragma once

#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <random>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <vector>

#include "framework/units.hpp"

namespace grading {

// Where one argument's random values come from.
struct ArgDomain {
    enum class Kind { Scalar, Integer, Vector, UnitVector, Bool, Choice } kind = Kind::Scalar;
    int size = 1;  // components, for vectors
    double lo = -1.0, hi = 1.0;
    bool degrees = false;            // a scalar that is an angle in degrees
    std::vector<std::string> names;  // a choice's names (an enum argument)
    double step = 0.0;               // > 0: every number drawn is a multiple of it
};
inline ArgDomain domain(ArgDomain::Kind kind, int size, double lo, double hi,
                        bool degrees = false) {
    ArgDomain d;
    d.kind = kind;
    d.size = size;
    d.lo = lo;
    d.hi = hi;
    d.degrees = degrees;
    return d;
}
inline ArgDomain scalar(double lo, double hi) { return domain(ArgDomain::Kind::Scalar, 1, lo, hi); }
inline ArgDomain degrees(double lo, double hi) {
    return domain(ArgDomain::Kind::Scalar, 1, lo, hi, true);
}
inline ArgDomain integer(int lo, int hi) {
    return domain(ArgDomain::Kind::Integer, 1, double(lo), double(hi));
}
inline ArgDomain vec(int n, double lo, double hi) {
    return domain(ArgDomain::Kind::Vector, n, lo, hi);
}
inline ArgDomain unit_vec(int n) { return domain(ArgDomain::Kind::UnitVector, n, -1.0, 1.0); }
// `d` with its numbers drawn from the multiples of `step` in [lo, hi].
inline ArgDomain on_grid(ArgDomain d, double step) {
    d.step = step;
    return d;
}
inline ArgDomain boolean() { return domain(ArgDomain::Kind::Bool, 1, 0.0, 1.0); }
// Any of the names an enum argument is bound to (fw::ChoicesOf, names.hpp).
template <class E>
ArgDomain choice() {
    ArgDomain d = domain(ArgDomain::Kind::Choice, 1, 0.0, 0.0);
    for (const fw::Choice<E>& c : fw::ChoicesOf<E>::list) d.names.emplace_back(c.name);
    return d;
}

// What a function returns, as far as printing it and recognising mistakes
// need: a vector of `rows` numbers, a matrix of `columns` x `rows` (GLM's
// mat<C, R>, stored by column), something else (a number, a bool), or a
// list (std::vector) of one of these.
struct ValueShape {
    enum class Kind { Other, Vector, Matrix } kind = Kind::Other;
    int columns = 1, rows = 1;
    bool list = false;
};

template <class T, class = void>
struct ShapeOf {
    static ValueShape get() { return {}; }
};
template <glm::length_t N, glm::qualifier Q>
struct ShapeOf<glm::vec<N, float, Q>> {
    static ValueShape get() { return {ValueShape::Kind::Vector, 1, int(N), false}; }
};
template <glm::length_t C, glm::length_t R, glm::qualifier Q>
struct ShapeOf<glm::mat<C, R, float, Q>> {
    static ValueShape get() { return {ValueShape::Kind::Matrix, int(C), int(R), false}; }
};
template <class T>
struct ShapeOf<std::vector<T>> {
    static ValueShape get() {
        ValueShape s = ShapeOf<T>::get();
        s.list = true;
        return s;
    }
};
// An aggregate with named fields (fw::FieldsOf): a list of its field's shape.
template <class T>
struct ShapeOf<T, std::enable_if_t<fw::HasFields<T>::value>> {
    static ValueShape get() {
        ValueShape s = ShapeOf<typename fw::JsonValue<T>::FieldType>::get();
        s.list = true;
        return s;
    }
};

// The names of a result's elements: an aggregate's field names, else none.
template <class T>
std::vector<std::string> element_names_of() {
    std::vector<std::string> names;
    if constexpr (fw::HasFields<T>::value)
        for (const auto& f : fw::FieldsOf<T>::list) names.emplace_back(f.name);
    return names;
}

// The usual mistakes the report recognises in a failing unit check. Their
// names (mistake_id() in mistakes.hpp) are part of the report's text.
enum class Mistake {
    Transpose,               // "transpose"
    Inverse,                 // "inverse"
    ReversedProduct,         // "reversed-product"
    RadiansForDegrees,       // "radians-for-degrees": an angle in radians where degrees were meant
    DegreesForRadians,       // "degrees-for-radians": an angle in degrees where radians were meant
    FlippedAngle,            // "flipped-angle"
    TranslationInBottomRow,  // "translation-in-bottom-row"
    NotNormalised,           // "not-normalised"
    FlippedAxis,             // "flipped-axis": a basis vector (rows of the matrix) negated
    LastColumnForDiagonal,   // "last-column-for-diagonal": diagonal entries put in the last column
    LengthSquared,           // "length-squared": divided by a length squared, not the length
    OffByOne,                // "off-by-one": a number 1 more or 1 less than expected
    PerspectiveDepth,        // "perspective-depth": window depth weighted by 1/w like a colour
};

// What the function returns when written with one mistake, computed by
// course from the same arguments as the reference.
struct Alternative {
    Mistake mistake;
    fw::UnitFunction function;
    ValueShape shape;  // of its result: the reference's
};
template <class R, class... A>
Alternative reversed_product(R (*fn)(A...)) {
    return {Mistake::ReversedProduct, fw::unit_function("reversed product", fn),
            ShapeOf<std::decay_t<R>>::get()};
}
template <class R, class... A>
Alternative not_normalised(R (*fn)(A...)) {
    return {Mistake::NotNormalised, fw::unit_function("not normalised", fn),
            ShapeOf<std::decay_t<R>>::get()};
}
template <class R, class... A>
Alternative length_squared(R (*fn)(A...)) {
    return {Mistake::LengthSquared, fw::unit_function("length squared", fn),
            ShapeOf<std::decay_t<R>>::get()};
}

template <class R, class... A>
Alternative perspective_depth(R (*fn)(A...)) {
    return {Mistake::PerspectiveDepth, fw::unit_function("perspective depth", fn),
            ShapeOf<std::decay_t<R>>::get()};
}

struct ElementNames {
    std::vector<std::string> names;
};
inline ElementNames element_names(std::vector<std::string> names) { return {std::move(names)}; }

struct ComponentNames {
    std::vector<std::string> names;
};
inline ComponentNames component_names(std::vector<std::string> names) { return {std::move(names)}; }

// What an off-by-one result means for this function, after "is the expected
// number plus or minus 1: " ("a mipmap level counted from 1, ...").
struct OffByOneWords {
    std::string words;
};
inline OffByOneWords off_by_one(std::string words) { return {std::move(words)}; }

// Arguments the function is not defined for: a draw for which `test` returns
// true is drawn again.
struct RedrawWhen {
    fw::UnitFunction test;
};
template <class... A>
RedrawWhen redraw_when(bool (*test)(A...)) {
    return {fw::unit_function("redraw when", test)};
}

struct ReferenceUnit {
    std::string lab;                         // lab id, e.g. "transforms"
    fw::UnitFunction function;               // name + JSON call, as in the lab
    std::vector<ArgDomain> domains;          // one per argument
    std::vector<bool> enum_arguments;        // which arguments are enums (need a choice())
    double tolerance = 1e-4;                 // default; a check may set its own
    ValueShape shape;                        // of the result
    std::vector<std::string> element_names;  // of a list result's elements, where known
    // Of a vector result's components, where they mean more than x, y, z, w.
    std::vector<std::string> component_names;
    std::vector<Alternative> alternatives;  // for recognising mistakes
    // Where a result 1 off names Mistake::OffByOne: the function's words for
    // it (grading::off_by_one); empty: it names nothing.
    std::string off_by_one;
    // Where set, a drawn argument list it returns true for is drawn again.
    std::optional<fw::UnitFunction> redraw;
    // Built from a lab's recorded cases.json (recorded.hpp), not compiled:
    // it knows only the argument lists recorded there.
    bool recorded = false;
    // For a recorded reference, what its cases are, as the report says it
    // ("the cases recorded in this copy ...").
    std::string recorded_cases;
    // Where set, how much the result (element k of a list; -1: the whole)
    // changes over one float step of the angles mistake recognition changed
    // to `changed` (`below` and `above`: those angles one float down and up),
    // as the largest difference of a number; nullopt where unknown. Unset,
    // mistake recognition calls `function` on `below` and `above`. A
    // recorded reference holds these numbers instead of both results.
    std::function<std::optional<double>(const nlohmann::json& changed, const nlohmann::json& below,
                                        const nlohmann::json& above, int k)>
        float_step;
};

inline void add_to_reference(ReferenceUnit& unit, double tolerance) { unit.tolerance = tolerance; }
inline void add_to_reference(ReferenceUnit& unit, Alternative alternative) {
    unit.alternatives.push_back(std::move(alternative));
}
inline void add_to_reference(ReferenceUnit& unit, ElementNames names) {
    unit.element_names = std::move(names.names);
}
inline void add_to_reference(ReferenceUnit& unit, ComponentNames names) {
    unit.component_names = std::move(names.names);
}
inline void add_to_reference(ReferenceUnit& unit, OffByOneWords words) {
    unit.off_by_one = std::move(words.words);
}
inline void add_to_reference(ReferenceUnit& unit, RedrawWhen redraw) {
    unit.redraw = std::move(redraw.test);
}

// The reference `fn` under `name`, with its domains and the optional extras
// listed at the top of this file.
template <class R, class... A, class... Extra>
ReferenceUnit make_reference(std::string name, R (*fn)(A...), std::vector<ArgDomain> domains,
                             Extra... extra) {
    ReferenceUnit unit;
    unit.function = fw::unit_function(std::move(name), fn);
    unit.domains = std::move(domains);
    unit.enum_arguments = {std::is_enum_v<std::decay_t<A>>...};
    unit.shape = ShapeOf<std::decay_t<R>>::get();
    unit.element_names = element_names_of<std::decay_t<R>>();
    (add_to_reference(unit, std::move(extra)), ...);
    return unit;
}

// Registers `unit` for the lab in folder `lab_dir` ("01_transforms"), which
// fills in unit.lab; a recorded unit does not replace a compiled one of the
// same name (false: not registered). Throws fw::Error when the domains or an alternative do
// not fit the function's arguments, or element names are given for a result
// that is not a list.
bool register_reference(std::string_view lab_dir, ReferenceUnit unit);
// Course's reference for a lab's unit function; throws fw::Error listing the
// lab's references when there is none by that name. The registry owns every
// reference for the life of the program; the names are taken as views so that
// temporary arguments cannot look like what the result points into.
const ReferenceUnit& find_reference(std::string_view lab, std::string_view function);

// One random argument list for `unit` (a JSON array, one element per
// argument), drawn again while unit.redraw holds; throws fw::Error when 1000
// draws in a row do.
nlohmann::json random_arguments(const ReferenceUnit& unit, std::mt19937& rng);

// What a value that is not finite usually means, in words: "a division by a
// zero length?" for NaN, "a division by zero?" for an infinity; empty for a
// finite value. A number that is not finite comes from the child as the string
// "NaN", "Infinity" or "-Infinity" (framework/json_glm.hpp).
std::string non_finite_hint(double value);

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
// COURSE_REFERENCE(function_name, &reference_fn, {domains...}[, extras...])
// (the extras, in any order: a tolerance, alternatives, element names, the
// off-by-one words)
#define COURSE_REFERENCE(NAME, FN, ...)                                                           \
    namespace {                                                                                   \
    static_assert(sizeof(FW_LAB_DIR) > 1,                                                         \
                  "COURSE_REFERENCE is only for files in labs/NN_name/grading/");                 \
    const bool COURSE_REFERENCE_CAT(course_reference_, __LINE__) = ::grading::register_reference( \
        FW_LAB_DIR, ::grading::make_reference(#NAME, FN, __VA_ARGS__));                           \
    }
