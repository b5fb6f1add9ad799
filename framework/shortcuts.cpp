#include "framework/shortcuts.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>

#include "framework/text.hpp"

namespace fw {

namespace {

int key_code(const Param& p) { return std::toupper(static_cast<unsigned char>(p.shortcut)); }

std::string key_name(const Param& p) { return std::string(1, static_cast<char>(key_code(p))); }

bool step_number(const Param& p, double& value, bool shift) {
    double next = value + (shift ? -p.key_step() : p.key_step());
    if (p.type == ParamType::Int) next = std::round(next);
    next = std::clamp(next, p.min, p.max);
    bool changed = next != value;
    value = next;
    return changed;
}

}  // namespace

bool apply_param_key(ParamValues& params, int key, bool shift, bool repeat) {
    bool changed = false;
    for (const Param& p : params.params()) {
        if (p.shortcut == 0 || key_code(p) != key) continue;
        switch (p.type) {
            case ParamType::Bool:
                if (repeat) break;
                params.flag_ref(p.name) = !params.flag_ref(p.name);
                changed = true;
                break;
            case ParamType::Enum: {
                if (repeat) break;
                int n = static_cast<int>(p.choices.size());
                int& index = params.choice_ref(p.name);
                index = (index + (shift ? n - 1 : 1)) % n;
                changed = true;
                break;
            }
            case ParamType::Float:
            case ParamType::Int:
                changed = step_number(p, params.number_ref(p.name), shift) || changed;
                break;
            case ParamType::Color:
                break;  // no sensible single-key edit of a colour
        }
    }
    return changed;
}

std::vector<Shortcut> param_shortcuts(const LabInfo& info) {
    std::vector<Shortcut> list;
    for (const Param& p : info.params) {
        if (p.shortcut == 0 || p.type == ParamType::Color) continue;
        std::string k = key_name(p);
        switch (p.type) {
            case ParamType::Bool:
                list.push_back({k, "toggle " + p.name});
                break;
            case ParamType::Enum:
                list.push_back({k + " / Shift+" + k, "cycle " + p.name});
                break;
            default: {
                std::string unit = p.unit_text.empty() ? "" : " " + p.unit_text;
                list.push_back(
                    {k + " / Shift+" + k, p.name + " +/- " + number_text(p.key_step()) + unit});
            }
        }
    }
    return list;
}

}  // namespace fw
