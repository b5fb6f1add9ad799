// Offscreen contexts: the context main() made for LAB_BACKEND is GL 4.3 core
// and draws; backend names parse, and bad ones say what the valid ones are.
#include <glad/gl.h>

#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>

#include "framework/context.hpp"
#include "framework/error.hpp"
#include "tests/support/test_support.hpp"

namespace {

// Sets or unsets an environment variable for one scope, then restores it.
class ScopedEnv {
public:
    ScopedEnv(const char* name, const char* value) : name_(name) {
        if (const char* old = std::getenv(name)) old_ = old;
        if (value) {
            setenv(name, value, 1);
        } else {
            unsetenv(name);
        }
    }
    ~ScopedEnv() {
        if (old_) {
            setenv(name_, old_->c_str(), 1);
        } else {
            unsetenv(name_);
        }
    }
    ScopedEnv(const ScopedEnv&) = delete;
    ScopedEnv& operator=(const ScopedEnv&) = delete;

private:
    const char* name_;
    std::optional<std::string> old_;
};

bool contains(const std::string& haystack, const std::string& needle) {
    return haystack.find(needle) != std::string::npos;
}

// A list of valid backends offers what this build has: osmesa only when it
// was built in, and otherwise says that it was not.
void check_offered_backends(const std::string& msg) {
    INFO("message: " << msg);
    if (fw::backend_compiled_in(fw::Backend::OSMesa)) {
        CHECK(contains(msg, "auto, osmesa, egl"));
    } else {
        CHECK(contains(msg, "auto, egl"));
        CHECK(contains(msg, "this build has no osmesa"));
        CHECK_FALSE(contains(msg, "osmesa,"));
    }
}

}  // namespace

TEST_CASE("the context is OpenGL 4.3 core or newer") {
    GLint major = 0, minor = 0, profile = 0, flags = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    glGetIntegerv(GL_CONTEXT_PROFILE_MASK, &profile);
    glGetIntegerv(GL_CONTEXT_FLAGS, &flags);
    INFO("expected >= 4.3 core; observed " << major << "." << minor << ", profile mask " << profile
                                           << ", flags " << flags);
    CHECK((major > 4 || (major == 4 && minor >= 3)));
    CHECK((profile & GL_CONTEXT_CORE_PROFILE_BIT) != 0);
    // docs/labs.md, What every lab shares: no forward-compatible flag (OSMesa refuses it).
    CHECK((flags & GL_CONTEXT_FLAG_FORWARD_COMPATIBLE_BIT) == 0);
    CHECK(glGetError() == GL_NO_ERROR);
}

TEST_CASE("context info names the backend LAB_BACKEND asked for") {
    const fw::ContextInfo& info = fw::test::context_info();
    MESSAGE("backend " << info.backend << ", platform " << info.platform << ", " << info.gl_version
                       << ", " << info.gl_renderer << ", " << info.gl_vendor);
    CHECK(!info.gl_version.empty());
    CHECK(!info.gl_renderer.empty());
    CHECK(!info.gl_vendor.empty());

    const char* env = std::getenv("LAB_BACKEND");
    const std::string asked = env && *env ? env : "auto";
    if (asked == "auto") {
        CHECK((info.backend == "egl" || info.backend == "osmesa"));
    } else {
        CHECK(info.backend == asked);
    }
    if (info.backend == "egl") {
        CHECK((info.platform == "device" || info.platform == "surfaceless"));
    } else {
        CHECK(info.platform == "osmesa");
    }
}

TEST_CASE("clearing an RGBA8 + depth framebuffer object reads back exactly") {
    constexpr int kSize = 8;
    GLuint fbo = 0, colour = 0, depth = 0;
    glGenRenderbuffers(1, &colour);
    glBindRenderbuffer(GL_RENDERBUFFER, colour);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, kSize, kSize);
    glGenRenderbuffers(1, &depth);
    glBindRenderbuffer(GL_RENDERBUFFER, depth);
    glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH_COMPONENT24, kSize, kSize);
    glBindRenderbuffer(GL_RENDERBUFFER, 0);
    glGenFramebuffers(1, &fbo);
    glBindFramebuffer(GL_FRAMEBUFFER, fbo);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour);
    glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_RENDERBUFFER, depth);
    REQUIRE(glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE);

    // k/255 converts to exactly k in a normalised 8-bit channel.
    glViewport(0, 0, kSize, kSize);
    glClearColor(51 / 255.0f, 102 / 255.0f, 153 / 255.0f, 1.0f);
    glClearDepth(0.25);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);

    unsigned char rgba[kSize * kSize * 4] = {};
    float depths[kSize * kSize] = {};
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, kSize, kSize, GL_RGBA, GL_UNSIGNED_BYTE, rgba);
    glReadPixels(0, 0, kSize, kSize, GL_DEPTH_COMPONENT, GL_FLOAT, depths);
    CHECK(glGetError() == GL_NO_ERROR);

    for (int probe : {0, kSize * kSize - 1}) {
        const unsigned char* p = rgba + probe * 4;
        INFO("pixel " << probe << ": expected (51, 102, 153, 255) observed (" << int(p[0]) << ", "
                      << int(p[1]) << ", " << int(p[2]) << ", " << int(p[3]) << "), depth expected "
                      << 0.25 << " observed " << depths[probe]);
        const bool ok = p[0] == 51 && p[1] == 102 && p[2] == 153 && p[3] == 255 &&
                        std::abs(depths[probe] - 0.25f) < 1e-6f;
        CHECK(ok);
    }

    // Leave the shared context as the next test expects it.
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
    glDeleteFramebuffers(1, &fbo);
    glDeleteRenderbuffers(1, &colour);
    glDeleteRenderbuffers(1, &depth);
    glClearColor(0, 0, 0, 0);
    glClearDepth(1.0);
    glPixelStorei(GL_PACK_ALIGNMENT, 4);
}

TEST_CASE("backend names parse and round-trip") {
    for (fw::Backend b : {fw::Backend::Auto, fw::Backend::OSMesa, fw::Backend::EGL}) {
        CHECK(fw::parse_backend(fw::backend_name(b)) == b);
    }
}

TEST_CASE("an unknown backend name lists the valid ones") {
    try {
        fw::parse_backend("vulkan");
        FAIL("parse_backend(\"vulkan\") did not throw");
    } catch (const fw::UsageError& e) {
        const std::string msg = e.what();
        INFO("message: " << msg);
        CHECK(contains(msg, "vulkan"));
        check_offered_backends(msg);
    }
    CHECK_THROWS_AS(fw::parse_backend(""), fw::UsageError);
    CHECK_THROWS_AS(fw::parse_backend("EGL"), fw::UsageError);
}

TEST_CASE("LAB_BACKEND is validated and names itself when wrong") {
    {
        ScopedEnv env("LAB_BACKEND", "bogus");
        try {
            fw::backend_from_env();
            FAIL("backend_from_env() accepted LAB_BACKEND=bogus");
        } catch (const fw::UsageError& e) {
            const std::string msg = e.what();
            INFO("message: " << msg);
            CHECK(contains(msg, "LAB_BACKEND"));
            CHECK(contains(msg, "bogus"));
            check_offered_backends(msg);
        }
    }
    {
        ScopedEnv env("LAB_BACKEND", "osmesa");
        CHECK(fw::backend_from_env() == fw::Backend::OSMesa);
    }
    {
        ScopedEnv env("LAB_BACKEND", nullptr);
        CHECK(fw::backend_from_env() == fw::Backend::Auto);
    }
}

TEST_CASE("backend_compiled_in matches the build") {
    std::string why;
    CHECK(fw::backend_compiled_in(fw::Backend::EGL, &why));
    CHECK(fw::backend_compiled_in(fw::Backend::Auto, &why));
#ifdef LAB_HAVE_OSMESA
    CHECK(fw::backend_compiled_in(fw::Backend::OSMesa, &why));
#else
    CHECK_FALSE(fw::backend_compiled_in(fw::Backend::OSMesa, &why));
    INFO("why: " << why);
    CHECK(contains(why, "libosmesa6-dev"));
    CHECK(contains(why, "--backend egl"));
#endif
}
