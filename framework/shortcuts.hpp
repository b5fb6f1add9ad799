// Keyboard shortcuts of the lab's parameters, from their declaration: Bool
// toggles, Enum cycles, numbers step (Shift reverses). LabSession
// (framework/session.hpp) applies and lists them for the window (`lab run`)
// and the browser page (`lab serve`).
#pragma once

#include <string>
#include <vector>

#include "framework/lab.hpp"

namespace fw {

// Applies the shortcut of every parameter whose key is `key` (an upper-case
// ASCII letter or a digit). `repeat`: the key is held down; only numbers
// step again then. Returns true if a parameter changed.
bool apply_param_key(ParamValues& params, int key, bool shift, bool repeat);

struct Shortcut {
    std::string keys;    // "D", "F / Shift+F", "F12"
    std::string action;  // "toggle depth_test", "fov +/- 5 deg"
};
// The parameters' shortcuts, in declaration order.
std::vector<Shortcut> param_shortcuts(const LabInfo& info);

}  // namespace fw
