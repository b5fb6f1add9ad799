// The main() of every test executable. For GL tests it creates the offscreen
// context named by LAB_BACKEND first; if this machine lacks that backend the
// test reports SKIP with the reason and exits 77, which CTest shows as
// skipped, unless LAB_REQUIRE_BACKENDS asks for it (CI), when it fails.
#define DOCTEST_CONFIG_IMPLEMENT
#include <doctest/doctest.h>

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include "framework/context.hpp"
#include "framework/error.hpp"
#include "test_support.hpp"

#ifndef LAB_TEST_NEEDS_GL
#define LAB_TEST_NEEDS_GL 0
#endif

namespace {
std::unique_ptr<fw::OffscreenContext> g_context;
}  // namespace

const fw::ContextInfo& fw::test::context_info() {
    if (!g_context) {
        std::fprintf(stderr,
                     "test error: context_info() in a test without a GL context; "
                     "declare it with lab_gl_test in tests/CMakeLists.txt\n");
        std::abort();
    }
    return g_context->info();
}

int main(int argc, char** argv) {
    if (LAB_TEST_NEEDS_GL) {
        const char* env = std::getenv("LAB_BACKEND");
        std::string name = env ? env : "auto";
        try {
            g_context = fw::create_offscreen_context(fw::parse_backend(name));
            std::printf("backend %s (%s): %s, %s\n", g_context->info().backend.c_str(),
                        g_context->info().platform.c_str(), g_context->info().gl_version.c_str(),
                        g_context->info().gl_renderer.c_str());
        } catch (const fw::EnvironmentError& e) {
            if (fw::test::backend_required(name)) {
                std::printf("FAIL: backend %s is required (LAB_REQUIRE_BACKENDS) but: %s\n",
                            name.c_str(), e.what());
                return 1;
            }
            std::printf("SKIP: backend %s unavailable: %s\n", name.c_str(), e.what());
            return 77;
        }
    }
    doctest::Context ctx;
    ctx.applyCommandLine(argc, argv);
    int rc = ctx.run();
    g_context.reset();
    fw::test::remove_marked(rc == 0);
    return rc;
}
