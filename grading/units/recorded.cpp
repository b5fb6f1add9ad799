// A reference recorded as data (recorded.hpp): recording the calls judging
// makes, writing them as one function's entry of cases.json, and a
// reference that answers from that entry.
#include "grading/units/recorded.hpp"

#include <charconv>
#include <cmath>
#include <exception>
#include <functional>
#include <limits>
#include <optional>

#include "framework/error.hpp"
#include "grading/units/mistakes.hpp"

namespace grading {

namespace {

using nlohmann::json;

constexpr const char* kDomainKinds[] = {"scalar",      "integer", "vector",
                                        "unit-vector", "bool",    "choice"};
constexpr const char* kShapeKinds[] = {"other", "vector", "matrix"};
constexpr Mistake kMistakes[] = {Mistake::Transpose,
                                 Mistake::Inverse,
                                 Mistake::ReversedProduct,
                                 Mistake::RadiansForDegrees,
                                 Mistake::DegreesForRadians,
                                 Mistake::FlippedAngle,
                                 Mistake::TranslationInBottomRow,
                                 Mistake::NotNormalised,
                                 Mistake::FlippedAxis,
                                 Mistake::LastColumnForDiagonal,
                                 Mistake::LengthSquared,
                                 Mistake::PerspectiveDepth};

// A result that differs from `expected` everywhere (numbers become NaN,
// which matches nothing), or only in element `k` of a list.
json wrong(const json& expected, int k) {
    if (k >= 0) {
        json out = expected;
        out[static_cast<size_t>(k)] = wrong(expected[static_cast<size_t>(k)], -1);
        return out;
    }
    if (expected.is_array()) {
        json out = json::array();
        for (const json& e : expected) out.push_back(wrong(e, -1));
        return out;
    }
    if (expected.is_number()) return std::numeric_limits<double>::quiet_NaN();
    if (expected.is_boolean()) return !expected.get<bool>();
    return expected.dump() + "?";
}

// Every float of `value` as the float it was computed in, exactly (what a
// compiled reference returns); the file holds them to 9 digits.
json as_floats(const json& value) {
    if (value.is_array()) {
        json out = json::array();
        for (const json& e : value) out.push_back(as_floats(e));
        return out;
    }
    if (value.is_number_float()) return double(static_cast<float>(value.get<double>()));
    return value;
}

// A function that records each of its calls in `table`.
fw::UnitFunction recording(
    const fw::UnitFunction& f,
    const std::shared_ptr<std::map<std::string, std::pair<json, json>>>& table) {
    fw::UnitFunction r = f;
    r.call = [call = f.call, table](const json& args) {
        json result = call(args);
        json key = float_digits(args);
        std::string text = key.dump();
        (*table)[std::move(text)] = {std::move(key), float_digits(result)};
        return result;
    };
    return r;
}

// How much each element of a result (the whole, where it is no list)
// changes between `below` and `above`.
json element_steps(const fw::UnitFunction& f, const json& below, const json& above, bool list) {
    const json lo = f.call(below), hi = f.call(above);
    json out = json::array();
    if (!list) out.push_back(largest_difference(lo, hi));
    for (size_t i = 0; list && i < lo.size() && i < hi.size(); ++i)
        out.push_back(largest_difference(lo[i], hi[i]));
    return out;
}

std::optional<double> step_of(const json& steps, int k) {
    const size_t i = k < 0 ? 0 : static_cast<size_t>(k);
    if (!steps.is_array() || i >= steps.size() || !steps[i].is_number()) return std::nullopt;
    return steps[i].get<double>();
}

json table_json(const std::map<std::string, std::pair<json, json>>& table) {
    json out = json::array();
    for (const auto& [key, call] : table) out.push_back({call.first, call.second});
    return out;
}

json domain_json(const ArgDomain& d) {
    json out = {{"kind", kDomainKinds[static_cast<int>(d.kind)]},
                {"lo", d.lo},
                {"hi", d.hi},
                {"degrees", d.degrees}};
    if (d.kind == ArgDomain::Kind::Vector || d.kind == ArgDomain::Kind::UnitVector)
        out["size"] = d.size;
    if (d.kind == ArgDomain::Kind::Choice) out["names"] = d.names;
    return out;
}

}  // namespace

json float_digits(const json& value) {
    if (value.is_array()) {
        json out = json::array();
        for (const json& e : value) out.push_back(float_digits(e));
        return out;
    }
    if (!value.is_number_float()) return value;
    const double v = value.get<double>();
    if (!std::isfinite(v)) return value;
    char text[32];
    const auto written = std::to_chars(text, text + sizeof text, double(static_cast<float>(v)),
                                       std::chars_format::general, 9);
    double out = 0.0;
    std::from_chars(text, written.ptr, out);
    return out;
}

ReferenceRecorder::ReferenceRecorder(const ReferenceUnit& ref)
    : ref_(ref), recording_(ref), reference_(std::make_shared<Table>()) {
    recording_.function = recording(ref.function, reference_);
    float_steps_ = std::make_shared<Table>();
    recording_.float_step = [f = ref.function, list = ref.shape.list, table = float_steps_](
                                const json&, const json& below, const json& above,
                                int k) -> std::optional<double> {
        json key = float_digits(json::array({below, above}));
        json steps;
        try {
            steps = float_digits(element_steps(f, below, above, list));
        } catch (const std::exception&) {
            return std::nullopt;
        }
        std::string text = key.dump();
        (*table)[std::move(text)] = {std::move(key), steps};
        return step_of(steps, k);
    };
    for (Alternative& a : recording_.alternatives) {
        alternatives_.push_back(std::make_shared<Table>());
        a.function = recording(a.function, alternatives_.back());
    }
}

void ReferenceRecorder::record(const json& args, double tolerance) {
    const json expected = recording_.function.call(args);
    std::vector<int> elements = {-1};
    if (ref_.shape.list && expected.is_array()) {
        elements.clear();
        for (size_t k = 0; k < expected.size(); ++k) elements.push_back(static_cast<int>(k));
    }
    for (int k : elements)
        explain_failure(recording_, {args, expected, wrong(expected, k)}, tolerance);
}

json ReferenceRecorder::entry() const {
    const ValueShape& s = ref_.shape;
    json out = {{"shape",
                 {{"kind", kShapeKinds[static_cast<int>(s.kind)]},
                  {"columns", s.columns},
                  {"rows", s.rows},
                  {"list", s.list}}},
                {"element_names", ref_.element_names},
                {"component_names", ref_.component_names},
                {"tolerance", ref_.tolerance},
                {"domains", json::array()},
                {"reference", table_json(*reference_)},
                {"float_steps", table_json(*float_steps_)},
                {"alternatives", json::array()}};
    for (const ArgDomain& d : ref_.domains) out["domains"].push_back(domain_json(d));
    if (!ref_.off_by_one.empty()) out["off_by_one"] = ref_.off_by_one;
    for (size_t i = 0; i < ref_.alternatives.size(); ++i) {
        const Alternative& a = ref_.alternatives[i];
        out["alternatives"].push_back({{"mistake", std::string(mistake_id(a.mistake))},
                                       {"name", a.function.name},
                                       {"table", table_json(*alternatives_[i])}});
    }
    return out;
}

namespace {

// The entry's field `key`, or fw::Error naming it.
const json& field(const std::string& name, const json& entry, const char* key, json::value_t type) {
    const bool ok = entry.is_object() && entry.contains(key) &&
                    (entry[key].type() == type ||
                     (type == json::value_t::number_float && entry[key].is_number()));
    if (!ok)
        throw fw::Error("recorded reference '" + name + "': \"" + key +
                        "\" is missing or not of its type");
    return entry[key];
}

// A function of `arity` arguments that answers from `table` ([[args, result], ...]).
fw::UnitFunction lookup(const std::string& name, int arity, const json& table) {
    auto results = std::make_shared<std::map<std::string, json>>();
    for (const json& call : table) {
        if (!call.is_array() || call.size() != 2)
            throw fw::Error("recorded reference '" + name +
                            "': a table entry is not [args, result]");
        (*results)[float_digits(call[0]).dump()] = as_floats(call[1]);
    }
    fw::UnitFunction f;
    f.name = name;
    f.arity = arity;
    f.call = [name, results](const json& args) {
        const auto found = results->find(float_digits(args).dump());
        if (found == results->end())
            throw fw::Error("'" + name + "' was not recorded for the arguments " + args.dump() +
                            " (the lab's grading/cases.json holds only the cases recorded by "
                            "course release)");
        return found->second;
    };
    return f;
}

// ReferenceUnit::float_step from `table` ([[[below, above], steps], ...]).
std::function<std::optional<double>(const json&, const json&, const json&, int)> float_steps(
    const std::string& name, const json& table) {
    auto steps = std::make_shared<std::map<std::string, json>>();
    for (const json& entry : table) {
        if (!entry.is_array() || entry.size() != 2)
            throw fw::Error("recorded reference '" + name +
                            "': a float step is not [[below, above], steps]");
        (*steps)[float_digits(entry[0]).dump()] = entry[1];
    }
    return [steps](const json&, const json& below, const json& above, int k) {
        const auto found = steps->find(float_digits(json::array({below, above})).dump());
        return found == steps->end() ? std::nullopt : step_of(found->second, k);
    };
}

template <size_t N>
int index_of(const std::string& name, const char* const (&names)[N], const std::string& value) {
    for (size_t i = 0; i < N; ++i)
        if (value == names[i]) return static_cast<int>(i);
    throw fw::Error("recorded reference '" + name + "': unknown kind \"" + value + "\"");
}

ArgDomain domain_from(const std::string& name, const json& d) {
    using T = json::value_t;
    ArgDomain out;
    out.kind = static_cast<ArgDomain::Kind>(
        index_of(name, kDomainKinds, field(name, d, "kind", T::string).get<std::string>()));
    out.lo = field(name, d, "lo", T::number_float).get<double>();
    out.hi = field(name, d, "hi", T::number_float).get<double>();
    out.degrees = field(name, d, "degrees", T::boolean).get<bool>();
    if (d.contains("size")) out.size = field(name, d, "size", T::number_float).get<int>();
    if (d.contains("names"))
        out.names = field(name, d, "names", T::array).get<std::vector<std::string>>();
    return out;
}

Mistake mistake_from(const std::string& name, const std::string& id) {
    for (Mistake m : kMistakes)
        if (mistake_id(m) == id) return m;
    throw fw::Error("recorded reference '" + name + "': unknown mistake \"" + id + "\"");
}

}  // namespace

ReferenceUnit recorded_reference(const std::string& name, const json& entry) {
    using T = json::value_t;
    ReferenceUnit unit;
    unit.recorded = true;
    for (const json& d : field(name, entry, "domains", T::array)) {
        unit.domains.push_back(domain_from(name, d));
        unit.enum_arguments.push_back(unit.domains.back().kind == ArgDomain::Kind::Choice);
    }
    const int arity = static_cast<int>(unit.domains.size());
    unit.function = lookup(name, arity, field(name, entry, "reference", T::array));
    unit.float_step = float_steps(name, field(name, entry, "float_steps", T::array));
    unit.tolerance = field(name, entry, "tolerance", T::number_float).get<double>();
    const json& shape = field(name, entry, "shape", T::object);
    unit.shape.kind = static_cast<ValueShape::Kind>(
        index_of(name, kShapeKinds, field(name, shape, "kind", T::string).get<std::string>()));
    unit.shape.columns = field(name, shape, "columns", T::number_float).get<int>();
    unit.shape.rows = field(name, shape, "rows", T::number_float).get<int>();
    unit.shape.list = field(name, shape, "list", T::boolean).get<bool>();
    unit.element_names =
        field(name, entry, "element_names", T::array).get<std::vector<std::string>>();
    if (entry.contains("component_names"))
        unit.component_names =
            field(name, entry, "component_names", T::array).get<std::vector<std::string>>();
    if (entry.contains("off_by_one"))
        unit.off_by_one = field(name, entry, "off_by_one", T::string).get<std::string>();
    for (const json& a : field(name, entry, "alternatives", T::array)) {
        const std::string id = field(name, a, "mistake", T::string);
        const std::string alt = field(name, a, "name", T::string);
        unit.alternatives.push_back({mistake_from(name, id),
                                     lookup(alt, arity, field(name, a, "table", T::array)),
                                     unit.shape});
    }
    return unit;
}

}  // namespace grading
