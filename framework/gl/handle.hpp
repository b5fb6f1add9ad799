// The one piece every GL wrapper shares: a GL object name that is deleted
// exactly once. Move-only, like std::unique_ptr; a moved-from or
// default-constructed Handle holds 0 and deletes nothing, so wrappers can be
// declared before a context exists and created later by assignment.
#pragma once

#include <glad/gl.h>

#include <utility>

namespace fw::detail {

class Handle {
public:
    using Deleter = void (*)(GLuint);

    Handle() = default;
    Handle(GLuint id, Deleter deleter) : id_(id), deleter_(deleter) {}
    ~Handle() { reset(); }

    Handle(const Handle&) = delete;
    Handle& operator=(const Handle&) = delete;
    Handle(Handle&& other) noexcept
        : id_(std::exchange(other.id_, 0)), deleter_(std::exchange(other.deleter_, nullptr)) {}
    Handle& operator=(Handle&& other) noexcept {
        if (this != &other) {
            reset();
            id_ = std::exchange(other.id_, 0);
            deleter_ = std::exchange(other.deleter_, nullptr);
        }
        return *this;
    }

    GLuint get() const { return id_; }

    void reset() {
        if (id_ != 0 && deleter_) deleter_(id_);
        id_ = 0;
    }

private:
    GLuint id_ = 0;
    Deleter deleter_ = nullptr;
};

}  // namespace fw::detail
