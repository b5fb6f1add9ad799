// Keyboard shortcuts of `lab run`: each parameter's key from its declaration
// (Bool toggles, Enum cycles, numbers step; Shift reverses) plus the window's
// own keys. The panel lists them from the same code that applies them.
#pragma once

#include <string>
#include <vector>

#include "framework/lab.hpp"
#include "framework/shortcuts.hpp"

namespace fw::win {

// GLFW's key codes for A-Z and 0-9 are their ASCII codes, so the window
// passes them to fw::apply_param_key as they come.
using fw::apply_param_key;
using fw::Shortcut;

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
