// Scoped GL state: a wrapper that must bind an object (or set a pixel-store
// parameter) to do its work sets it for one scope and puts back what was
// there before, so that it changes no state its caller can see.
//
//   {
//       fw::ScopedBinding texture = fw::bind_texture_2d_scoped(id);
//       fw::ScopedBinding alignment = fw::pixel_store_scoped(GL_UNPACK_ALIGNMENT, 1);
//       glTexSubImage2D(GL_TEXTURE_2D, ...);
//   }  // alignment, then the texture binding, restored
#pragma once

#include <glad/gl.h>

namespace fw {

// Reads the current value with glGetIntegerv(query), applies `value` with
// `apply(target, value)`, and in the destructor applies the old value again.
// Neither copyable nor movable: it restores exactly once, at the end of the
// scope it was declared in.
class ScopedBinding {
public:
    using Apply = void (*)(GLenum target, GLint value);

    ScopedBinding(GLenum target, GLenum query, GLint value, Apply apply);
    ~ScopedBinding();
    ScopedBinding(const ScopedBinding&) = delete;
    ScopedBinding& operator=(const ScopedBinding&) = delete;

private:
    GLenum target_;
    GLint previous_ = 0;
    Apply apply_;
};

// The query that reads which buffer is bound to `target`
// (GL_ARRAY_BUFFER_BINDING for GL_ARRAY_BUFFER): for GL_ARRAY_BUFFER,
// GL_ELEMENT_ARRAY_BUFFER, GL_UNIFORM_BUFFER, GL_SHADER_STORAGE_BUFFER,
// GL_TRANSFORM_FEEDBACK_BUFFER, GL_ATOMIC_COUNTER_BUFFER, GL_COPY_READ_BUFFER,
// GL_COPY_WRITE_BUFFER, GL_PIXEL_PACK_BUFFER, GL_PIXEL_UNPACK_BUFFER,
// GL_DRAW_INDIRECT_BUFFER and GL_DISPATCH_INDIRECT_BUFFER; 0 for another enum.
GLenum buffer_binding_query(GLenum target);

// glGetIntegerv(pname) and glGetIntegeri_v(pname, index), one value each.
GLint get_integer(GLenum pname);
GLint get_integer(GLenum pname, GLuint index);
// glBindBuffer(target, id) for the scope. `target` is one of the targets
// buffer_binding_query knows; another throws fw::Error.
ScopedBinding bind_buffer_scoped(GLenum target, GLuint id);
// glBindTexture(GL_TEXTURE_2D, id) on the active texture unit, for the scope.
ScopedBinding bind_texture_2d_scoped(GLuint id);
// glBindTexture(GL_TEXTURE_CUBE_MAP, id) on the active texture unit, for the scope.
ScopedBinding bind_texture_cube_scoped(GLuint id);
// glBindFramebuffer(target, id) for the scope; target GL_DRAW_FRAMEBUFFER or
// GL_READ_FRAMEBUFFER (another throws fw::Error).
ScopedBinding bind_framebuffer_scoped(GLenum target, GLuint id);
// glBindVertexArray(id) for the scope.
ScopedBinding bind_vertex_array_scoped(GLuint id);
// glPixelStorei(parameter, value) for the scope, e.g. GL_UNPACK_ALIGNMENT, 1.
ScopedBinding pixel_store_scoped(GLenum parameter, GLint value);

}  // namespace fw
