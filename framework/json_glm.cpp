#include "framework/json_glm.hpp"

#include <algorithm>
#include <charconv>
#include <cstdint>

namespace fw {

void throw_mismatch(const std::string& what, const nlohmann::json& got) {
    throw Error(what + ", got " + got.dump());
}

namespace {

template <class Number>
void append_number(std::string& out, Number v) {
    char text[32];
    const auto written = std::to_chars(text, text + sizeof text, v);
    out.append(text, written.ptr);
}

}  // namespace

void append_json(std::string& out, const nlohmann::json& value) {
    using Type = nlohmann::json::value_t;
    switch (value.type()) {
        case Type::number_float: {
            const double v = value.get<double>();
            if (!std::isfinite(v)) {
                out += "null";
                return;
            }
            const size_t start = out.size();
            append_number(out, v);
            // "1", as to_chars writes 1.0, would read back as an integer.
            if (std::none_of(out.begin() + static_cast<std::ptrdiff_t>(start), out.end(),
                             [](char c) { return c == '.' || c == 'e'; }))
                out += ".0";
            return;
        }
        case Type::number_integer:
            append_number(out, value.get<std::int64_t>());
            return;
        case Type::number_unsigned:
            append_number(out, value.get<std::uint64_t>());
            return;
        case Type::array: {
            out += '[';
            for (auto it = value.begin(); it != value.end(); ++it) {
                if (it != value.begin()) out += ',';
                append_json(out, *it);
            }
            out += ']';
            return;
        }
        case Type::object: {
            out += '{';
            for (auto it = value.begin(); it != value.end(); ++it) {
                if (it != value.begin()) out += ',';
                out += nlohmann::json(it.key()).dump();
                out += ':';
                append_json(out, it.value());
            }
            out += '}';
            return;
        }
        default:  // null, true, false, strings (escaped as dump() escapes them)
            out += value.dump();
            return;
    }
}

std::optional<double> json_number(const nlohmann::json& j) {
    if (j.is_number()) return j.get<double>();
    if (!j.is_string()) return std::nullopt;
    const std::string& s = j.get_ref<const std::string&>();
    if (s == "NaN") return std::numeric_limits<double>::quiet_NaN();
    if (s == "Infinity") return std::numeric_limits<double>::infinity();
    if (s == "-Infinity") return -std::numeric_limits<double>::infinity();
    return std::nullopt;
}

nlohmann::json JsonValue<float>::to(float v) {
    if (!std::isfinite(v)) return non_finite_name(v);
    return v;
}

float JsonValue<float>::from(const nlohmann::json& j) {
    const std::optional<double> v = json_number(j);
    if (!v) throw_mismatch("expected a number", j);
    return static_cast<float>(*v);
}

nlohmann::json JsonValue<int>::to(int v) { return v; }

int JsonValue<int>::from(const nlohmann::json& j) {
    if (!j.is_number_integer()) throw_mismatch("expected an integer", j);
    return j.get<int>();
}

nlohmann::json JsonValue<bool>::to(bool v) { return v; }

bool JsonValue<bool>::from(const nlohmann::json& j) {
    if (!j.is_boolean()) throw_mismatch("expected true or false", j);
    return j.get<bool>();
}

}  // namespace fw
