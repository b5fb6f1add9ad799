// Keyboard shortcuts of `lab run`: each parameter's key from its declaration
// (Bool toggles, Enum cycles, numbers step; Shift reverses) plus the window's
// own keys. The panel lists them from the same code that applies them.
#pragma once

#include <string>
#include <vector>

#include "framework/lab.hpp"

namespace fw::win {

// Applies the shortcut of every parameter whose key is `key` (an ASCII
// letter or digit; GLFW's key codes for A-Z and 0-9 are their ASCII codes).
// `repeat`: the key is held down; only numbers step again then.
// Returns true if a parameter changed.
bool apply_param_key(ParamValues& params, int key, bool shift, bool repeat);

struct Shortcut {
    std::string keys;    // "D", "F / Shift+F", "F12"
    std::string action;  // "toggle depth_test", "fov +/- 5 deg"
};
// The parameters' shortcuts, then R, F12 and Esc.
std::vector<Shortcut> shortcut_list(const LabInfo& info);

// Keys pressed by the LAB_RUN_SCRIPT variable, so that tests can drive the
// window without a keyboard: "1:D,2:Shift+F,3:F12" presses D in frame 1,
// Shift+F in frame 2, F12 in frame 3. Keys: a letter or digit, R, F12, Esc.
// Throws UsageError naming the variable for anything else.
struct ScriptedKey {
    int frame = 0;
    int key = 0;   // GLFW key code
    int mods = 0;  // GLFW_MOD_SHIFT or 0
};
std::vector<ScriptedKey> parse_key_script(const std::string& script);

}  // namespace fw::win
