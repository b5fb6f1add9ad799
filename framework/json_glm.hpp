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

// JSON has no NaN or infinity (nlohmann writes them as null), so a number
// that is not finite travels as one of the strings "NaN", "Infinity",
// "-Infinity": a report can then say which it was.
inline const char* non_finite_name(double v) {
    return std::isnan(v) ? "NaN" : v > 0 ? "Infinity" : "-Infinity";
}

// A number as it travels: a JSON number, or one of the strings above;
// nullopt for anything else.
inline std::optional<double> json_number(const nlohmann::json& j) {
    if (j.is_number()) return j.get<double>();
    if (!j.is_string()) return std::nullopt;
    const std::string& s = j.get_ref<const std::string&>();
    if (s == "NaN") return std::numeric_limits<double>::quiet_NaN();
    if (s == "Infinity") return std::numeric_limits<double>::infinity();
    if (s == "-Infinity") return -std::numeric_limits<double>::infinity();
    return std::nullopt;
}

template <>
struct JsonValue<float> {
    static nlohmann::json to(float v) {
        if (!std::isfinite(v)) return non_finite_name(v);
        return v;
    }
    static float from(const nlohmann::json& j) {
        const std::optional<double> v = json_number(j);
        if (!v) throw Error("expected a number, got " + j.dump());
        return static_cast<float>(*v);
    }
};

template <>
struct JsonValue<int> {
    static nlohmann::json to(int v) { return v; }
    static int from(const nlohmann::json& j) {
        if (!j.is_number_integer()) throw Error("expected an integer, got " + j.dump());
        return j.get<int>();
    }
};

template <>
struct JsonValue<bool> {
    static nlohmann::json to(bool v) { return v; }
    static bool from(const nlohmann::json& j) {
        if (!j.is_boolean()) throw Error("expected true or false, got " + j.dump());
        return j.get<bool>();
    }
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
            throw Error("expected an array of " + std::to_string(N) + " numbers, got " + j.dump());
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
            throw Error("expected " + std::to_string(C) + " columns, got " + j.dump());
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
