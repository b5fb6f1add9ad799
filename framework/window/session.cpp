#include "framework/window/session.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <cstdio>
#include <cstdlib>

#include "framework/error.hpp"

namespace fw::win {

namespace {

// GLFW reports why a call failed only through this callback.
std::string g_glfw_error;

void remember_glfw_error(int code, const char* description) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "0x%x", static_cast<unsigned>(code));
    g_glfw_error =
        std::string(description ? description : "no description") + " (GLFW error " + buf + ")";
}

std::string variable_state(const char* name) {
    const char* value = std::getenv(name);
    if (!value) return "$" + std::string(name) + " is not set";
    if (!*value) return "$" + std::string(name) + " is empty";
    return "$" + std::string(name) + " is '" + value + "'";
}

[[noreturn]] void no_window(const std::string& what, const std::string& lab_id) {
    throw EnvironmentError(
        "lab run needs a display, but " + what + ": " +
        (g_glfw_error.empty() ? "GLFW gave no reason" : g_glfw_error) + ". " +
        variable_state("DISPLAY") + ", " + variable_state("WAYLAND_DISPLAY") +
        ". Run it on a virtual display with 'xvfb-run -a lab run " + lab_id +
        " ...' (apt-get install xvfb xauth), or draw offscreen without a window with 'lab render " +
        lab_id + " -o out.png'");
}

}  // namespace

GlfwLibrary::GlfwLibrary(const std::string& lab_id) {
    glfwSetErrorCallback(remember_glfw_error);
    if (!glfwInit()) no_window("GLFW could not initialise", lab_id);
}

GlfwLibrary::~GlfwLibrary() { glfwTerminate(); }

GlfwWindow::GlfwWindow(const std::string& lab_id, const std::string& title, int width, int height) {
    glfwDefaultWindowHints();
    // docs/labs.md, What every lab shares: GL 4.3 core, not forward-compatible,
    // no MSAA, no sRGB; the same context the offscreen backends create.
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
    glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
    glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_FALSE);
    glfwWindowHint(GLFW_SAMPLES, 0);
    glfwWindowHint(GLFW_SRGB_CAPABLE, GLFW_FALSE);
    glfwWindowHint(GLFW_RESIZABLE, GLFW_TRUE);
    window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!window_) no_window("GLFW could not create a window with a GL 4.3 core context", lab_id);
    glfwMakeContextCurrent(window_);
    glfwSwapInterval(1);
}

GlfwWindow::~GlfwWindow() { glfwDestroyWindow(window_); }

ImGuiLayer::ImGuiLayer(GLFWwindow* window) {
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    // No imgui.ini written into whatever directory the student ran `lab` in.
    ImGui::GetIO().IniFilename = nullptr;
    ImGui::StyleColorsDark();
    glfw_backend_ = ImGui_ImplGlfw_InitForOpenGL(window, true);
    gl_backend_ = glfw_backend_ && ImGui_ImplOpenGL3_Init("#version 430");
    if (!gl_backend_) {
        shutdown();
        throw Error("Dear ImGui could not initialise its GLFW or OpenGL 3 backend");
    }
}

ImGuiLayer::~ImGuiLayer() { shutdown(); }

void ImGuiLayer::shutdown() {
    if (gl_backend_) ImGui_ImplOpenGL3_Shutdown();
    if (glfw_backend_) ImGui_ImplGlfw_Shutdown();
    gl_backend_ = glfw_backend_ = false;
    if (ImGui::GetCurrentContext()) ImGui::DestroyContext();
}

void ImGuiLayer::begin_frame() {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
}

void ImGuiLayer::end_frame() {
    ImGui::Render();
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

}  // namespace fw::win
