#include "framework/gl/buffer.hpp"

#include "framework/gl/binding.hpp"
#include "framework/gl/debug.hpp"
#include "framework/text.hpp"

namespace fw {

Buffer::Buffer(const BufferDesc& desc) : target_(desc.target), label_(desc.label) {
    if (desc.size == 0)
        throw UsageError("BufferDesc.size must be greater than zero (label " +
                         quoted_label(label_) + ")");
    GLuint id = 0;
    glGenBuffers(1, &id);
    handle_ = detail::Handle(id, [](GLuint name) { glDeleteBuffers(1, &name); });
    // A name from glGenBuffers becomes a buffer object when first bound, to
    // any target; its target does not stick to it.
    ScopedBinding bind = bind_buffer_scoped(GL_COPY_WRITE_BUFFER, id);
    glBufferData(GL_COPY_WRITE_BUFFER, static_cast<GLsizeiptr>(desc.size), desc.data, desc.usage);
    size_ = desc.size;
    set_object_label(GL_BUFFER, id, label_);
}

void Buffer::bind() const { glBindBuffer(target_, id()); }

void Buffer::bind_base(GLuint index) const { glBindBufferBase(target_, index, id()); }

void Buffer::check_range(const char* what, std::size_t offset, std::size_t bytes) const {
    if (id() == 0)
        throw UsageError(std::string("Buffer::") + what +
                         " on an empty Buffer (default-constructed or moved from)");
    if (offset > size_ || bytes > size_ - offset)
        throw UsageError("Buffer " + quoted_label(label_) + ": " + what + " of bytes [" +
                         std::to_string(offset) + ", " + std::to_string(offset + bytes) +
                         ") is outside its " + std::to_string(size_) + " bytes");
}

void Buffer::update(std::size_t offset, const void* data, std::size_t bytes) {
    check_range("update", offset, bytes);
    if (bytes == 0) return;
    ScopedBinding bind = bind_buffer_scoped(GL_COPY_WRITE_BUFFER, id());
    glBufferSubData(GL_COPY_WRITE_BUFFER, static_cast<GLintptr>(offset),
                    static_cast<GLsizeiptr>(bytes), data);
}

std::vector<std::uint8_t> Buffer::read(std::size_t offset, std::size_t bytes) const {
    if (bytes == SIZE_MAX && offset <= size_) bytes = size_ - offset;
    check_range("read", offset, bytes);
    std::vector<std::uint8_t> out(bytes);
    if (bytes == 0) return out;
    ScopedBinding bind = bind_buffer_scoped(GL_COPY_READ_BUFFER, id());
    glGetBufferSubData(GL_COPY_READ_BUFFER, static_cast<GLintptr>(offset),
                       static_cast<GLsizeiptr>(bytes), out.data());
    return out;
}

}  // namespace fw
