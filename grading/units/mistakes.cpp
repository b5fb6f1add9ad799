// Recognising the usual mistakes of a failing unit check (mistakes.hpp):
// the alternatives course computes (their sentences: mistake_words.cpp).
#include "grading/units/mistakes.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <map>
#include <set>

namespace grading {

namespace {

using nlohmann::json;

constexpr double kPi = 3.14159265358979323846;

// `observed` within tolerance of `value` (relative where |value| > 1, as
// results_match() compares), allowing `slack` more.
bool close(const json& observed, const json& value, double tolerance, double slack) {
    if (value.is_array()) {
        if (!observed.is_array() || observed.size() != value.size()) return false;
        for (size_t i = 0; i < value.size(); ++i)
            if (!close(observed[i], value[i], tolerance, slack)) return false;
        return true;
    }
    if (value.is_number()) {
        if (!observed.is_number()) return false;
        const double o = observed.get<double>(), v = value.get<double>();
        return std::isfinite(o) &&
               std::fabs(o - v) <= tolerance * std::max(1.0, std::fabs(v)) + slack;
    }
    return observed == value;
}

bool same_structure(const json& a, const json& b) {
    if (a.is_array()) {
        if (!b.is_array() || a.size() != b.size()) return false;
        for (size_t i = 0; i < a.size(); ++i)
            if (!same_structure(a[i], b[i])) return false;
        return true;
    }
    return a.is_number() ? b.is_number() : a.type() == b.type();
}

// Element `k` of a list result (-1: the whole value); nullopt when missing.
// (std::in_place: json converts itself to any type, std::optional<json> too,
// so a plain `return value;` is ambiguous to GCC 16.)
std::optional<json> element(const json& value, int k) {
    if (k < 0) return std::optional<json>(std::in_place, value);
    if (!value.is_array() || static_cast<size_t>(k) >= value.size()) return std::nullopt;
    return std::optional<json>(std::in_place, value[static_cast<size_t>(k)]);
}

// The function on `args`, element `k`; nullopt when it throws (an argument
// the reference rejects).
std::optional<json> call(const fw::UnitFunction& f, const json& args, int k) {
    try {
        return element(f.call(args), k);
    } catch (const std::exception&) {
        return std::nullopt;
    }
}

struct Checker {
    const ReferenceUnit& ref;
    const json& args;
    const json& expected;  // the element explained
    const json& observed;
    int k;
    double tolerance;
    std::vector<Explanation> found;

    // Whether `value` explains the case: it matches the observed value and
    // differs from the expected one.
    bool matches(const std::optional<json>& value, double slack = 0.0) const {
        return value && !results_match(expected, *value, tolerance, nullptr) &&
               close(observed, *value, tolerance, slack);
    }
    void add(Mistake m, int argument, int rows = 0) {
        for (const Explanation& e : found)
            if (e.mistake == m) return;
        found.push_back({m, k, argument, rows});
    }
    void consider(Mistake m, const std::optional<json>& value, int argument = -1) {
        if (matches(value)) add(m, argument);
    }

    // The reference with the angles at `which` (-1: every angle argument)
    // times `factor`. Angles become floats on the way in, so a converted
    // angle is only as close as one float step: where the reference's
    // result changes more than the tolerance over that step, the match
    // allows for that change.
    void angles(Mistake m, int which, double factor) {
        json changed = args, below = args, above = args;
        for (size_t i = 0; i < ref.domains.size(); ++i) {
            if (!ref.domains[i].degrees || (which >= 0 && static_cast<int>(i) != which)) continue;
            if (i >= args.size() || !args[i].is_number()) return;
            const double wanted = args[i].get<double>() * factor;
            if (!(std::fabs(wanted) <= std::numeric_limits<float>::max())) return;
            const float x = static_cast<float>(wanted);
            changed[i] = double(x);
            below[i] = double(std::nextafter(x, -std::numeric_limits<float>::infinity()));
            above[i] = double(std::nextafter(x, std::numeric_limits<float>::infinity()));
        }
        const std::optional<json> value = call(ref.function, changed, k);
        if (!value || results_match(expected, *value, tolerance, nullptr)) return;
        if (close(observed, *value, tolerance, 0.0)) return add(m, which);
        if (factor == -1.0) return;  // negation is exact
        const std::optional<double> step = float_step(changed, below, above);
        if (step && matches(value, *step)) add(m, which);
    }

    // How much element k of the result changes over the float step from
    // `below` to `above` (ReferenceUnit::float_step).
    std::optional<double> float_step(const json& changed, const json& below, const json& above) {
        if (ref.float_step) return ref.float_step(changed, below, above, k);
        const std::optional<json> lo = call(ref.function, below, k);
        const std::optional<json> hi = call(ref.function, above, k);
        if (!lo || !hi) return std::nullopt;
        return largest_difference(*lo, *hi);
    }

    void run() {
        const ValueShape& s = ref.shape;
        if (s.kind == ValueShape::Kind::Matrix && s.columns == s.rows) {
            consider(Mistake::Transpose, transposed(expected));
            consider(Mistake::Inverse, inverted(expected));
            consider(Mistake::TranslationInBottomRow, translation_in_bottom_row(expected));
            consider(Mistake::LastColumnForDiagonal, diagonal_in_last_column(expected));
            flipped_rows(s.rows);
        }
        if (s.kind == ValueShape::Kind::Vector) unnormalised_vector();
        // Only where the reference says what a result 1 off means: elsewhere
        // (an index in a sorted order) a difference of 1 is no evidence.
        if (!ref.off_by_one.empty() && expected.is_number() && observed.is_number()) off_by_one();
        std::vector<int> degrees;
        for (size_t i = 0; i < ref.domains.size(); ++i)
            if (ref.domains[i].degrees) degrees.push_back(static_cast<int>(i));
        std::vector<int> which = degrees;
        if (degrees.size() > 1) which.push_back(-1);
        for (int i : which) {
            angles(Mistake::FlippedAngle, i, -1.0);
            angles(Mistake::DegreesForRadians, i, 180.0 / kPi);
            angles(Mistake::RadiansForDegrees, i, kPi / 180.0);
        }
        for (const Alternative& a : ref.alternatives)
            consider(a.mistake, call(a.function, args, k));
    }

    // Some rows above the bottom one negated, with or without their last
    // entry: a basis vector the matrix is built from points the wrong way.
    void flipped_rows(int n) {
        for (int rows = 1; rows < (1 << (n - 1)); ++rows)
            for (bool with_last : {true, false})
                if (matches(rows_negated(expected, rows, with_last)))
                    return add(Mistake::FlippedAxis, -1, rows);
    }

    // A number expected, that number plus or minus 1 observed: for the
    // functions whose reference names it (a level started at 1 where it
    // starts at 0, or the other way).
    void off_by_one() {
        for (const double step : {1.0, -1.0})
            if (matches(json(expected.get<double>() + step))) return add(Mistake::OffByOne, -1);
    }

    // A unit vector expected, a longer or shorter one observed in its direction.
    void unnormalised_vector() {
        if (!expected.is_array() || !observed.is_array()) return;
        for (const json& v : expected)
            if (!v.is_number()) return;
        double e2 = 0.0, o2 = 0.0;
        for (size_t i = 0; i < expected.size(); ++i) {
            e2 += expected[i].get<double>() * expected[i].get<double>();
            o2 += observed[i].get<double>() * observed[i].get<double>();
        }
        const double length = std::sqrt(o2);
        if (std::fabs(std::sqrt(e2) - 1.0) > tolerance || !std::isfinite(length) ||
            std::fabs(length - 1.0) <= tolerance || length == 0.0)
            return;
        json direction = json::array();
        for (const json& v : observed) direction.push_back(v.get<double>() / length);
        if (close(direction, expected, tolerance, 0.0)) add(Mistake::NotNormalised, -1);
    }
};

}  // namespace

double largest_difference(const json& a, const json& b) {
    if (a.is_array() && b.is_array() && a.size() == b.size()) {
        double worst = 0.0;
        for (size_t i = 0; i < a.size(); ++i)
            worst = std::max(worst, largest_difference(a[i], b[i]));
        return worst;
    }
    if (a.is_number() && b.is_number()) {
        const double d = std::fabs(a.get<double>() - b.get<double>());
        return std::isfinite(d) ? d : std::numeric_limits<double>::infinity();
    }
    return a == b ? 0.0 : std::numeric_limits<double>::infinity();
}

std::string_view mistake_id(Mistake mistake) {
    switch (mistake) {
        case Mistake::Transpose:
            return "transpose";
        case Mistake::Inverse:
            return "inverse";
        case Mistake::ReversedProduct:
            return "reversed-product";
        case Mistake::RadiansForDegrees:
            return "radians-for-degrees";
        case Mistake::DegreesForRadians:
            return "degrees-for-radians";
        case Mistake::FlippedAngle:
            return "flipped-angle";
        case Mistake::TranslationInBottomRow:
            return "translation-in-bottom-row";
        case Mistake::FlippedAxis:
            return "flipped-axis";
        case Mistake::LastColumnForDiagonal:
            return "last-column-for-diagonal";
        case Mistake::LengthSquared:
            return "length-squared";
        case Mistake::OffByOne:
            return "off-by-one";
        case Mistake::NotNormalised:
            return "not-normalised";
        case Mistake::PerspectiveDepth:
            return "perspective-depth";
    }
    return "unknown";
}

std::vector<Explanation> explain_failure(const ReferenceUnit& ref, const UnitFailure& failure,
                                         double tolerance) {
    const json &expected = failure.expected, &observed = failure.observed;
    if (results_match(expected, observed, tolerance, nullptr) ||
        !same_structure(expected, observed))
        return {};
    int k = -1;
    if (ref.shape.list) {
        for (size_t i = 0; i < expected.size() && k < 0; ++i)
            if (!results_match(expected[i], observed[i], tolerance, nullptr))
                k = static_cast<int>(i);
        if (k < 0) return {};
    }
    const json& e = k < 0 ? expected : expected[static_cast<size_t>(k)];
    const json& o = k < 0 ? observed : observed[static_cast<size_t>(k)];
    Checker checker{ref, failure.args, e, o, k, tolerance, {}};
    checker.run();
    return checker.found;
}

Recognised recognise_mistakes(const ReferenceUnit& ref, const std::vector<UnitFailure>& failures,
                              double tolerance) {
    const size_t n = std::min(failures.size(), kMistakeCases);
    struct Tally {
        std::set<size_t> cases;
        std::map<int, int> elements, arguments, rows;
    };
    std::map<Mistake, Tally> tallies;
    for (size_t i = 0; i < n; ++i) {
        for (const Explanation& e : explain_failure(ref, failures[i], tolerance)) {
            Tally& t = tallies[e.mistake];
            t.cases.insert(i);
            ++t.elements[e.element];
            ++t.arguments[e.argument];
            ++t.rows[e.rows];
        }
    }
    auto most = [](const std::map<int, int>& votes) {
        return std::max_element(votes.begin(), votes.end(),
                                [](const auto& a, const auto& b) { return a.second < b.second; })
            ->first;
    };
    Recognised out;
    const std::set<size_t>* first = nullptr;
    bool same = true;
    for (const auto& [mistake, tally] : tallies) {
        if (2 * tally.cases.size() <= n) continue;
        out.mistakes.push_back(
            {mistake, most(tally.elements), most(tally.arguments), most(tally.rows)});
        if (first && *first != tally.cases) same = false;
        if (!first) first = &tally.cases;
    }
    out.coincide = out.mistakes.size() > 1 && same;
    return out;
}

}  // namespace grading
