// fw::Buffer: a GL buffer object holding vertices, indices or uniform data.
//
//   auto vbo = fw::Buffer::from(vertices, GL_ARRAY_BUFFER, "quad vertices");
//   glBindBuffer(GL_ARRAY_BUFFER, vbo.id());   // raw GL whenever you need it
//
// The size is fixed at creation (glBufferData once); update() rewrites part
// of it. Creation, update() and read() bind the buffer to
// GL_COPY_WRITE_BUFFER / GL_COPY_READ_BUFFER, never to its own target: binding
// GL_ELEMENT_ARRAY_BUFFER would silently change the index buffer of whatever
// vertex array happens to be bound.
#pragma once

#include <glad/gl.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

#include "framework/error.hpp"
#include "framework/gl/handle.hpp"

namespace fw {

struct BufferDesc {
    GLenum target = GL_ARRAY_BUFFER;  // the binding point bind() uses
    GLenum usage = GL_STATIC_DRAW;    // a hint: GL_STATIC_DRAW, GL_DYNAMIC_DRAW, ...
    const void* data = nullptr;       // nullptr: contents undefined until update()
    std::size_t size = 0;             // bytes; must be > 0
    std::string label;                // shown in GL debug messages and errors
};

class Buffer {
public:
    Buffer() = default;
    explicit Buffer(const BufferDesc& desc);

    // A buffer holding a copy of `v` (sizeof(T) * v.size() bytes).
    template <class T>
    static Buffer from(const std::vector<T>& v, GLenum target = GL_ARRAY_BUFFER,
                       std::string label = {}) {
        BufferDesc desc;
        desc.target = target;
        desc.data = v.data();
        desc.size = v.size() * sizeof(T);
        desc.label = std::move(label);
        return Buffer(desc);
    }

    GLuint id() const { return handle_.get(); }
    std::size_t size() const { return size_; }
    GLenum target() const { return target_; }
    const std::string& label() const { return label_; }

    // glBindBuffer(target(), id()).
    void bind() const;
    // glBindBufferBase(target(), index, id()), for uniform and storage buffers.
    void bind_base(GLuint index) const;

    // Overwrites bytes [offset, offset + bytes). Throws UsageError if that
    // range is not inside the buffer.
    void update(std::size_t offset, const void* data, std::size_t bytes);
    template <class T>
    void update(const std::vector<T>& v, std::size_t offset = 0) {
        update(offset, v.data(), v.size() * sizeof(T));
    }

    // Copies bytes [offset, offset + bytes) back from GL; the default reads
    // to the end. Throws UsageError for a range outside the buffer.
    std::vector<std::uint8_t> read(std::size_t offset = 0, std::size_t bytes = SIZE_MAX) const;

    // The whole buffer as elements of T; throws if the size is not a multiple.
    template <class T>
    std::vector<T> read_as() const {
        if (size_ % sizeof(T) != 0)
            throw UsageError("Buffer '" + label_ + "': its " + std::to_string(size_) +
                             " bytes are not a whole number of " + std::to_string(sizeof(T)) +
                             "-byte elements");
        std::vector<std::uint8_t> bytes = read();
        std::vector<T> out(size_ / sizeof(T));
        if (!bytes.empty()) std::memcpy(out.data(), bytes.data(), bytes.size());
        return out;
    }

private:
    void check_range(const char* what, std::size_t offset, std::size_t bytes) const;

    detail::Handle handle_;
    std::size_t size_ = 0;
    GLenum target_ = GL_ARRAY_BUFFER;
    std::string label_;
};

}  // namespace fw
