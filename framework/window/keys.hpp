// Keyboard shortcuts of `lab run`: the session's keys (each parameter's key
// from its declaration, R) plus the window's own, F12 and Esc. The panel
// lists them from the same code that applies them.
#pragma once

#include <string>
#include <vector>

#include "framework/lab.hpp"
#include "framework/shortcuts.hpp"

namespace fw::win {

using fw::Shortcut;

// The session's keys (LabSession::shortcuts), then F12 and Esc.
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
