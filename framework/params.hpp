// A lab's parameters, declared once. The command line (`--set name=value`),
// the window's panel and keyboard shortcuts, the checkpoints, `lab list` and
// the stats all read this one declaration. Each parameter's name is written
// once, in a typed handle, and the lab names the parameter through it:
//
//   enum class Scene { Order, Indexed };
//   constexpr fw::Choice<Scene> kScenes[] = {{Scene::Order, "order"}, {Scene::Indexed, "indexed"}};
//   constexpr fw::ParamId<Scene> kScene{"scene"};
//   constexpr fw::ParamId<float> kFov{"fov"};
//   constexpr fw::ParamId<bool> kDepthTest{"depth_test"};
//
//   fw::Param::choice(kScene, kScenes, Scene::Order).help("which scene").key('S'),
//   fw::Param::number(kFov, 60).range(10, 150).unit("deg").key('F'),
//   fw::Param::boolean(kDepthTest, true).key('D'),
//
// and in draw():  switch (params[kScene]) { case Scene::Order: ... }
//
// A misspelt handle is a compile error, and so is reading a parameter as
// another type than its handle's. A choice is bound to a C++ enum, so the
// lab compares enum values, never strings, and a declaration whose default
// is not among its choices throws when the lab is registered.
#pragma once

#include <array>
#include <glm/glm.hpp>
#include <initializer_list>
#include <nlohmann/json_fwd.hpp>  // declarations only: a file that uses a JSON value includes json.hpp
#include <string>
#include <type_traits>
#include <typeindex>
#include <typeinfo>
#include <vector>

#include "framework/names.hpp"  // fw::Choice: a choice's enum value and name

namespace fw {

// A parameter's name and the C++ type of its value: float (a number), int,
// bool, glm::vec3 (a colour) or the enum a choice is bound to.
template <class T>
struct ParamId {
    const char* name;
};

// The one parameter the framework reads itself: a lab that declares it
// animates while it is on, and `lab serve` then draws every frame with the
// time running (docs/contract.md, `lab serve`). It must be a bool: a lab
// that declares it as another type is refused when it starts.
constexpr ParamId<bool> kAnimate{"animate"};

enum class ParamType { Float, Int, Bool, Enum, Color };
const char* param_type_name(ParamType t);

struct Param {
    std::string name;
    ParamType type = ParamType::Float;
    std::string help_text;
    std::string unit_text;
    double default_number = 0.0, min = 0.0, max = 1.0, step_size = 0.0;  // Float, Int
    bool default_flag = false;                                           // Bool
    std::vector<std::string> choices;                                    // Enum: names
    std::vector<long long> choice_values;        // Enum: the C++ enum value of each name
    std::type_index choice_enum = typeid(void);  // Enum: the enum type it is bound to
    int default_choice = 0;
    glm::vec3 default_color{0.0f};  // Color
    // Window shortcut: a printable key ('A'..'Z', '0'..'9'). Bool toggles,
    // Enum cycles, numbers step up (with Shift, down). 0 = none.
    int shortcut = 0;

    static Param number(std::string name, double def);  // float
    static Param integer(std::string name, int def);
    static Param boolean(std::string name, bool def);
    // A choice bound to the enum E; `options` in the order the panel lists them.
    template <class E>
    static Param choice(std::string name, std::initializer_list<Choice<E>> options, E def) {
        return choice_of(std::move(name), options.begin(), options.size(), def);
    }
    template <class E, std::size_t N>
    static Param choice(std::string name, const Choice<E> (&options)[N], E def) {
        return choice_of(std::move(name), options, N, def);
    }
    template <class E, std::size_t N>
    static Param choice(std::string name, const std::array<Choice<E>, N>& options, E def) {
        return choice_of(std::move(name), options.data(), N, def);
    }
    static Param color(std::string name, const std::string& hex_rrggbb);
    // The same, named by a typed handle (the way labs declare them).
    static Param number(ParamId<float> id, double def) { return number(id.name, def); }
    static Param integer(ParamId<int> id, int def) { return integer(id.name, def); }
    static Param boolean(ParamId<bool> id, bool def) { return boolean(id.name, def); }
    static Param color(ParamId<glm::vec3> id, const std::string& hex_rrggbb) {
        return color(id.name, hex_rrggbb);
    }
    template <class E, class Options>
    static Param choice(ParamId<E> id, const Options& options, E def) {
        return choice(std::string(id.name), options, def);
    }
    // A choice over the names the enum is bound to (fw::ChoicesOf, names.hpp).
    template <class E, class = std::enable_if_t<HasChoices<E>::value>>
    static Param choice(ParamId<E> id, E def) {
        return choice(std::string(id.name), ChoicesOf<E>::list, def);
    }

    Param& range(double lo, double hi);
    Param& step(double s);  // keyboard step; default (max - min) / 20, integers 1
    Param& unit(std::string u);
    Param& help(std::string h);
    Param& key(int k);

    double key_step() const;
    std::string default_text() const;  // as --set would take it
    std::string range_text()
        const;  // "[10, 150] deg", "{order, indexed}", "true|false", "hex rrggbb"

private:
    template <class E>
    static Param choice_of(std::string name, const Choice<E>* options, std::size_t n, E def) {
        std::vector<std::string> names;
        std::vector<long long> values;
        for (std::size_t i = 0; i < n; ++i) {
            names.emplace_back(options[i].name);
            values.push_back(static_cast<long long>(options[i].value));
        }
        return make_choice(std::move(name), std::move(names), std::move(values),
                           static_cast<long long>(def), typeid(E));
    }
    // Checks the declaration (names non-empty and distinct, values distinct,
    // the default among them) and throws fw::Error naming what is wrong.
    static Param make_choice(std::string name, std::vector<std::string> names,
                             std::vector<long long> values, long long def, std::type_index type);
};

// A parameter as `lab list --json` and `lab serve`'s page describe it: name,
// type, help, unit, range and default; min, max and step for a number,
// choices for a choice, and its key when it has one.
nlohmann::json describe_param(const Param& p);

// The resolved value of every parameter of one lab.
class ParamValues {
public:
    ParamValues() = default;
    ParamValues(std::string lab, const std::vector<Param>* params);  // all defaults

    // Parses and validates `text` for parameter `name`; throws UsageError naming
    // the lab, the parameter and what would be valid.
    void set(const std::string& name, const std::string& text);
    // "name=value", as --set takes it.
    void set_assignment(const std::string& assignment);
    void set_json(const std::string& name, const nlohmann::json& value);

    float number(const std::string& name) const;  // Float (also Int)
    int integer(const std::string& name) const;
    bool flag(const std::string& name) const;
    glm::vec3 color(const std::string& name) const;
    // The value of a choice parameter as its enum; throws fw::Error when the
    // parameter is not a choice bound to E.
    template <class E>
    E get(const std::string& name) const {
        return static_cast<E>(choice_value(name, typeid(E)));
    }

    // A parameter's value through its typed handle (ParamId).
    float operator[](ParamId<float> id) const { return number(id.name); }
    int operator[](ParamId<int> id) const { return integer(id.name); }
    bool operator[](ParamId<bool> id) const { return flag(id.name); }
    glm::vec3 operator[](ParamId<glm::vec3> id) const { return color(id.name); }
    template <class E>
    E operator[](ParamId<E> id) const {
        static_assert(std::is_enum_v<E>, "a ParamId is of float, int, bool, glm::vec3 or an enum");
        return get<E>(id.name);
    }

    // Sets a number parameter to `value` clamped to its declared range, as a
    // drag or scroll does; returns the value set.
    double set_clamped(const std::string& name, double value);
    double set_clamped(ParamId<float> id, double value) { return set_clamped(id.name, value); }
    // The value itself, unclamped, for a handler that wraps an angle round.
    double& number_ref(ParamId<float> id) { return number_ref(id.name); }

    // Direct, validated access for the window panel.
    double& number_ref(const std::string& name);
    bool& flag_ref(const std::string& name);
    int& choice_ref(const std::string& name);
    glm::vec3& color_ref(const std::string& name);

    std::string text(const std::string& name) const;  // as --set would take it
    nlohmann::json to_json() const;                   // every resolved value
    const std::vector<Param>& params() const { return *params_; }
    const std::string& lab() const { return lab_; }
    // Whether the lab declares the parameter (a handle's type is checked when
    // it is read).
    template <class T>
    bool declares(ParamId<T> id) const {
        return declares(id.name);
    }

private:
    struct Value {
        double number = 0.0;
        bool flag = false;
        int choice = 0;
        glm::vec3 color{0.0f};
    };
    bool declares(const std::string& name) const;
    size_t index_of(const std::string& name) const;
    size_t index_of(const std::string& name, ParamType want) const;
    long long choice_value(const std::string& name, std::type_index type) const;

    std::string lab_;
    const std::vector<Param>* params_ = nullptr;
    std::vector<Value> values_;
};

// "ff8000" or "#ff8000" -> (1, 0.502, 0); false if malformed.
bool parse_hex_color(const std::string& text, glm::vec3& out);
std::string hex_color(glm::vec3 c);

}  // namespace fw
