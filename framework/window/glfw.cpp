#include "framework/window/glfw.hpp"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <dlfcn.h>
#include <imgui.h>
#include <link.h>
#include <unistd.h>

#include <cctype>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <optional>
#include <thread>
#include <vector>

#include "framework/error.hpp"

namespace fw::win {

namespace {

// GLFW reports why a call failed only through this callback.
std::string g_glfw_error;
int g_glfw_code = 0;

void remember_glfw_error(int code, const char* description) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "0x%x", static_cast<unsigned>(code));
    g_glfw_code = code;
    g_glfw_error =
        std::string(description ? description : "no description") + " (GLFW error " + buf + ")";
}

void forget_glfw_error() {
    g_glfw_code = 0;
    g_glfw_error.clear();
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
        " ...' (apt-get install xvfb xauth), draw offscreen without a window with 'lab render " +
        lab_id + " -o out.png', or use the lab in a browser with 'lab serve " + lab_id +
        "', then open the URL it prints");
}

// `what` says what the drivers offered instead of GL 4.3 core.
[[noreturn]] void no_gl43(const std::string& what, const std::string& lab_id) {
    throw EnvironmentError("lab run needs OpenGL 4.3 core, but " + what +
                           ". Use the lab in a browser instead, rendered offscreen: 'lab serve " +
                           lab_id +
                           "', then open the URL it prints; or draw one frame with 'lab "
                           "render " +
                           lab_id + " -o out.png'");
}

struct GlVersion {
    int major = 0, minor = 0;
    bool core = false;
};

GlVersion version_of(GLFWwindow* window) {
    // GLFW reads these from the context itself (GL_VERSION, the profile
    // mask), so they are what the driver handed back, not what was asked for.
    return {glfwGetWindowAttrib(window, GLFW_CONTEXT_VERSION_MAJOR),
            glfwGetWindowAttrib(window, GLFW_CONTEXT_VERSION_MINOR),
            glfwGetWindowAttrib(window, GLFW_OPENGL_PROFILE) == GLFW_OPENGL_CORE_PROFILE};
}

bool at_least_43(const GlVersion& v) { return v.major > 4 || (v.major == 4 && v.minor >= 3); }

// "offers only OpenGL 4.1": what a driver gave instead of GL 4.3 core.
std::string shortfall(const GlVersion& v) {
    const std::string version = "OpenGL " + std::to_string(v.major) + "." + std::to_string(v.minor);
    return at_least_43(v) ? "offers " + version + " but not its core profile"
                          : "offers only " + version;
}

// The newest context the driver offers, asked for after it refused 4.3 core:
// a core request for 3.2 gets the newest core version there is (forward-
// compatible, as macOS requires), a plain request the newest other one.
std::optional<GlVersion> offered_version() {
    for (const bool core : {true, false}) {
        glfwDefaultWindowHints();
        glfwWindowHint(GLFW_VISIBLE, GLFW_FALSE);
        if (core) {
            glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
            glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 2);
            glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
            glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
        }
        GLFWwindow* probe = glfwCreateWindow(16, 16, "GL version probe", nullptr, nullptr);
        if (!probe) continue;
        const GlVersion v = version_of(probe);
        glfwDestroyWindow(probe);
        return v;
    }
    return std::nullopt;
}

// One try at the lab's window: the window when its context is GL 4.3 core,
// else null and, in `why`, what the driver did instead ("offers only OpenGL
// 4.1", "could not create ...").
GLFWwindow* try_window(const std::string& title, int width, int height, std::string& why) {
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
    forget_glfw_error();
    if (GLFWwindow* window = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr)) {
        // A driver may hand back less than was asked for instead of failing.
        const GlVersion v = version_of(window);
        if (v.core && at_least_43(v)) return window;
        glfwDestroyWindow(window);
        why = shortfall(v);
        return nullptr;
    }
    // GLFW_VERSION_UNAVAILABLE: the driver refused the version or profile;
    // ask it what it has, so that the student learns the version.
    const std::string error = g_glfw_error.empty() ? "GLFW gave no reason" : g_glfw_error;
    const bool refused = g_glfw_code == GLFW_VERSION_UNAVAILABLE;
    if (refused)
        if (std::optional<GlVersion> v = offered_version()) {
            why = shortfall(*v);
            return nullptr;
        }
    why = "could not create a GL 4.3 core context: " + error;
    return nullptr;
}

// Whether Mesa already renders in software: it takes 1, y, yes and true, in
// any case, as on.
bool software_forced() {
    const char* value = std::getenv("LIBGL_ALWAYS_SOFTWARE");
    if (!value) return false;
    std::string v = value;
    for (char& c : v) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return v == "1" || v == "y" || v == "yes" || v == "true";
}

// Sets the environment that makes the next GL driver load Mesa's llvmpipe,
// which offers GL 4.5 core on any machine. Returns a note for the user when
// it cleared their MESA_GL_VERSION_OVERRIDE, else "".
std::string use_software_renderer() {
    setenv("LIBGL_ALWAYS_SOFTWARE", "1", 1);
    setenv("GALLIUM_DRIVER", "llvmpipe", 1);
    // MESA_GL_VERSION_OVERRIDE makes every Mesa driver, llvmpipe included,
    // report the version it names: left set, a 4.1 in it would refuse the
    // software context just as it refused the first one. llvmpipe's own
    // version (4.5 core) is what the labs need, so clearing the override can
    // only help here, for a user who set it as much as for a test that sets it
    // to imitate an old driver. The first try keeps it, so such a test goes
    // the way a real old driver sends `lab run`; a variable for tests alone
    // would leave that way untested. The notice names the cleared value.
    const char* override_value = std::getenv("MESA_GL_VERSION_OVERRIDE");
    if (!override_value) return "";
    const std::string note = " ($MESA_GL_VERSION_OVERRIDE was '" + std::string(override_value) +
                             "'; cleared for the software renderer)";
    unsetenv("MESA_GL_VERSION_OVERRIDE");
    return note;
}

// Set in the environment of `lab run` started again on the software
// renderer: what the GPU driver offered, for the notice and the errors.
constexpr const char* kGpuShortfall = "LAB_RUN_GPU_SHORTFALL";

// Starts this very command again, from the start, in a fresh process: the
// drivers then load once, reading the environment set for the software
// renderer, and nothing of the refused driver stays loaded (an unloaded
// driver's caches cannot be freed or even named any more). Returns only when
// that cannot be done.
void exec_self() {
    std::ifstream in("/proc/self/cmdline", std::ios::binary);
    const std::string cmdline{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    if (cmdline.empty()) return;
    std::vector<char*> argv;
    for (size_t i = 0; i < cmdline.size(); i = cmdline.find('\0', i) + 1)
        argv.push_back(const_cast<char*>(cmdline.c_str() + i));
    argv.push_back(nullptr);
    std::fflush(nullptr);
    execv("/proc/self/exe", argv.data());
}

// GLFW started again: an X server with no other client (Xvfb, as xvfb-run
// starts it) resets when the last connection closes, and refuses connections
// until it has: try for up to two seconds.
bool init_glfw_patiently() {
    for (int attempt = 0; attempt < 40; ++attempt) {
        if (glfwInit()) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    return false;
}

// Keeps every loaded library mapped from now on. glfwTerminate unloads the
// GL driver; a leak checker at exit then cannot name a driver's leftovers
// (it reports "<unknown module>"), so they cannot be told from ours.
void keep_libraries_loaded() {
    std::vector<std::string> names;
    dl_iterate_phdr(
        [](dl_phdr_info* info, size_t, void* out) {
            if (info->dlpi_name && *info->dlpi_name)
                static_cast<std::vector<std::string>*>(out)->push_back(info->dlpi_name);
            return 0;
        },
        &names);
    for (const std::string& name : names)
        dlopen(name.c_str(), RTLD_LAZY | RTLD_NOLOAD | RTLD_NODELETE);
}

}  // namespace

GlfwLibrary::GlfwLibrary(const std::string& lab_id) : lab_id_(lab_id) {
    glfwSetErrorCallback(remember_glfw_error);
    const bool again = std::getenv(kGpuShortfall) != nullptr;
    if (!(again ? init_glfw_patiently() : glfwInit()))
        no_window("GLFW could not initialise", lab_id);
}

GlfwLibrary::~GlfwLibrary() {
    keep_libraries_loaded();  // the process is ending
    glfwTerminate();
}

void GlfwLibrary::terminate() { glfwTerminate(); }

void GlfwLibrary::restart() {
    glfwTerminate();
    if (!init_glfw_patiently()) no_window("GLFW could not initialise again", lab_id_);
}

GlfwWindow::GlfwWindow(GlfwLibrary& glfw, const std::string& lab_id, const std::string& title,
                       int width, int height) {
    std::string gpu_why;
    if (const char* handed = std::getenv(kGpuShortfall)) {
        // Started again on the software renderer: this is its try.
        gpu_why = handed;
        unsetenv(kGpuShortfall);
    } else {
        window_ = try_window(title, width, height, gpu_why);
        if (!window_) {
            if (software_forced())
                no_gl43("the driver " + gpu_why + " (" + variable_state("LIBGL_ALWAYS_SOFTWARE") +
                            ": that is already Mesa's software renderer)",
                        lab_id);
            gpu_why += use_software_renderer();
            setenv(kGpuShortfall, gpu_why.c_str(), 1);
            glfw.terminate();
            exec_self();
            // No /proc: the drivers load again in this process instead.
            unsetenv(kGpuShortfall);
            glfw.restart();
        }
    }
    if (!window_) {
        std::string software_why;
        window_ = try_window(title, width, height, software_why);
        if (!window_)
            no_gl43("the GPU driver " + gpu_why + ", and Mesa's software renderer (llvmpipe) " +
                        software_why,
                    lab_id);
        software_notice_ = "Software rendering (llvmpipe): the GPU driver " + gpu_why +
                           ", and lab run needs OpenGL 4.3 core";
    }
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
