// GL 4.3 core contexts. Offscreen contexts (OSMesa, EGL) render into a
// framework-owned framebuffer object, never into a window system surface, so
// both backends run exactly the same GL code. The windowed context (GLFW)
// lives in the runner, not here.
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace fw {

enum class Backend { Auto, OSMesa, EGL };

// "auto", "osmesa", "egl" -> Backend; anything else throws UsageError listing them.
Backend parse_backend(const std::string& name);
const char* backend_name(Backend b);

// The backend to use when none is given: $LAB_BACKEND if set (validated),
// else Auto.
Backend backend_from_env();

// Whether this build can create the backend at all (OSMesa is optional at
// build time) and, if not, why. Does not create a context.
bool backend_compiled_in(Backend b, std::string* why_not = nullptr);

struct ContextInfo {
    std::string backend;      // "osmesa" or "egl"
    std::string platform;     // egl: "device" or "surfaceless"; osmesa: "osmesa"
    std::string gl_version;   // GL_VERSION
    std::string gl_renderer;  // GL_RENDERER
    std::string gl_vendor;    // GL_VENDOR
};

// A current GL 4.3 core context without a window. Creating one makes it
// current on the calling thread and loads GL entry points (glad). Destroying
// it releases the context. Only one exists at a time per process.
class OffscreenContext {
public:
    virtual ~OffscreenContext() = default;
    OffscreenContext(const OffscreenContext&) = delete;
    OffscreenContext& operator=(const OffscreenContext&) = delete;

    const ContextInfo& info() const { return info_; }

protected:
    OffscreenContext() = default;
    ContextInfo info_;
};

// Creates a context on `backend`. Auto tries EGL, then OSMesa. On failure
// throws EnvironmentError naming the missing library or variable and which
// backend would work instead. Also throws if the context is not 4.3 core.
std::unique_ptr<OffscreenContext> create_offscreen_context(Backend backend);

// After any context (offscreen or GLFW) is current: loads GL with `loader`,
// checks GL_VERSION >= 4.3 and the core profile bit, throws EnvironmentError
// otherwise, and fills gl_version/gl_renderer/gl_vendor of `info`.
using GLProc = void (*)();
using GLLoader = GLProc (*)(const char* name);
void load_gl_and_check(GLLoader loader, ContextInfo& info);

// Keeps the GL driver libraries that are loaded now (the vendor's EGL or GLX
// library, Mesa's *_dri.so, LLVM) loaded until the process exits, instead of
// being unloaded when the context is destroyed. A second context skips the
// reload, and a leak checker can still name the driver behind an allocation
// the driver never frees (Mesa's own leaks are suppressed by name in
// scripts/lsan.supp; ours are not). Call it once a context is current.
void keep_gl_drivers_loaded();

}  // namespace fw
