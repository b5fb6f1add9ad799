#include "framework/gl/binding.hpp"

#include <string>

#include "framework/error.hpp"
#include "framework/gl/debug.hpp"

namespace fw {

namespace {

GLenum framebuffer_binding_query(GLenum target) {
    if (target == GL_DRAW_FRAMEBUFFER) return GL_DRAW_FRAMEBUFFER_BINDING;
    if (target == GL_READ_FRAMEBUFFER) return GL_READ_FRAMEBUFFER_BINDING;
    throw Error("bind_framebuffer_scoped: " + gl_enum_name(target) +
                " is neither GL_DRAW_FRAMEBUFFER nor GL_READ_FRAMEBUFFER");
}

}  // namespace

GLint get_integer(GLenum pname) {
    GLint v = 0;
    glGetIntegerv(pname, &v);
    return v;
}

GLint get_integer(GLenum pname, GLuint index) {
    GLint v = 0;
    glGetIntegeri_v(pname, index, &v);
    return v;
}

GLenum buffer_binding_query(GLenum target) {
    switch (target) {
        case GL_ARRAY_BUFFER:
            return GL_ARRAY_BUFFER_BINDING;
        case GL_ELEMENT_ARRAY_BUFFER:
            return GL_ELEMENT_ARRAY_BUFFER_BINDING;
        case GL_UNIFORM_BUFFER:
            return GL_UNIFORM_BUFFER_BINDING;
        case GL_SHADER_STORAGE_BUFFER:
            return GL_SHADER_STORAGE_BUFFER_BINDING;
        case GL_TRANSFORM_FEEDBACK_BUFFER:
            return GL_TRANSFORM_FEEDBACK_BUFFER_BINDING;
        case GL_ATOMIC_COUNTER_BUFFER:
            return GL_ATOMIC_COUNTER_BUFFER_BINDING;
        case GL_COPY_READ_BUFFER:
            return GL_COPY_READ_BUFFER_BINDING;
        case GL_COPY_WRITE_BUFFER:
            return GL_COPY_WRITE_BUFFER_BINDING;
        case GL_PIXEL_PACK_BUFFER:
            return GL_PIXEL_PACK_BUFFER_BINDING;
        case GL_PIXEL_UNPACK_BUFFER:
            return GL_PIXEL_UNPACK_BUFFER_BINDING;
        case GL_DRAW_INDIRECT_BUFFER:
            return GL_DRAW_INDIRECT_BUFFER_BINDING;
        case GL_DISPATCH_INDIRECT_BUFFER:
            return GL_DISPATCH_INDIRECT_BUFFER_BINDING;
        default:
            return 0;
    }
}

ScopedBinding::ScopedBinding(GLenum target, GLenum query, GLint value, Apply apply)
    : target_(target), apply_(apply) {
    glGetIntegerv(query, &previous_);
    apply_(target_, value);
}

ScopedBinding::~ScopedBinding() { apply_(target_, previous_); }

ScopedBinding bind_buffer_scoped(GLenum target, GLuint id) {
    const GLenum query = buffer_binding_query(target);
    if (query == 0)
        throw Error("bind_buffer_scoped: " + gl_enum_name(target) +
                    " is not a buffer target it knows; add its binding query to binding.cpp");
    return {target, query, static_cast<GLint>(id),
            [](GLenum t, GLint v) { glBindBuffer(t, static_cast<GLuint>(v)); }};
}

ScopedBinding bind_texture_2d_scoped(GLuint id) {
    return {GL_TEXTURE_2D, GL_TEXTURE_BINDING_2D, static_cast<GLint>(id),
            [](GLenum t, GLint v) { glBindTexture(t, static_cast<GLuint>(v)); }};
}

ScopedBinding bind_texture_cube_scoped(GLuint id) {
    return {GL_TEXTURE_CUBE_MAP, GL_TEXTURE_BINDING_CUBE_MAP, static_cast<GLint>(id),
            [](GLenum t, GLint v) { glBindTexture(t, static_cast<GLuint>(v)); }};
}

ScopedBinding bind_framebuffer_scoped(GLenum target, GLuint id) {
    return {target, framebuffer_binding_query(target), static_cast<GLint>(id),
            [](GLenum t, GLint v) { glBindFramebuffer(t, static_cast<GLuint>(v)); }};
}

ScopedBinding bind_vertex_array_scoped(GLuint id) {
    // Vertex arrays have no target; the first argument is unused.
    return {GL_NONE, GL_VERTEX_ARRAY_BINDING, static_cast<GLint>(id),
            [](GLenum, GLint v) { glBindVertexArray(static_cast<GLuint>(v)); }};
}

ScopedBinding pixel_store_scoped(GLenum parameter, GLint value) {
    return {parameter, parameter, value, [](GLenum p, GLint v) { glPixelStorei(p, v); }};
}

}  // namespace fw
