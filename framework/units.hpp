// Unit functions: the student functions of a lab (translate, lookAt, ...)
// that the grader evaluates on inputs it chooses. A lab lists them in its
// LabInfo; the `lab` child only calls them and reports what they return,
// and `course` compares the results with its own reference
// (labs/NN_name/grading/*.cpp).
//
//   info.functions = {
//       fw::unit_function("translate", &transforms::translate),  // mat4 (vec3)
//       fw::unit_function("rotate", &transforms::rotate),        // mat4 (float, vec3)
//   };
//
// Arguments arrive as a JSON array, one element per parameter, and the result
// goes back as JSON (json_glm.hpp). Supported types: float, int, bool, vecN,
// matN, an enum bound to its names (names.hpp; in JSON, the name), and as
// results a std::vector of those or a small aggregate whose fields are
// named for the grader (fw::FieldsOf in names.hpp; in JSON, the fields in
// order, as a list).
#pragma once

#include <functional>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "framework/json_glm.hpp"
#include "framework/names.hpp"

namespace fw {

template <class T>
struct JsonValue<std::vector<T>> {
    static nlohmann::json to(const std::vector<T>& v) {
        nlohmann::json out = nlohmann::json::array();
        for (const T& e : v) out.push_back(JsonValue<T>::to(e));
        return out;
    }
    static std::vector<T> from(const nlohmann::json& j) {
        if (!j.is_array()) throw_mismatch("expected an array", j);
        std::vector<T> out;
        for (const auto& e : j) out.push_back(JsonValue<T>::from(e));
        return out;
    }
};

// An enum bound to its names: the name in JSON.
template <class E>
struct JsonValue<E, std::enable_if_t<std::is_enum_v<E> && HasChoices<E>::value>> {
    static nlohmann::json to(E v) { return choice_name(v); }
    static E from(const nlohmann::json& j) {
        if (j.is_string())
            for (const Choice<E>& c : ChoicesOf<E>::list)
                if (j.get<std::string>() == c.name) return c.value;
        throw_mismatch("expected one of " + choice_names<E>(), j);
    }
};

// An aggregate with named fields: its fields in order, as a JSON list.
template <class T>
struct JsonValue<T, std::enable_if_t<HasFields<T>::value>> {
    using FieldType = std::remove_reference_t<decltype(T{}.*(FieldsOf<T>::list[0].member))>;
    static_assert(sizeof(T) == std::size(FieldsOf<T>::list) * sizeof(FieldType),
                  "fw::FieldsOf<T> must list every field of T");
    static nlohmann::json to(const T& v) {
        nlohmann::json out = nlohmann::json::array();
        for (const auto& f : FieldsOf<T>::list)
            out.push_back(JsonValue<FieldType>::to(v.*f.member));
        return out;
    }
    static T from(const nlohmann::json& j) {
        constexpr size_t n = std::size(FieldsOf<T>::list);
        if (!j.is_array() || j.size() != n)
            throw_mismatch("expected a list of " + std::to_string(n) + " values", j);
        T v{};
        size_t i = 0;
        for (const auto& f : FieldsOf<T>::list) v.*f.member = JsonValue<FieldType>::from(j[i++]);
        return v;
    }
};

struct UnitFunction {
    std::string name;
    int arity = 0;
    // Calls the function with `args` (a JSON array); throws Error when the
    // arguments do not fit its parameters.
    std::function<nlohmann::json(const nlohmann::json& args)> call;
};

namespace detail {
template <class R, class... A, size_t... I>
nlohmann::json call_with_json(R (*f)(A...), const nlohmann::json& args, std::index_sequence<I...>) {
    return to_json_value<std::decay_t<R>>(f(from_json_value<std::decay_t<A>>(args[I])...));
}
}  // namespace detail

template <class R, class... A>
UnitFunction unit_function(std::string name, R (*f)(A...)) {
    UnitFunction u;
    u.name = name;
    u.arity = static_cast<int>(sizeof...(A));
    u.call = [f, name](const nlohmann::json& args) {
        if (!args.is_array() || args.size() != sizeof...(A))
            throw_mismatch(
                "unit function '" + name + "' takes " + std::to_string(sizeof...(A)) + " arguments",
                args);
        return detail::call_with_json(f, args, std::index_sequence_for<A...>{});
    };
    return u;
}

}  // namespace fw
