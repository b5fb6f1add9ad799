// `lab run`: each frame the lab draws into a framework framebuffer exactly as
// `lab render` does, the framebuffer is copied (glBlitFramebuffer) into the
// window, and the ImGui panel is drawn on top.
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
#include <memory>
#include <string>
#include <vector>

#include "framework/context.hpp"
#include "framework/error.hpp"
#include "framework/gl/debug.hpp"
#include "framework/gl/framebuffer.hpp"
#include "framework/image.hpp"
#include "framework/window/keys.hpp"
#include "framework/window/panel.hpp"
#include "framework/window/session.hpp"

namespace fw {

namespace {

// What the GLFW callbacks (called inside glfwPollEvents) share with the loop.
struct InputState {
    Lab* lab = nullptr;
    ParamValues* params = nullptr;
    bool reload = false, screenshot = false;
    bool dragging = false;
    double last_x = 0.0, last_y = 0.0;
    std::string error;  // an exception from a lab hook; C callbacks must not throw
};

InputState& input_of(GLFWwindow* window) {
    return *static_cast<InputState*>(glfwGetWindowUserPointer(window));
}

template <class F>
void guarded(InputState& in, F&& hook) {
    try {
        hook();
        in.error.clear();
    } catch (const std::exception& e) {
        in.error = std::string("error in the lab's mouse handler: ") + e.what();
    }
}

void on_key(GLFWwindow* window, int key, int /*scancode*/, int action, int mods) {
    InputState& in = input_of(window);
    // While the user types into an ImGui field, keys belong to the field.
    if (action == GLFW_RELEASE || ImGui::GetIO().WantCaptureKeyboard) return;
    if (mods & (GLFW_MOD_CONTROL | GLFW_MOD_ALT | GLFW_MOD_SUPER)) return;
    bool press = action == GLFW_PRESS;
    if (key == GLFW_KEY_ESCAPE && press)
        glfwSetWindowShouldClose(window, GLFW_TRUE);
    else if (key == GLFW_KEY_F12 && press)
        in.screenshot = true;
    else if (key == GLFW_KEY_R && press)
        in.reload = true;
    else
        win::apply_param_key(*in.params, key, (mods & GLFW_MOD_SHIFT) != 0, !press);
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

// The frame the window draws now: its framebuffer's size, and the time.
Frame frame_of(GLFWwindow* window) {
    Frame frame;
    glfwGetFramebufferSize(window, &frame.width, &frame.height);
    frame.time = glfwGetTime();
    return frame;
}

void on_cursor(GLFWwindow* window, double x, double y) {
    InputState& in = input_of(window);
    if (!in.dragging) return;
    // GLFW's y grows downwards; the lab gets GL's convention, up positive.
    double dx = x - in.last_x, dy = in.last_y - y;
    in.last_x = x;
    in.last_y = y;
    guarded(in, [&] { in.lab->on_drag(*in.params, frame_of(window), dx, dy); });
}

void on_scroll(GLFWwindow* window, double /*x*/, double y) {
    InputState& in = input_of(window);
    if (ImGui::GetIO().WantCaptureMouse) return;
    guarded(in, [&] { in.lab->on_scroll(*in.params, frame_of(window), y); });
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

// The lab's frame, drawn into `fb` the way LabRenderer::render draws it
// offscreen, then copied into the window. Returns what went wrong, if anything.
std::vector<std::string> draw_lab(Lab& lab, const std::string& id, const ParamValues& params,
                                  const Framebuffer& fb, double time) {
    std::vector<std::string> problems;
    fb.bind();  // also sets the viewport to the framebuffer's size
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClearDepth(1.0);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    std::string rejected = lab.validate(params);
    if (!rejected.empty()) {
        problems.push_back("Nothing drawn: lab '" + id + "' rejects these parameters: " + rejected);
    } else {
        try {
            lab.draw(params, Frame{fb.width(), fb.height(), time});
            check_gl("draw of lab " + id);
        } catch (const std::exception& e) {
            problems.push_back(std::string("Drawing failed: ") + e.what());
        }
    }
    glBindFramebuffer(GL_READ_FRAMEBUFFER, fb.id());
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    glBlitFramebuffer(0, 0, fb.width(), fb.height(), 0, 0, fb.width(), fb.height(),
                      GL_COLOR_BUFFER_BIT, GL_NEAREST);
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    return problems;
}

// R: recompiles every program from disk; the messages of those that failed.
std::vector<std::string> reload_shaders(ProgramLibrary& programs, const std::string& id) {
    std::vector<std::string> errors;
    for (const std::string& e : programs.reload_all())
        errors.push_back(
            "Shader reload failed; the last good program keeps drawing. "
            "Fix the file and press R.\n" +
            e);
    if (errors.empty()) {
        std::printf("lab %s: shaders reloaded\n", id.c_str());
        std::fflush(stdout);
    }
    return errors;
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

// The frames of one window and what they share: the lab and its parameters,
// the framebuffer it draws into, and the problems shown in the panel.
class WindowLoop {
public:
    WindowLoop(const RegisteredLab& lab, Lab& instance, ParamValues& params,
               const WindowOptions& options, GLFWwindow* window, InputState& input,
               const std::string& software_notice)
        : lab_(lab),
          instance_(instance),
          params_(params),
          options_(options),
          window_(window),
          input_(input),
          software_notice_(software_notice) {}

    // Frame `n` (from 1); false once it was the last.
    bool frame(int n, const std::vector<win::ScriptedKey>& scripted, ProgramLibrary& programs,
               win::ImGuiLayer& imgui, const ContextInfo& context) {
        glfwPollEvents();
        for (const win::ScriptedKey& k : scripted)
            if (k.frame == n) on_key(window_, k.key, 0, GLFW_PRESS, k.mods);
        const bool last =
            glfwWindowShouldClose(window_) || (options_.frames > 0 && n >= options_.frames);
        int width = 0, height = 0;
        glfwGetFramebufferSize(window_, &width, &height);
        if (width == 0 || height == 0) {  // minimised
            if (!last) glfwWaitEvents();
            return !last;
        }
        if (input_.reload) {
            input_.reload = false;
            printed_.clear();  // a failed retry prints its error again
            reload_errors_ = reload_shaders(programs, lab_.info.id);
        }
        resize(width, height);
        const std::vector<std::string> problems = draw();
        imgui.begin_frame();
        if (options_.show_ui) win::draw_panel(lab_, params_, context.gl_renderer, software_notice_);
        win::draw_errors(problems);
        imgui.end_frame();
        if (input_.screenshot) save_screenshot(width, height);
        if (last && !options_.screenshot.empty())
            write_png(options_.screenshot, read_window(width, height));
        glfwSwapBuffers(window_);
        return !last;
    }

private:
    // A framebuffer of the window's size, made again when the size changes.
    void resize(int width, int height) {
        if (framebuffer_ && framebuffer_->width() == width && framebuffer_->height() == height)
            return;
        framebuffer_.reset();
        framebuffer_ = std::make_unique<Framebuffer>(FramebufferDesc{
            width, height, "window " + std::to_string(width) + "x" + std::to_string(height)});
    }

    // Draws the lab's frame into the window; what went wrong, printed once.
    std::vector<std::string> draw() {
        const double time =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
        std::vector<std::string> problems = reload_errors_;
        for (std::string& p : draw_lab(instance_, lab_.info.id, params_, *framebuffer_, time))
            problems.push_back(std::move(p));
        if (!input_.error.empty()) problems.push_back(input_.error);
        print_new(problems, printed_);
        return problems;
    }

    // F12: screenshot-<lab>-NNN.png; a failure is shown in the window.
    void save_screenshot(int width, int height) {
        input_.screenshot = false;
        const std::string path = next_screenshot_path(lab_.info.id);
        try {
            write_png(path, read_window(width, height));
            std::printf("%s\n", path.c_str());
            std::fflush(stdout);
            input_.error.clear();
        } catch (const Error& e) {
            input_.error = std::string("Screenshot failed: ") + e.what();
        }
    }

    const RegisteredLab& lab_;
    Lab& instance_;
    ParamValues& params_;
    const WindowOptions& options_;
    GLFWwindow* window_;
    InputState& input_;
    const std::string& software_notice_;  // shown in the panel when not empty
    const std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
    std::unique_ptr<Framebuffer> framebuffer_;
    std::vector<std::string> reload_errors_;  // stay until a reload succeeds
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
    enable_debug_output();

    InputState input;
    install_callbacks(window.get(), input);
    win::ImGuiLayer imgui(window.get());

    // The lab's GL objects must die while the context lives: declared after it.
    ProgramLibrary programs(lab.info.dir);
    std::unique_ptr<Lab> instance = lab.create();
    instance->init(programs);
    check_gl("init of lab " + id);
    input.lab = instance.get();
    input.params = &params;

    WindowLoop loop(lab, *instance, params, options, window.get(), input, notice);
    for (int frame = 1; loop.frame(frame, scripted, programs, imgui, context);) ++frame;
}

}  // namespace fw
