// The OSMesa backend: Mesa's off-screen rendering library, GL 4.3 core on
// llvmpipe. Compiled only when CMake found libosmesa6-dev (LAB_HAVE_OSMESA);
// Mesa 25.1 dropped OSMesa, so EGL is the long-term path.
//
// <GL/osmesa.h> pulls in the system <GL/gl.h>, so this file must not include
// glad; GL is loaded in context.cpp through load_gl_and_check.
#include <GL/osmesa.h>

#include <array>
#include <cstdint>
#include <memory>
#include <string>

#include "framework/backends/backends.hpp"
#include "framework/error.hpp"

namespace fw::backends {

namespace {

GLProc osmesa_loader(const char* name) {
    return reinterpret_cast<GLProc>(OSMesaGetProcAddress(name));
}

class OSMesaOffscreenContext final : public OffscreenContext {
public:
    OSMesaOffscreenContext() {
        info_.backend = "osmesa";
        info_.platform = "osmesa";
    }

    ~OSMesaOffscreenContext() override {
        if (context_) {
            // A NULL context and buffer release the current context.
            OSMesaMakeCurrent(nullptr, nullptr, 0, 0, 0);
            OSMesaDestroyContext(context_);
        }
    }

    void set_up() {
        // Core profile, no forward-compatible flag: OSMesa refuses it (docs/labs.md).
        // clang-format off
        const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA,
                               OSMESA_DEPTH_BITS, 24,
                               OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                               OSMESA_CONTEXT_MAJOR_VERSION, 4,
                               OSMESA_CONTEXT_MINOR_VERSION, 3,
                               0};
        // clang-format on
        context_ = OSMesaCreateContextAttribs(attribs, nullptr);
        if (!context_) {
            throw EnvironmentError(
                std::string(
                    "OSMesaCreateContextAttribs(RGBA, core profile 4.3) returned NULL: this "
                    "libOSMesa cannot make a GL 4.3 core context (Mesa >= 20 with llvmpipe can; "
                    "the classic swrast OSMesa cannot); try LIBGL_ALWAYS_SOFTWARE=1 or use "
                    "--backend egl") +
                mesa_override_note());
        }
        // OSMesaMakeCurrent needs a colour buffer. The framework renders into
        // its own framebuffer objects, so this one is small and never read.
        if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, kSize, kSize)) {
            throw EnvironmentError(
                "OSMesaMakeCurrent(16x16 RGBA8 buffer) failed; use --backend egl");
        }
        load_gl_and_check(osmesa_loader, info_);
    }

private:
    static constexpr int kSize = 16;
    OSMesaContext context_ = nullptr;
    std::array<std::uint8_t, kSize * kSize * 4> buffer_{};
};

}  // namespace

std::unique_ptr<OffscreenContext> create_osmesa_context() {
    // Made first and filled in second, so a failure half-way destroys what
    // was created.
    auto context = std::make_unique<OSMesaOffscreenContext>();
    context->set_up();
    return context;
}

}  // namespace fw::backends
