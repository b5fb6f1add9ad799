#include "framework/params.hpp"

#include <cxxabi.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <nlohmann/json.hpp>

#include "framework/error.hpp"
#include "framework/text.hpp"

namespace fw {

namespace {

// "pipeline::Scene" for a type's name, as the compiler spells it.
std::string type_name(std::type_index type) {
    int status = 0;
    char* name = abi::__cxa_demangle(type.name(), nullptr, nullptr, &status);
    std::string out = status == 0 && name ? name : type.name();
    std::free(name);
    return out;
}

bool parse_double(const std::string& text, double& out) {
    if (text.empty()) return false;
    char* end = nullptr;
    errno = 0;
    out = std::strtod(text.c_str(), &end);
    return errno == 0 && end == text.c_str() + text.size() && std::isfinite(out);
}

}  // namespace

const char* param_type_name(ParamType t) {
    switch (t) {
        case ParamType::Float:
            return "float";
        case ParamType::Int:
            return "int";
        case ParamType::Bool:
            return "bool";
        case ParamType::Enum:
            return "enum";
        case ParamType::Color:
            return "color";
    }
    return "?";
}

Param Param::number(std::string name, double def) {
    Param p;
    p.name = std::move(name);
    p.type = ParamType::Float;
    p.default_number = def;
    p.min = def - 1.0;
    p.max = def + 1.0;
    return p;
}

Param Param::integer(std::string name, int def) {
    Param p = number(std::move(name), def);
    p.type = ParamType::Int;
    return p;
}

Param Param::boolean(std::string name, bool def) {
    Param p;
    p.name = std::move(name);
    p.type = ParamType::Bool;
    p.default_flag = def;
    return p;
}

Param Param::make_choice(std::string name, std::vector<std::string> names,
                         std::vector<long long> values, long long def, std::type_index type) {
    Param p;
    p.name = std::move(name);
    p.type = ParamType::Enum;
    p.choice_enum = type;
    const std::string where = "parameter '" + p.name + "'";
    if (names.empty()) throw Error(where + ": a choice needs at least one value");
    for (std::size_t i = 0; i < names.size(); ++i) {
        if (names[i].empty()) throw Error(where + ": choice " + std::to_string(i) + " has no name");
        for (std::size_t j = 0; j < i; ++j) {
            if (names[j] == names[i])
                throw Error(where + ": the name '" + names[i] + "' is given twice");
            if (values[j] == values[i])
                throw Error(where + ": '" + names[j] + "' and '" + names[i] +
                            "' are the same enum value");
        }
    }
    p.choices = std::move(names);
    p.choice_values = std::move(values);
    p.default_choice = -1;
    for (std::size_t i = 0; i < p.choice_values.size(); ++i)
        if (p.choice_values[i] == def) p.default_choice = static_cast<int>(i);
    if (p.default_choice < 0)
        throw Error(where + ": the default (enum value " + std::to_string(def) +
                    ") is not one of its choices {" + join(p.choices, ", ") + "}");
    return p;
}

Param Param::color(std::string name, const std::string& hex_rrggbb) {
    Param p;
    p.name = std::move(name);
    p.type = ParamType::Color;
    if (!parse_hex_color(hex_rrggbb, p.default_color))
        throw Error("parameter '" + p.name + "': default '" + hex_rrggbb + "' is not hex rrggbb");
    return p;
}

Param& Param::range(double lo, double hi) {
    if (!(lo <= default_number && default_number <= hi))
        throw Error("parameter '" + name + "': default " + number_text(default_number) +
                    " is outside its range [" + number_text(lo) + ", " + number_text(hi) + "]");
    min = lo;
    max = hi;
    return *this;
}
Param& Param::step(double s) {
    step_size = s;
    return *this;
}
Param& Param::unit(std::string u) {
    unit_text = std::move(u);
    return *this;
}
Param& Param::help(std::string h) {
    help_text = std::move(h);
    return *this;
}
Param& Param::key(int k) {
    shortcut = k;
    return *this;
}

double Param::key_step() const {
    if (step_size > 0.0) return step_size;
    if (type == ParamType::Int) return 1.0;
    return (max - min) / 20.0;
}

std::string Param::default_text() const {
    switch (type) {
        case ParamType::Float:
        case ParamType::Int:
            return number_text(default_number);
        case ParamType::Bool:
            return default_flag ? "true" : "false";
        case ParamType::Enum:
            return choices[static_cast<size_t>(default_choice)];
        case ParamType::Color:
            return hex_color(default_color);
    }
    return {};
}

std::string Param::range_text() const {
    switch (type) {
        case ParamType::Float:
        case ParamType::Int: {
            std::string r = "[" + number_text(min) + ", " + number_text(max) + "]";
            if (type == ParamType::Int) r += " integer";
            return unit_text.empty() ? r : r + " " + unit_text;
        }
        case ParamType::Bool:
            return "true|false";
        case ParamType::Enum:
            return "{" + join(choices, ", ") + "}";
        case ParamType::Color:
            return "hex rrggbb";
    }
    return {};
}

bool parse_hex_color(const std::string& text, glm::vec3& out) {
    std::string s = (!text.empty() && text[0] == '#') ? text.substr(1) : text;
    if (s.size() != 6) return false;
    unsigned v[3];
    for (int i = 0; i < 3; ++i) {
        std::string byte = s.substr(static_cast<size_t>(2 * i), 2);
        char* end = nullptr;
        v[i] = static_cast<unsigned>(std::strtoul(byte.c_str(), &end, 16));
        if (end != byte.c_str() + 2) return false;
    }
    out = glm::vec3(v[0], v[1], v[2]) / 255.0f;
    return true;
}

std::string hex_color(glm::vec3 c) {
    char buf[8];
    auto byte = [](float f) {
        return static_cast<int>(std::lround(glm::clamp(f, 0.0f, 1.0f) * 255.0f));
    };
    std::snprintf(buf, sizeof buf, "%02x%02x%02x", byte(c.r), byte(c.g), byte(c.b));
    return buf;
}

ParamValues::ParamValues(std::string lab, const std::vector<Param>* params)
    : lab_(std::move(lab)), params_(params), values_(params->size()) {
    for (size_t i = 0; i < params->size(); ++i) {
        const Param& p = (*params)[i];
        values_[i] = {p.default_number, p.default_flag, p.default_choice, p.default_color};
    }
}

bool ParamValues::declares(const std::string& name) const {
    return std::any_of(params_->begin(), params_->end(),
                       [&name](const Param& p) { return p.name == name; });
}

size_t ParamValues::index_of(const std::string& name) const {
    std::vector<std::string> names;
    for (size_t i = 0; i < params_->size(); ++i) {
        if ((*params_)[i].name == name) return i;
        names.push_back((*params_)[i].name);
    }
    throw UsageError("lab '" + lab_ + "' has no parameter '" + name + "'; its parameters are: " +
                     (names.empty() ? std::string("(none)") : join(names, ", ")));
}

size_t ParamValues::index_of(const std::string& name, ParamType want) const {
    size_t i = index_of(name);
    ParamType have = (*params_)[i].type;
    bool ok = have == want || (want == ParamType::Float && have == ParamType::Int);
    if (!ok)
        throw Error("lab '" + lab_ + "': parameter '" + name + "' is " + param_type_name(have) +
                    ", read as " + param_type_name(want) + "; use the accessor for " +
                    param_type_name(have));
    return i;
}

void ParamValues::set(const std::string& name, const std::string& text) {
    size_t i = index_of(name);
    const Param& p = (*params_)[i];
    Value& v = values_[i];
    std::string where = "lab '" + lab_ + "', parameter '" + name + "'";
    switch (p.type) {
        case ParamType::Float:
        case ParamType::Int: {
            double d = 0.0;
            if (!parse_double(text, d))
                throw UsageError(where + ": '" + text + "' is not a number; expected " +
                                 p.range_text());
            if (p.type == ParamType::Int && d != std::floor(d))
                throw UsageError(where + ": '" + text + "' is not an integer; expected " +
                                 p.range_text());
            if (d < p.min || d > p.max)
                throw UsageError(where + ": " + text + " is out of range; expected " +
                                 p.range_text());
            v.number = d;
            return;
        }
        case ParamType::Bool: {
            if (text == "true" || text == "1" || text == "on" || text == "yes")
                v.flag = true;
            else if (text == "false" || text == "0" || text == "off" || text == "no")
                v.flag = false;
            else
                throw UsageError(where + ": '" + text + "' is not a bool; expected true or false");
            return;
        }
        case ParamType::Enum: {
            for (size_t c = 0; c < p.choices.size(); ++c)
                if (p.choices[c] == text) {
                    v.choice = static_cast<int>(c);
                    return;
                }
            throw UsageError(where + ": unknown value '" + text +
                             "'; valid values: " + join(p.choices, ", "));
        }
        case ParamType::Color:
            if (!parse_hex_color(text, v.color))
                throw UsageError(where + ": '" + text +
                                 "' is not a colour; expected hex rrggbb, e.g. ff8000");
            return;
    }
}

void ParamValues::set_assignment(const std::string& assignment) {
    size_t eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0)
        throw UsageError("--set '" + assignment + "': expected name=value, e.g. --set fov=45");
    set(assignment.substr(0, eq), assignment.substr(eq + 1));
}

void ParamValues::set_json(const std::string& name, const nlohmann::json& value) {
    if (value.is_string()) return set(name, value.get<std::string>());
    if (value.is_boolean()) return set(name, value.get<bool>() ? "true" : "false");
    if (value.is_number()) return set(name, number_text(value.get<double>()));
    throw UsageError("lab '" + lab_ + "', parameter '" + name + "': value " + value.dump() +
                     " must be a string, number or bool");
}

float ParamValues::number(const std::string& name) const {
    return static_cast<float>(values_[index_of(name, ParamType::Float)].number);
}
int ParamValues::integer(const std::string& name) const {
    return static_cast<int>(values_[index_of(name, ParamType::Int)].number);
}
bool ParamValues::flag(const std::string& name) const {
    return values_[index_of(name, ParamType::Bool)].flag;
}
long long ParamValues::choice_value(const std::string& name, std::type_index type) const {
    const size_t i = index_of(name, ParamType::Enum);
    const Param& p = (*params_)[i];
    if (p.choice_enum != type)
        throw Error("lab '" + lab_ + "': parameter '" + name + "' is a choice of " +
                    type_name(p.choice_enum) + ", read as " + type_name(type) +
                    "; read it with get<" + type_name(p.choice_enum) + ">");
    return p.choice_values[static_cast<size_t>(values_[i].choice)];
}
double ParamValues::set_clamped(const std::string& name, double value) {
    const size_t i = index_of(name, ParamType::Float);
    const Param& p = (*params_)[i];
    double v = std::clamp(value, p.min, p.max);
    if (p.type == ParamType::Int) v = std::round(v);
    values_[i].number = v;
    return v;
}
glm::vec3 ParamValues::color(const std::string& name) const {
    return values_[index_of(name, ParamType::Color)].color;
}
double& ParamValues::number_ref(const std::string& name) {
    return values_[index_of(name, ParamType::Float)].number;
}
bool& ParamValues::flag_ref(const std::string& name) {
    return values_[index_of(name, ParamType::Bool)].flag;
}
int& ParamValues::choice_ref(const std::string& name) {
    return values_[index_of(name, ParamType::Enum)].choice;
}
glm::vec3& ParamValues::color_ref(const std::string& name) {
    return values_[index_of(name, ParamType::Color)].color;
}

std::string ParamValues::text(const std::string& name) const {
    size_t i = index_of(name);
    const Param& p = (*params_)[i];
    const Value& v = values_[i];
    switch (p.type) {
        case ParamType::Float:
        case ParamType::Int:
            return number_text(v.number);
        case ParamType::Bool:
            return v.flag ? "true" : "false";
        case ParamType::Enum:
            return p.choices[static_cast<size_t>(v.choice)];
        case ParamType::Color:
            return hex_color(v.color);
    }
    return {};
}

nlohmann::json ParamValues::to_json() const {
    nlohmann::json out = nlohmann::json::object();
    for (size_t i = 0; i < params_->size(); ++i) {
        const Param& p = (*params_)[i];
        const Value& v = values_[i];
        switch (p.type) {
            case ParamType::Float:
                out[p.name] = v.number;
                break;
            case ParamType::Int:
                out[p.name] = static_cast<long>(v.number);
                break;
            case ParamType::Bool:
                out[p.name] = v.flag;
                break;
            case ParamType::Enum:
                out[p.name] = p.choices[static_cast<size_t>(v.choice)];
                break;
            case ParamType::Color:
                out[p.name] = hex_color(v.color);
                break;
        }
    }
    return out;
}

nlohmann::json describe_param(const Param& p) {
    nlohmann::json d = {{"name", p.name},          {"type", param_type_name(p.type)},
                        {"help", p.help_text},     {"unit", p.unit_text},
                        {"range", p.range_text()}, {"default", p.default_text()}};
    if (p.type == ParamType::Float || p.type == ParamType::Int)
        d.update({{"min", p.min}, {"max", p.max}, {"step", p.key_step()}});
    if (p.type == ParamType::Enum) d["choices"] = p.choices;
    if (p.shortcut) d["key"] = std::string(1, static_cast<char>(std::toupper(p.shortcut)));
    return d;
}

}  // namespace fw
