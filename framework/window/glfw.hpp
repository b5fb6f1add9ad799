// The window system side of `lab run`, as RAII guards so that every exit
// path (Esc, --frames, an exception) releases ImGui, the window and GLFW in
// the right order: declare them in this order, they die in reverse.
#pragma once

#include <string>

struct GLFWwindow;

namespace fw::win {

// glfwInit / glfwTerminate. Throws EnvironmentError when there is no
// display, naming $DISPLAY / $WAYLAND_DISPLAY and what to run instead.
class GlfwLibrary {
public:
    explicit GlfwLibrary(const std::string& lab_id);
    ~GlfwLibrary();
    GlfwLibrary(const GlfwLibrary&) = delete;
    GlfwLibrary& operator=(const GlfwLibrary&) = delete;

    // glfwTerminate (GLFW may be terminated twice). No window may be open.
    void terminate();
    // glfwTerminate, then glfwInit again, so that the GL driver is loaded
    // afresh and reads the environment again. No window may be open.
    void restart();

private:
    std::string lab_id_;
};

// A resizable window whose GL 4.3 core context (not forward-compatible,
// single-sampled, no sRGB) is made current. When the driver cannot give that
// context (it fails, or hands back an older version or another profile), the
// window is made again on Mesa's software renderer, llvmpipe: the command
// starts again in the same process (execv of /proc/self/exe) with
// LIBGL_ALWAYS_SOFTWARE=1 and GALLIUM_DRIVER=llvmpipe set, so that only the
// software driver is ever loaded in it; without /proc, `glfw` is restarted.
// Throws EnvironmentError, naming the version the driver offers and the
// offscreen alternatives (`lab serve`, `lab render`), when that fails too or
// when software rendering was already forced.
class GlfwWindow {
public:
    GlfwWindow(GlfwLibrary& glfw, const std::string& lab_id, const std::string& title, int width,
               int height);
    ~GlfwWindow();
    GlfwWindow(const GlfwWindow&) = delete;
    GlfwWindow& operator=(const GlfwWindow&) = delete;
    GLFWwindow* get() const { return window_; }

    // Empty when the driver's own context is in use; otherwise one line that
    // says the window renders in software, and why.
    const std::string& software_notice() const { return software_notice_; }

private:
    GLFWwindow* window_ = nullptr;
    std::string software_notice_;
};

// Dear ImGui with its GLFW and OpenGL 3 backends. Create it after the
// window's own GLFW callbacks are installed: ImGui chains to them.
class ImGuiLayer {
public:
    explicit ImGuiLayer(GLFWwindow* window);
    ~ImGuiLayer();
    ImGuiLayer(const ImGuiLayer&) = delete;
    ImGuiLayer& operator=(const ImGuiLayer&) = delete;

    void begin_frame();
    void end_frame();  // renders into the bound (default) framebuffer

private:
    void shutdown();
    bool glfw_backend_ = false;
    bool gl_backend_ = false;
};

}  // namespace fw::win
