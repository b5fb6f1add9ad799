// Private to the framework: one factory per offscreen backend. context.cpp
// picks among them; each returns a current GL 4.3 core context with GL loaded,
// or throws EnvironmentError saying what is missing and what would work.
#pragma once

#include <memory>
#include <string>

#include "framework/context.hpp"

namespace fw::backends {

// "; MESA_GL_VERSION_OVERRIDE=3.3 is set, unset it" when a Mesa variable that
// caps the GL version is set, else "". Appended to version failures.
std::string mesa_override_note();

// egl.cpp: the EGL device platform on a real GPU, else Mesa's surfaceless
// platform. Always compiled in (libEGL is a required build dependency).
std::unique_ptr<OffscreenContext> create_egl_context();

#ifdef LAB_HAVE_OSMESA
// osmesa.cpp: OSMesaCreateContextAttribs, core 4.3. Compiled only when CMake
// found libosmesa6-dev.
std::unique_ptr<OffscreenContext> create_osmesa_context();
#endif

}  // namespace fw::backends
