// JSON for the GLM types that unit checks pass around: a vecN is an array of
// N numbers, a matN an array of N columns (GLM storage: m[column][row]).
// The `lab` child and `course` both read and write values this way.
#pragma once

#include <glm/glm.hpp>
#include <nlohmann/json.hpp>
#include <string>

#include "framework/error.hpp"

namespace fw {

// to(T) -> json, from(json) -> T; throws Error when malformed. The second
// parameter lets a specialisation pick a family of types (units.hpp: enums
// with names, aggregates with named fields).
template <class T, class = void>
struct JsonValue;

template <>
struct JsonValue<float> {
    static nlohmann::json to(float v) { return v; }
    static float from(const nlohmann::json& j) {
        if (!j.is_number()) throw Error("expected a number, got " + j.dump());
        return j.get<float>();
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
        for (glm::length_t i = 0; i < N; ++i) out.push_back(v[i]);
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
