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
};

// A resizable window whose GL 4.3 core context (not forward-compatible,
// single-sampled, no sRGB) is made current.
class GlfwWindow {
public:
    GlfwWindow(const std::string& lab_id, const std::string& title, int width, int height);
    ~GlfwWindow();
    GlfwWindow(const GlfwWindow&) = delete;
    GlfwWindow& operator=(const GlfwWindow&) = delete;
    GLFWwindow* get() const { return window_; }

private:
    GLFWwindow* window_ = nullptr;
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
