// `lab run`: each frame is drawn by LabRenderer, exactly as `lab render`
// draws it offscreen, the renderer's framebuffer is copied
// (glBlitFramebuffer) into the window, and the ImGui panel is drawn on top.
// The parameters, keys, mouse input, shader reloads and the problems shown
// are a LabSession's, as in `lab serve`; the window adds F12, Esc and the panel.
#include "framework/window/window.hpp"

#include <glad/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "framework/context.hpp"
#include "framework/error.hpp"
#include "framework/gl/debug.hpp"
#include "framework/gl/framebuffer.hpp"
#include "framework/image.hpp"
#include "framework/render.hpp"
#include "framework/session.hpp"
#include "framework/window/glfw.hpp"
#include "framework/window/keys.hpp"
#include "framework/window/panel.hpp"

namespace fw {

namespace {

// What the GLFW callbacks (called inside glfwPollEvents) share with the loop.
struct InputState {
    LabSession* session = nullptr;
    bool screenshot = false;
    bool dragging = false;
    double last_x = 0.0, last_y = 0.0;
    // A key or panel edit the session refused, or a screenshot that failed:
    // C callbacks must not throw, so the error list shows it instead.
    std::string refused;
};

InputState& input_of(GLFWwindow* window) {
    return *static_cast<InputState*>(glfwGetWindowUserPointer(window));
}

void on_key(GLFWwindow* window, int key, int /*scancode*/, int action, int mods) {
    InputState& in = input_of(window);
    // While the user types into an ImGui field, keys belong to the field.
    if (action == GLFW_RELEASE || ImGui::GetIO().WantCaptureKeyboard) return;
    if (mods & (GLFW_MOD_CONTROL | GLFW_MOD_ALT | GLFW_MOD_SUPER)) return;
    const bool press = action == GLFW_PRESS;
    if (key == GLFW_KEY_ESCAPE && press) {
        glfwSetWindowShouldClose(window, GLFW_TRUE);
    } else if (key == GLFW_KEY_F12 && press) {
        in.screenshot = true;
    } else if ((key >= GLFW_KEY_A && key <= GLFW_KEY_Z) ||
               (key >= GLFW_KEY_0 && key <= GLFW_KEY_9)) {
        // GLFW's codes for A-Z and 0-9 are their ASCII codes, as the session takes them.
        try {
            if (in.session->press_key(key, (mods & GLFW_MOD_SHIFT) != 0, !press))
                in.refused.clear();
        } catch (const Error& e) {
            in.refused = e.what();
        }
    }
}

void on_mouse_button(GLFWwindow* window, int button, int action, int /*mods*/) {
    InputState& in = input_of(window);
    if (button != GLFW_MOUSE_BUTTON_LEFT) return;
    // A drag that starts over the panel moves the slider, not the camera.
    if (action == GLFW_PRESS && !ImGui::GetIO().WantCaptureMouse) {
        in.dragging = true;
        glfwGetCursorPos(window, &in.last_x, &in.last_y);
    } else if (action == GLFW_RELEASE) {
        in.dragging = false;
    }
}

void on_cursor(GLFWwindow* window, double x, double y) {
    InputState& in = input_of(window);
    if (!in.dragging) return;
    // GLFW's y grows downwards; the lab gets GL's convention, up positive.
    in.session->drag(x - in.last_x, in.last_y - y);
    in.last_x = x;
    in.last_y = y;
}

void on_scroll(GLFWwindow* window, double /*x*/, double y) {
    InputState& in = input_of(window);
    if (!ImGui::GetIO().WantCaptureMouse) in.session->scroll(y);
}

// The window as it looks now: the back buffer, after drawing, before the swap.
Image read_window(int width, int height) {
    Image img(width, height);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, img.pixels.data());
    check_gl("reading the window's back buffer for a screenshot");
    // The window is opaque whatever alpha the default framebuffer holds.
    for (Rgba8& p : img.pixels) p.a = 255;
    return img;
}

std::string next_screenshot_path(const std::string& lab_id) {
    for (int n = 1;; ++n) {
        char name[64];
        std::snprintf(name, sizeof name, "-%03d.png", n);
        std::string path = "screenshot-" + lab_id + name;
        if (!std::filesystem::exists(path)) return path;
    }
}

std::string window_title(const LabInfo& info) {
    char number[16];
    std::snprintf(number, sizeof number, "%02d", info.number);
    return "lab " + std::string(number) + " " + info.id + ": " + info.title;
}

// Prints each problem once, when it appears, so the terminal has it too.
void print_new(const std::vector<std::string>& problems, std::vector<std::string>& printed) {
    for (const std::string& p : problems)
        if (std::find(printed.begin(), printed.end(), p) == printed.end())
            std::fprintf(stderr, "lab: %s\n", p.c_str());
    printed = problems;
}

void install_callbacks(GLFWwindow* window, InputState& input) {
    glfwSetWindowUserPointer(window, &input);
    glfwSetKeyCallback(window, on_key);
    glfwSetMouseButtonCallback(window, on_mouse_button);
    glfwSetCursorPosCallback(window, on_cursor);
    glfwSetScrollCallback(window, on_scroll);
}

// What one window's frames share: the lab, its renderer and session, the
// window and its input, the options.
struct WindowParts {
    const RegisteredLab& lab;
    LabRenderer& renderer;
    LabSession& session;
    const WindowOptions& options;
    GLFWwindow* window;
    InputState& input;
    win::ImGuiLayer& imgui;
    std::string gl_renderer;
    std::string software_notice;  // shown in the panel when not empty
};

class WindowLoop {
public:
    explicit WindowLoop(WindowParts parts) : p_(std::move(parts)) {}

    // Frame `n` (from 1); false once it was the last.
    bool frame(int n, const std::vector<win::ScriptedKey>& scripted) {
        glfwPollEvents();
        for (const win::ScriptedKey& k : scripted)
            if (k.frame == n) on_key(p_.window, k.key, 0, GLFW_PRESS, k.mods);
        const bool last =
            glfwWindowShouldClose(p_.window) || (p_.options.frames > 0 && n >= p_.options.frames);
        int width = 0, height = 0;
        glfwGetFramebufferSize(p_.window, &width, &height);
        if (width == 0 || height == 0) {  // minimised
            if (!last) glfwWaitEvents();
            return !last;
        }
        draw(width, height);
        p_.imgui.begin_frame();
        if (p_.options.show_ui) panel();
        const std::vector<std::string> problems = shown_problems();
        win::draw_errors(problems);
        p_.imgui.end_frame();
        if (p_.input.screenshot) save_screenshot(width, height);
        if (last && !p_.options.screenshot.empty())
            write_png(p_.options.screenshot, read_window(width, height));
        glfwSwapBuffers(p_.window);
        return !last;
    }

private:
    // The session's input since the last frame, then the lab's frame as the
    // renderer draws it, copied into the window.
    void draw(int width, int height) {
        const double time =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
        if (p_.session.apply_input(Frame{width, height, time})) {
            printed_.clear();  // a failed retry prints its error again
            if (p_.session.problems().shader_errors.empty()) {
                std::printf("lab %s: shaders reloaded\n", p_.lab.info.id.c_str());
                std::fflush(stdout);
            }
        }
        try {
            p_.renderer.draw(p_.session.params(), width, height, time);
            p_.session.drawn("");
        } catch (const std::exception& e) {
            p_.session.drawn(e.what());
        }
        present_frame(p_.renderer.framebuffer(), width, height);
    }

    // The panel edits a copy, which the session takes if the lab accepts it.
    void panel() {
        ParamValues edited = p_.session.params();
        if (!win::draw_panel(p_.lab, edited, p_.gl_renderer, p_.software_notice)) return;
        try {
            p_.session.replace(edited);
            p_.input.refused.clear();
        } catch (const Error& e) {
            p_.input.refused = e.what();
        }
    }

    // The session's problems and what the window refused; printed once.
    std::vector<std::string> shown_problems() {
        std::vector<std::string> problems = p_.session.problems().lines();
        if (!p_.input.refused.empty()) problems.push_back(p_.input.refused);
        print_new(problems, printed_);
        return problems;
    }

    // F12: screenshot-<lab>-NNN.png; a failure is shown in the window.
    void save_screenshot(int width, int height) {
        p_.input.screenshot = false;
        const std::string path = next_screenshot_path(p_.lab.info.id);
        try {
            write_png(path, read_window(width, height));
            std::printf("%s\n", path.c_str());
            std::fflush(stdout);
            p_.input.refused.clear();
        } catch (const Error& e) {
            p_.input.refused = std::string("Screenshot failed: ") + e.what();
        }
    }

    WindowParts p_;
    const std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
    std::vector<std::string> printed_;
};

}  // namespace

void run_window(const RegisteredLab& lab, ParamValues params, const WindowOptions& options) {
    const std::string& id = lab.info.id;
    const char* script = std::getenv("LAB_RUN_SCRIPT");
    const std::vector<win::ScriptedKey> scripted = win::parse_key_script(script ? script : "");
    win::GlfwLibrary glfw(id);
    win::GlfwWindow window(glfw, id, window_title(lab.info), options.width, options.height);
    const std::string& notice = window.software_notice();
    if (!notice.empty()) {
        std::fprintf(stderr, "lab: %s\n", notice.c_str());
        std::fflush(stderr);
    }
    ContextInfo context{"glfw", "glx", "", "", ""};
    load_gl_and_check(glfwGetProcAddress, context);
    keep_gl_drivers_loaded();

    InputState input;
    install_callbacks(window.get(), input);
    win::ImGuiLayer imgui(window.get());

    // The lab's GL objects must die while the context lives: declared after it.
    LabRenderer renderer(lab, context);
    LabSession session(renderer, std::move(params));
    input.session = &session;

    WindowLoop loop(
        {lab, renderer, session, options, window.get(), input, imgui, context.gl_renderer, notice});
    for (int frame = 1; loop.frame(frame, scripted);) ++frame;
}

}  // namespace fw
