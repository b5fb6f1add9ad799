#include "framework/window/keys.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <sstream>

#include "framework/error.hpp"

namespace fw::win {

namespace {

int key_code(const Param& p) { return std::toupper(static_cast<unsigned char>(p.shortcut)); }

std::string key_name(const Param& p) { return std::string(1, static_cast<char>(key_code(p))); }

std::string number_text(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", v);
    return buf;
}

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

std::vector<Shortcut> shortcut_list(const LabInfo& info) {
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
    list.push_back({"R", "reload shaders from disk"});
    list.push_back({"F12", "save screenshot-" + info.id + "-NNN.png"});
    list.push_back({"Esc", "quit"});
    return list;
}

std::vector<ScriptedKey> parse_key_script(const std::string& script) {
    std::vector<ScriptedKey> keys;
    std::stringstream items(script);
    std::string item;
    while (std::getline(items, item, ',')) {
        auto bad = [&] {
            throw UsageError("LAB_RUN_SCRIPT: '" + item +
                             "' is not FRAME:KEY (KEY: a letter, a digit, Shift+KEY, F12 or Esc), "
                             "e.g. LAB_RUN_SCRIPT=1:D,2:F12");
        };
        size_t colon = item.find(':');
        if (colon == std::string::npos || colon == 0) bad();
        char* end = nullptr;
        long frame = std::strtol(item.c_str(), &end, 10);
        if (end != item.c_str() + colon || frame < 1) bad();
        ScriptedKey k;
        k.frame = static_cast<int>(frame);
        std::string name = item.substr(colon + 1);
        if (name.rfind("Shift+", 0) == 0) {
            k.mods = GLFW_MOD_SHIFT;
            name = name.substr(6);
        }
        if (name == "F12")
            k.key = GLFW_KEY_F12;
        else if (name == "Esc")
            k.key = GLFW_KEY_ESCAPE;
        else if (name.size() == 1 && std::isalnum(static_cast<unsigned char>(name[0])))
            k.key = std::toupper(static_cast<unsigned char>(name[0]));
        else
            bad();
        keys.push_back(k);
    }
    return keys;
}

}  // namespace fw::win
