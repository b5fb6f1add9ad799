// Values with names. A C++ enum whose values have names: the names users type
// for a choice parameter (`--set order=srt`), and the names unit functions
// exchange with the grader for an enum argument. A lab lists an enum's names once, as an
// array of fw::Choice, and may bind the enum to it so that unit functions
// taking or returning it need no other spelling:
//
//   enum class Order { Trs, Srt };
//   constexpr fw::Choice<Order> kOrders[] = {{Order::Trs, "trs"}, {Order::Srt, "srt"}};
//   template <> struct fw::ChoicesOf<Order> { static constexpr const auto& list = kOrders; };
//
// (the specialisation outside the lab's namespace). Then
// fw::choice_name(Order::Srt) is "srt".
#pragma once

#include <cstddef>
#include <iterator>
#include <string>
#include <string_view>

namespace fw {

// One value of a choice: the C++ enum value and its name.
template <class E>
struct Choice {
    E value;
    const char* name;
};

// Specialise for an enum E with `static constexpr const auto& list`, an array
// of Choice<E> (above); unspecialised, E has no names.
template <class E>
struct ChoicesOf {};

template <class E, class = void>
struct HasChoices {
    static constexpr bool value = false;
};
template <class E>
struct HasChoices<E, decltype(void(ChoicesOf<E>::list))> {
    static constexpr bool value = true;
};

// The name of `value` in ChoicesOf<E>; "" when it has none.
template <class E>
const char* choice_name(E value) {
    for (const Choice<E>& c : ChoicesOf<E>::list)
        if (c.value == value) return c.name;
    return "";
}

// "trs, tsr, rts": the names of E, for messages.
template <class E>
std::string choice_names() {
    std::string out;
    for (const Choice<E>& c : ChoicesOf<E>::list)
        out += (out.empty() ? "" : ", ") + std::string(c.name);
    return out;
}

// A small aggregate whose fields have names, for a unit function's result
// (units.hpp): the grader's report names each field ("your J").
//
//   struct ArmMatrices { glm::mat4 S, J, H; };
//   template <> struct fw::FieldsOf<ArmMatrices> {
//       static constexpr fw::Field<ArmMatrices, glm::mat4> list[] = {
//           {"S", &ArmMatrices::S}, {"J", &ArmMatrices::J}, {"H", &ArmMatrices::H}};
//   };
// One named field of an aggregate unit value, all of type F.
template <class T, class F>
struct Field {
    using Member = F T::*;
    const char* name;
    Member member;
};

// Specialise for an aggregate T with `static constexpr Field<T, F> list[]`
// (above), every field of T in order; unspecialised, T has no fields.
template <class T>
struct FieldsOf {};

template <class T, class = void>
struct HasFields {
    static constexpr bool value = false;
};
template <class T>
struct HasFields<T, decltype(void(FieldsOf<T>::list))> {
    static constexpr bool value = true;
};

}  // namespace fw
