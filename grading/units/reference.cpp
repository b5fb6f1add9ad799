#include "grading/units/reference.hpp"

#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <optional>
#include <sstream>

#include "framework/error.hpp"
#include "framework/json_glm.hpp"
#include "framework/lab.hpp"
#include "framework/text.hpp"

namespace grading {

namespace {

using nlohmann::json;

// Keyed by lab, then function name; a map so that error messages list names
// in order, with transparent comparison so that lookups take string views.
using ByName = std::map<std::string, ReferenceUnit, std::less<>>;
std::map<std::string, ByName, std::less<>>& registry() {
    static std::map<std::string, ByName, std::less<>> all;
    return all;
}

// A float (the precision the child computes in) written with the 9 digits
// that identify it, so that the arguments printed in the report read back
// as exactly the ones evaluated.
// to_chars with a precision writes what printf's "%.9g" writes, and
// from_chars reads it back as strtod does (correctly rounded), at a quarter
// of their cost: a lab's plan draws thousands of these.
json float_value(double v) {
    char text[32];
    const auto written =
        std::to_chars(text, text + sizeof text, static_cast<double>(static_cast<float>(v)),
                      std::chars_format::general, 9);
    double out = 0.0;
    std::from_chars(text, written.ptr, out);
    return out;
}

// Uniform in [lo, hi]; with a step, uniform over its multiples there.
json random_number(const ArgDomain& d, std::mt19937& rng) {
    if (d.step > 0.0) {
        const auto first = static_cast<long>(std::ceil(d.lo / d.step));
        const auto last = static_cast<long>(std::floor(d.hi / d.step));
        return float_value(double(std::uniform_int_distribution<long>(first, last)(rng)) * d.step);
    }
    return float_value(std::uniform_real_distribution<double>(d.lo, d.hi)(rng));
}

json random_value(const ArgDomain& d, std::mt19937& rng) {
    switch (d.kind) {
        case ArgDomain::Kind::Scalar:
            return random_number(d, rng);
        case ArgDomain::Kind::Integer:
            return std::uniform_int_distribution<int>(static_cast<int>(d.lo),
                                                      static_cast<int>(d.hi))(rng);
        case ArgDomain::Kind::Bool:
            return std::uniform_int_distribution<int>(0, 1)(rng) == 1;
        case ArgDomain::Kind::Choice:
            if (d.names.empty()) break;
            return d.names[std::uniform_int_distribution<size_t>(0, d.names.size() - 1)(rng)];
        case ArgDomain::Kind::Vector: {
            json v = json::array();
            for (int i = 0; i < d.size; ++i) v.push_back(random_number(d, rng));
            return v;
        }
        case ArgDomain::Kind::UnitVector: {
            // Normal samples normalised: uniform on the sphere. A near-zero
            // sample is drawn again rather than divided by.
            std::normal_distribution<double> normal;
            for (;;) {
                std::vector<double> v(static_cast<size_t>(d.size));
                double len = 0.0;
                for (double& x : v) {
                    x = normal(rng);
                    len += x * x;
                }
                len = std::sqrt(len);
                if (len < 1e-6) continue;
                json out = json::array();
                for (double x : v) out.push_back(float_value(x / len));
                return out;
            }
        }
    }
    throw fw::Error("random_arguments: unknown argument domain");
}

std::string number_text(const json& j) {
    std::ostringstream s;
    s.precision(9);
    const std::optional<double> v = fw::json_number(j);
    if (v && !std::isfinite(*v))
        s << fw::non_finite_name(*v);
    else if (v)
        s << *v;
    else
        s << j.dump();
    return s.str();
}

bool match(const json& e, const json& o, double tolerance, const std::string& where,
           std::string* why) {
    auto fail = [&](const std::string& what) {
        if (why) *why = (where.empty() ? "" : where + ": ") + what;
        return false;
    };
    if (e.is_array()) {
        if (!o.is_array())
            return fail("expected an array of " + std::to_string(e.size()) + ", got " + o.dump());
        if (o.size() != e.size())
            return fail("expected " + std::to_string(e.size()) + " elements, got " +
                        std::to_string(o.size()));
        for (size_t i = 0; i < e.size(); ++i)
            if (!match(e[i], o[i], tolerance, where + "[" + std::to_string(i) + "]", why))
                return false;
        return true;
    }
    if (e.is_boolean()) {
        if (o != e) return fail("expected " + e.dump() + ", got " + o.dump());
        return true;
    }
    if (e.is_number()) {
        const std::optional<double> y = fw::json_number(o);
        if (!y) return fail("expected a number, got " + o.dump());
        const double x = e.get<double>();
        if (!std::isfinite(*y) || std::fabs(x - *y) > tolerance * std::max(1.0, std::fabs(x))) {
            const std::string hint = non_finite_hint(*y);
            return fail("expected " + number_text(e) + ", got " + number_text(o) +
                        (hint.empty() ? "" : " (" + hint + ")"));
        }
        return true;
    }
    if (o != e) return fail("expected " + e.dump() + ", got " + o.dump());
    return true;
}

}  // namespace

std::string non_finite_hint(double value) {
    if (std::isnan(value)) return "a division by a zero length?";
    if (std::isinf(value)) return "a division by zero?";
    return {};
}

bool register_reference(std::string_view lab_dir, ReferenceUnit unit) {
    int number = 0;
    fw::parse_lab_dir(lab_dir, number, unit.lab);
    if (static_cast<int>(unit.domains.size()) != unit.function.arity)
        throw fw::Error("reference '" + unit.lab + "." + unit.function.name + "' takes " +
                        std::to_string(unit.function.arity) + " arguments but has " +
                        std::to_string(unit.domains.size()) + " domains");
    for (size_t i = 0; i < unit.domains.size(); ++i)
        if (unit.enum_arguments[i] != (unit.domains[i].kind == ArgDomain::Kind::Choice))
            throw fw::Error("reference '" + unit.lab + "." + unit.function.name + "': argument " +
                            std::to_string(i + 1) +
                            (unit.enum_arguments[i] ? " is an enum and needs grading::choice<E>()"
                                                    : " is not an enum, so grading::choice "
                                                      "does not fit it"));
    for (const Alternative& a : unit.alternatives) {
        const ValueShape &s = a.shape, &r = unit.shape;
        if (a.function.arity != unit.function.arity || s.kind != r.kind || s.list != r.list ||
            s.columns != r.columns || s.rows != r.rows)
            throw fw::Error("reference '" + unit.lab + "." + unit.function.name + "' has an " +
                            a.function.name +
                            " alternative whose arguments or result differ from the reference's");
    }
    for (const ArgDomain& d : unit.domains)
        if (d.step > 0.0 && std::ceil(d.lo / d.step) > std::floor(d.hi / d.step))
            throw fw::Error("reference '" + unit.lab + "." + unit.function.name +
                            "' has a domain on a grid with no point between its bounds");
    if (unit.redraw && unit.redraw->arity != unit.function.arity)
        throw fw::Error("reference '" + unit.lab + "." + unit.function.name +
                        "': its redraw_when() test takes other arguments than the function");
    if (!unit.element_names.empty() && !unit.shape.list)
        throw fw::Error("reference '" + unit.lab + "." + unit.function.name +
                        "' names the elements of a result that is not a list");
    if (!unit.component_names.empty() && (unit.shape.kind != ValueShape::Kind::Vector ||
                                          int(unit.component_names.size()) != unit.shape.rows))
        throw fw::Error("reference '" + unit.lab + "." + unit.function.name +
                        "' names components that its result, not a vector of as many, lacks");
    ByName& lab = registry()[unit.lab];
    const auto existing = lab.find(unit.function.name);
    if (existing != lab.end() && unit.recorded && !existing->second.recorded) return false;
    std::string name = unit.function.name;
    lab[name] = std::move(unit);
    return true;
}

const ReferenceUnit& find_reference(std::string_view lab, std::string_view function) {
    auto& all = registry();
    auto l = all.find(lab);
    if (l != all.end()) {
        auto f = l->second.find(function);
        if (f != l->second.end()) return f->second;
    }
    const std::string names =
        l == all.end() ? std::string()
                       : fw::join(l->second, ", ", [](const auto& entry) { return entry.first; });
    throw fw::Error("course has no reference for unit function '" + std::string(function) +
                    "' of lab '" + std::string(lab) + "'; " +
                    (names.empty() ? "it has none for that lab" : "it has: " + names) +
                    " (references live in labs/NN_name/grading/*.cpp)");
}

json random_arguments(const ReferenceUnit& unit, std::mt19937& rng) {
    for (int tries = 0; tries < 1000; ++tries) {
        json args = json::array();
        for (const ArgDomain& d : unit.domains) args.push_back(random_value(d, rng));
        if (!unit.redraw || !unit.redraw->call(args).get<bool>()) return args;
    }
    throw fw::Error("reference '" + unit.lab + "." + unit.function.name +
                    "': 1000 argument lists in a row were drawn again (its redraw_when() test "
                    "holds for nearly all of its domains)");
}

bool results_match(const json& expected, const json& observed, double tolerance, std::string* why) {
    return match(expected, observed, tolerance, "", why);
}

}  // namespace grading
