// `lab run`: the lab in a GLFW window (GL 4.3 core) with a Dear ImGui panel
// generated from the lab's parameter declaration.
#pragma once

#include <string>

#include "framework/lab.hpp"

namespace fw {

struct WindowOptions {
    int width = 512, height = 512;
    int frames = 0;          // quit after this many frames; 0 = run until Esc / close
    std::string screenshot;  // save the last frame here (PNG) when quitting
    bool show_ui = true;     // --no-ui hides the panel
};

// Opens the window and runs until Esc, the close button or `frames`. When the
// driver offers no GL 4.3 core context, the window renders with Mesa's
// llvmpipe instead, and says so in the panel and once on stderr.
// Throws EnvironmentError when there is no display (naming $DISPLAY /
// $WAYLAND_DISPLAY and suggesting xvfb-run, `lab render` or `lab serve`) or no
// GL 4.3 core even in software (naming the version offered and suggesting
// `lab serve` or `lab render`), Error otherwise.
void run_window(const RegisteredLab& lab, ParamValues params, const WindowOptions& options);

}  // namespace fw
