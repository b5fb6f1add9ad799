#include "framework/json_glm.hpp"

namespace fw {

void throw_mismatch(const std::string& what, const nlohmann::json& got) {
    throw Error(what + ", got " + got.dump());
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
