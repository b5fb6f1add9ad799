// The Dear ImGui side of `lab run`: the parameter panel generated from the
// lab's declaration, and the red error overlay. Call between
// ImGuiLayer::begin_frame() and end_frame().
#pragma once

#include <string>
#include <vector>

#include "framework/lab.hpp"

namespace fw::win {

// One widget per parameter (slider with range and unit, checkbox, combo,
// colour editor; help as tooltip, shortcut key in the label), "Reset to
// defaults", the keyboard shortcuts, frame rate and GL renderer, and
// `notice` (that the window renders in software, and why) when not empty.
// True when the user changed `params`.
bool draw_panel(const RegisteredLab& lab, ParamValues& params, const std::string& gl_renderer,
                const std::string& notice);

// A red window at the bottom listing `messages` in full; nothing if empty.
void draw_errors(const std::vector<std::string>& messages);

}  // namespace fw::win
