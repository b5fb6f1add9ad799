// Backend names, the choice between backends, and the GL 4.3 core check that
// every context (offscreen or windowed) passes before a lab may draw.
#include "framework/context.hpp"

#include <dlfcn.h>
#include <glad/gl.h>
#include <link.h>

#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "framework/backends/backends.hpp"
#include "framework/error.hpp"
#include "framework/gl/vertex_array.hpp"
#include "framework/trace/calls.hpp"

namespace fw {

namespace {

constexpr const char* kBackendVariable = "LAB_BACKEND";
#ifdef LAB_HAVE_OSMESA
constexpr const char* kValidBackends = "auto, osmesa, egl";
#else
constexpr const char* kValidBackends = "auto, egl (this build has no osmesa)";
#endif

std::string gl_string(GLenum name) {
    const GLubyte* s = glGetString(name);
    return s ? reinterpret_cast<const char*>(s) : "(null)";
}

}  // namespace

std::string backends::mesa_override_note() {
    std::string note;
    for (const char* name : {"MESA_GL_VERSION_OVERRIDE", "MESA_GLSL_VERSION_OVERRIDE"}) {
        if (const char* value = std::getenv(name)) {
            note += std::string("; ") + name + "=" + value + " is set, unset it";
        }
    }
    return note;
}

Backend parse_backend(const std::string& name) {
    if (name == "auto") return Backend::Auto;
    if (name == "osmesa") return Backend::OSMesa;
    if (name == "egl") return Backend::EGL;
    throw UsageError("unknown backend '" + name + "'; valid backends: " + kValidBackends);
}

const char* backend_name(Backend b) {
    switch (b) {
        case Backend::Auto:
            return "auto";
        case Backend::OSMesa:
            return "osmesa";
        case Backend::EGL:
            return "egl";
    }
    return "?";
}

Backend backend_from_env() {
    const char* value = std::getenv(kBackendVariable);
    if (!value || !*value) return Backend::Auto;
    try {
        return parse_backend(value);
    } catch (const UsageError& e) {
        throw UsageError(std::string("environment variable ") + kBackendVariable + ": " + e.what() +
                         " (unset it to let the framework choose)");
    }
}

bool backend_compiled_in(Backend b, std::string* why_not) {
    if (b != Backend::OSMesa) return true;  // Auto and EGL: libEGL is a required dependency
#ifdef LAB_HAVE_OSMESA
    (void)why_not;
    return true;
#else
    if (why_not)
        *why_not =
            std::string("this build has no OSMesa (") + LAB_OSMESA_ABSENT + "); use --backend egl";
    return false;
#endif
}

namespace {

std::unique_ptr<OffscreenContext> create_osmesa() {
    std::string why;
    if (!backend_compiled_in(Backend::OSMesa, &why)) throw EnvironmentError(why);
#ifdef LAB_HAVE_OSMESA
    return backends::create_osmesa_context();
#else
    return nullptr;  // unreachable: backend_compiled_in said no
#endif
}

}  // namespace

std::unique_ptr<OffscreenContext> create_offscreen_context(Backend backend) {
    switch (backend) {
        case Backend::EGL:
            return backends::create_egl_context();
        case Backend::OSMesa:
            return create_osmesa();
        case Backend::Auto:
            break;
    }
    // Auto: EGL is the long-term path; OSMesa is the fallback while Mesa ships it.
    std::string egl_reason;
    try {
        return backends::create_egl_context();
    } catch (const EnvironmentError& e) {
        egl_reason = e.what();
    }
    if (!backend_compiled_in(Backend::OSMesa)) {
        throw EnvironmentError(
            "no offscreen OpenGL 4.3 core context with --backend auto (tried egl; this build has "
            "no osmesa).\n  egl: " +
            egl_reason);
    }
    try {
        return create_osmesa();
    } catch (const EnvironmentError& e) {
        throw EnvironmentError(
            "no offscreen OpenGL 4.3 core context with --backend auto (tried egl, then osmesa).\n"
            "  egl: " +
            egl_reason + "\n  osmesa: " + e.what());
    }
}

void load_gl_and_check(GLLoader loader, ContextInfo& info) {
    // GLLoader and GLADloadfunc are the same type: GLProc (*)(const char*).
    const int version = gladLoadGL(loader);
    if (version == 0) {
        throw EnvironmentError(
            "could not load OpenGL through the " + info.backend +
            " backend: glGetString is missing or returned no GL_VERSION (is a context current?)");
    }
    gl_calls::install();
    detail::track_vertex_array_binding();
    info.gl_version = gl_string(GL_VERSION);
    info.gl_renderer = gl_string(GL_RENDERER);
    info.gl_vendor = gl_string(GL_VENDOR);

    const int major = GLAD_VERSION_MAJOR(version);
    const int minor = GLAD_VERSION_MINOR(version);
    // GL_CONTEXT_PROFILE_MASK exists from GL 3.2 on; older contexts have no
    // profiles and behave like the compatibility profile.
    std::string profile = "compatibility";
    bool core = false;
    if (major > 3 || (major == 3 && minor >= 2)) {
        GLint mask = 0;
        glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &mask);
        core = (mask & GL_CONTEXT_CORE_PROFILE_BIT) != 0;
        if (core) {
            profile = "core";
        } else if (!(mask & GL_CONTEXT_COMPATIBILITY_PROFILE_BIT)) {
            char buf[64];
            std::snprintf(buf, sizeof buf, "profile mask 0x%x", static_cast<unsigned>(mask));
            profile = buf;
        }
    }
    const bool new_enough = major > 4 || (major == 4 && minor >= 3);
    if (!new_enough || !core) {
        throw EnvironmentError("the " + info.backend + " backend gave OpenGL " + info.gl_version +
                               " (" + profile + ", renderer " + info.gl_renderer +
                               "); the labs need 4.3 core: Mesa >= 20 llvmpipe "
                               "provides it; try LIBGL_ALWAYS_SOFTWARE=1 or another --backend (" +
                               kValidBackends + ")" + backends::mesa_override_note());
    }
}

void keep_gl_drivers_loaded() {
    dl_iterate_phdr(
        [](dl_phdr_info* info, size_t, void*) {
            const char* name = info->dlpi_name;
            if (name && (std::strstr(name, "libEGL_") || std::strstr(name, "libGLX_") ||
                         std::strstr(name, "_dri.so") || std::strstr(name, "libgallium") ||
                         std::strstr(name, "libLLVM"))) {
                // Takes a reference that is never dropped; the handle is not needed.
                (void)dlopen(name, RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
            }
            return 0;
        },
        nullptr);
}

}  // namespace fw
