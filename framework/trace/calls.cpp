#include "framework/trace/calls.hpp"

#include <glad/gl.h>

#include <atomic>
#include <chrono>

namespace fw::gl_calls {

namespace {

thread_local Observer* tl_observer = nullptr;
std::atomic<bool> g_installed{false};

using Hook = void (Observer::*)(const char*, int, va_list);

void pass(Hook hook, const char* name, int count, va_list args) {
    if (Observer* o = tl_observer) (o->*hook)(name, count, args);
}

void before_call(const char* name, GLADapiproc, int count, ...) {
    va_list args;
    va_start(args, count);
    pass(&Observer::before, name, count, args);
    va_end(args);
}

void after_call(void*, const char* name, GLADapiproc, int count, ...) {
    va_list args;
    va_start(args, count);
    pass(&Observer::after, name, count, args);
    va_end(args);
}

}  // namespace

void Fanout::each(Hook hook, const char* name, int count, va_list args) {
    using Clock = std::chrono::steady_clock;
    for (const Added& o : observers_) {
        const Clock::time_point start = o.seconds ? Clock::now() : Clock::time_point();
        va_list copy;
        va_copy(copy, args);
        (o.observer->*hook)(name, count, copy);
        va_end(copy);
        if (o.seconds) *o.seconds += std::chrono::duration<double>(Clock::now() - start).count();
    }
}

void Fanout::before(const char* name, int count, va_list args) {
    each(&Observer::before, name, count, args);
}

void Fanout::after(const char* name, int count, va_list args) {
    each(&Observer::after, name, count, args);
}

void install() {
    gladSetGLPreCallback(&before_call);
    gladSetGLPostCallback(&after_call);
    g_installed = true;
}

bool installed() { return g_installed; }

Observer* observe(Observer* o) {
    Observer* previous = tl_observer;
    tl_observer = o;
    return previous;
}

Observer* observer() { return tl_observer; }

Unobserved::Unobserved() : saved_(tl_observer) { tl_observer = nullptr; }
Unobserved::~Unobserved() { tl_observer = saved_; }

}  // namespace fw::gl_calls
