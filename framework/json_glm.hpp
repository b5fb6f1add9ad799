// JSON for the GLM types that unit checks pass around: a vecN is an array of
// N numbers, a matN an array of N columns (GLM storage: m[column][row]).
// The `lab` child and `course` both read and write values this way.
#pragma once

#include <cmath>
#include <glm/glm.hpp>
#include <limits>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "framework/error.hpp"

namespace fw {

// to(T) -> json, from(json) -> T; throws Error when malformed. The second
// parameter lets a specialisation pick a family of types (units.hpp: enums
// with names, aggregates with named fields).
template <class T, class = void>
struct JsonValue;

// Throws Error("WHAT, got JSON"), `got` as compact JSON text. Out of line:
// writing JSON text (nlohmann's dump) is a large template, which every file
// that converts a value would otherwise compile again.
[[noreturn]] void throw_mismatch(const std::string& what, const nlohmann::json& got);

// JSON has no NaN or infinity (nlohmann writes them as null), so a number
// that is not finite travels as one of the strings "NaN", "Infinity",
// "-Infinity": a report can then say which it was.
inline const char* non_finite_name(double v) {
    return std::isnan(v) ? "NaN" : v > 0 ? "Infinity" : "-Infinity";
}

// A number as it travels: a JSON number, or one of the strings above;
// nullopt for anything else.
std::optional<double> json_number(const nlohmann::json& j);

// Appends `value` as compact JSON text: what value.dump() writes, read back
// as the same value of the same types (a float keeps a '.' or an
// exponent; a number that is not finite is null, as dump() has it), in a
// fraction of dump()'s time: std::to_chars writes the numbers. For a lab's
// thousands of unit results.
void append_json(std::string& out, const nlohmann::json& value);

// The scalars, out of line (json_glm.cpp) like throw_mismatch: a lab's file
// then compiles none of nlohmann's conversions and exceptions for them.
template <>
struct JsonValue<float> {
    static nlohmann::json to(float v);
    static float from(const nlohmann::json& j);
};

template <>
struct JsonValue<int> {
    static nlohmann::json to(int v);
    static int from(const nlohmann::json& j);
};

template <>
struct JsonValue<bool> {
    static nlohmann::json to(bool v);
    static bool from(const nlohmann::json& j);
};

template <glm::length_t N>
struct JsonValue<glm::vec<N, float>> {
    static nlohmann::json to(const glm::vec<N, float>& v) {
        nlohmann::json out = nlohmann::json::array();
        for (glm::length_t i = 0; i < N; ++i) out.push_back(JsonValue<float>::to(v[i]));
        return out;
    }
    static glm::vec<N, float> from(const nlohmann::json& j) {
        if (!j.is_array() || j.size() != static_cast<size_t>(N))
            throw_mismatch("expected an array of " + std::to_string(N) + " numbers", j);
        glm::vec<N, float> v;
        for (glm::length_t i = 0; i < N; ++i)
            v[i] = JsonValue<float>::from(j[static_cast<size_t>(i)]);
        return v;
    }
};

template <glm::length_t C, glm::length_t R>
struct JsonValue<glm::mat<C, R, float>> {
    static nlohmann::json to(const glm::mat<C, R, float>& m) {
        nlohmann::json out = nlohmann::json::array();
        for (glm::length_t c = 0; c < C; ++c)
            out.push_back(JsonValue<glm::vec<R, float>>::to(m[c]));
        return out;
    }
    static glm::mat<C, R, float> from(const nlohmann::json& j) {
        if (!j.is_array() || j.size() != static_cast<size_t>(C))
            throw_mismatch("expected " + std::to_string(C) + " columns", j);
        glm::mat<C, R, float> m;
        for (glm::length_t c = 0; c < C; ++c)
            m[c] = JsonValue<glm::vec<R, float>>::from(j[static_cast<size_t>(c)]);
        return m;
    }
};

template <class T>
nlohmann::json to_json_value(const T& v) {
    return JsonValue<T>::to(v);
}
template <class T>
T from_json_value(const nlohmann::json& j) {
    return JsonValue<T>::from(j);
}

}  // namespace fw
