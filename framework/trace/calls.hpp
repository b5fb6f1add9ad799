// Every GL call a program makes through glad passes through here. The loader
// is generated with glad's --debug option (scripts/gen-glad.sh): each entry
// point calls a hook before and after the driver's function, with the
// function's name and its arguments. install() replaces glad's own hooks
// (which would call glGetError around every call, taking the errors a lab
// checks for itself, and print to stderr) by hooks that pass each call to
// this thread's observer, and do nothing when there is none.
//
// What observes: the grading child's record of what each draw was told
// (the state at every draw, dispatch, clear and read-back) and the checks of
// GL usage that the specification leaves undefined. A lab's own code needs
// nothing of this: it calls GL as usual.
#pragma once

#include <cstdarg>
#include <vector>

namespace fw::gl_calls {

// Receives the calls of the thread it observes. `name` is the GL function's
// name ("glDrawArrays"); `count` how many arguments follow in `args`, as C
// passes them to a variadic function: GLenum, GLuint and GLbitfield as
// unsigned int, GLint, GLsizei and GLboolean as int, GLfloat and GLdouble as
// double, GLintptr and GLsizeiptr as long, pointers as pointers.
class Observer {
public:
    virtual ~Observer() = default;
    virtual void before(const char* name, int count, va_list args) = 0;
    virtual void after(const char* name, int count, va_list args) = 0;
};

// Passes each call on to several observers, in the order they were added
// (each reads the arguments from its own copy of the list). Where `seconds`
// is given, the wall time the observer spends on the calls is added to it
// (`course grade --verbose` prints what the per-draw record costs).
class Fanout : public Observer {
public:
    void add(Observer* observer, double* seconds = nullptr) {
        observers_.push_back({observer, seconds});
    }
    bool empty() const { return observers_.empty(); }
    void before(const char* name, int count, va_list args) override;
    void after(const char* name, int count, va_list args) override;

private:
    void each(void (Observer::*hook)(const char*, int, va_list), const char* name, int count,
              va_list args);
    struct Added {
        Observer* observer;
        double* seconds;
    };
    std::vector<Added> observers_;
};

// Replaces glad's default hooks; call right after gladLoadGL (the framework's
// load_gl_and_check does). Safe to call again.
void install();

// Whether install() has run in this process.
bool installed();

// Makes `observer` (null: none) receive this thread's GL calls; returns the
// one it replaces.
Observer* observe(Observer* observer);

// The observer of this thread's calls, or null.
Observer* observer();

// While one lives, this thread's calls reach no observer: what an observer
// asks GL itself (its glGet queries) is not observed again.
class Unobserved {
public:
    Unobserved();
    ~Unobserved();
    Unobserved(const Unobserved&) = delete;
    Unobserved& operator=(const Unobserved&) = delete;

private:
    Observer* saved_;
};

}  // namespace fw::gl_calls
