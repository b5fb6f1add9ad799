// framework/trace/calls: every GL call reaches this thread's observer, with its
// arguments, before and after the driver's function; without an observer,
// and while an Unobserved lives, nothing does; and the hooks leave GL's
// errors to the program (glad's own hooks would call glGetError around
// every call).
#include <glad/gl.h>

#include <string>
#include <vector>

#include "framework/gl/debug.hpp"
#include "framework/trace/calls.hpp"
#include "tests/support/test_support.hpp"

namespace {

struct Seen {
    std::string when, name;
    std::vector<long> args;
};

// Keeps what glClearColor's neighbours and the calls below were given: the
// enums and integers of glEnable, glDepthFunc, glViewport and glGetError.
class Recorder : public fw::gl_calls::Observer {
public:
    std::vector<Seen> calls;
    void before(const char* name, int count, va_list args) override {
        add("before", name, count, args);
    }
    void after(const char* name, int count, va_list args) override {
        add("after", name, count, args);
    }

private:
    void add(const char* when, const char* name, int count, va_list args) {
        Seen s{when, name, {}};
        const std::string n = name;
        if (n == "glEnable" || n == "glDepthFunc" || n == "glViewport")
            for (int i = 0; i < count; ++i)
                s.args.push_back(n == "glViewport" ? va_arg(args, int) : va_arg(args, unsigned));
        calls.push_back(s);
    }
};

// The observer of this thread for the scope, as the grading child sets it.
struct Observing {
    explicit Observing(fw::gl_calls::Observer* o) : saved(fw::gl_calls::observe(o)) {}
    ~Observing() { fw::gl_calls::observe(saved); }
    fw::gl_calls::Observer* saved;
};

}  // namespace

TEST_CASE("gl calls: each call reaches the observer before and after, with its arguments") {
    REQUIRE(fw::gl_calls::installed());
    Recorder r;
    {
        Observing on(&r);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LEQUAL);
        glViewport(3, 4, 50, 60);
    }
    REQUIRE(r.calls.size() == 6);
    CHECK(r.calls[0].when == "before");
    CHECK(r.calls[0].name == "glEnable");
    CHECK(r.calls[0].args == std::vector<long>{GL_DEPTH_TEST});
    CHECK(r.calls[1].when == "after");
    CHECK(r.calls[1].name == "glEnable");
    CHECK(r.calls[2].name == "glDepthFunc");
    CHECK(r.calls[2].args == std::vector<long>{GL_LEQUAL});
    CHECK(r.calls[4].name == "glViewport");
    CHECK(r.calls[4].args == std::vector<long>{3, 4, 50, 60});
    glDisable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
}

TEST_CASE("gl calls: without an observer, or while Unobserved lives, nothing is seen") {
    Recorder r;
    glEnable(GL_DEPTH_TEST);  // no observer yet
    {
        Observing on(&r);
        {
            fw::gl_calls::Unobserved quiet;
            CHECK(fw::gl_calls::observer() == nullptr);
            glDisable(GL_DEPTH_TEST);
        }
        CHECK(fw::gl_calls::observer() == &r);
        glDepthFunc(GL_LESS);
    }
    glEnable(GL_DEPTH_TEST);  // the observer is gone again
    glDisable(GL_DEPTH_TEST);
    REQUIRE(r.calls.size() == 2);
    CHECK(r.calls[0].name == "glDepthFunc");
}

TEST_CASE("gl calls: the hooks leave GL's errors to the program") {
    while (glGetError() != GL_NO_ERROR) {
    }
    Recorder r;
    Observing on(&r);
    glEnable(0x1234);  // not a capability: GL_INVALID_ENUM
    CHECK(glGetError() == GL_INVALID_ENUM);
    CHECK(glGetError() == GL_NO_ERROR);
    fw::take_debug_messages();  // the debug output's message of the same error
}

TEST_CASE("gl calls: a fan-out passes each call, with its arguments, to every observer") {
    Recorder a, b;
    fw::gl_calls::Fanout both;
    both.add(&a);
    both.add(&b);
    {
        Observing on(&both);
        glDepthFunc(GL_GREATER);
    }
    glDepthFunc(GL_LESS);
    for (const Recorder* r : {&a, &b}) {
        REQUIRE(r->calls.size() == 2);
        CHECK(r->calls[0].args == std::vector<long>{GL_GREATER});
        CHECK(r->calls[1].args == std::vector<long>{GL_GREATER});
    }
}
