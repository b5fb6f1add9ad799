// What a draw, dispatch or read-back reads (usage_detail.hpp): each object,
// with the glMemoryBarrier bit that makes a shader's earlier writes visible
// to that read. Asked of GL at the call, never tracked from the binds.
#include <cstring>

#include "framework/gl/binding.hpp"
#include "framework/gl/debug.hpp"
#include "framework/trace/calls.hpp"
#include "framework/trace/usage_detail.hpp"

namespace fw::gl_usage::detail {

namespace {

// The texture binding query of the target glGetTexImage names (a cube
// map's face: the cube map's), 0 for one this does not follow.
GLenum texture_binding_query(GLenum target) {
    if (target >= GL_TEXTURE_CUBE_MAP_POSITIVE_X && target <= GL_TEXTURE_CUBE_MAP_NEGATIVE_Z)
        return GL_TEXTURE_BINDING_CUBE_MAP;
    switch (target) {
        case GL_TEXTURE_2D:
            return GL_TEXTURE_BINDING_2D;
        case GL_TEXTURE_3D:
            return GL_TEXTURE_BINDING_3D;
        case GL_TEXTURE_2D_ARRAY:
            return GL_TEXTURE_BINDING_2D_ARRAY;
        default:
            return 0;
    }
}

// The texture attached where glReadPixels reads (the read framebuffer's
// read buffer), 0 for none or a renderbuffer.
GLuint read_attachment() {
    const GLint fbo = get_integer(GL_READ_FRAMEBUFFER_BINDING),
                buffer = get_integer(GL_READ_BUFFER);
    if (fbo <= 0 || buffer == GL_NONE) return 0;
    GLint type = 0, name = 0;
    glGetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, GLenum(buffer),
                                          GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
    if (type != GL_TEXTURE) return 0;
    glGetFramebufferAttachmentParameteriv(GL_READ_FRAMEBUFFER, GLenum(buffer),
                                          GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &name);
    return GLuint(name);
}

}  // namespace

std::string barrier_bit_name(GLbitfield bit) {
    return fw::gl_enum_name(bit, GLAD_GL_GROUP_MemoryBarrierMask);
}

std::string object_name(const Key& k) {
    return k.first == Object::Buffer ? buffer_name(k.second) : texture_name(k.second);
}

GLuint storage_binding(GLuint program, const StorageBlock& s) {
    const GLenum prop = GL_BUFFER_BINDING;
    GLint binding = 0;
    glGetProgramResourceiv(program, GL_SHADER_STORAGE_BLOCK, s.index, 1, &prop, 1, nullptr,
                           &binding);
    return GLuint(binding);
}

std::vector<Source> call_sources(GLuint program, const ProgramInfo& p, bool draw,
                                 const char* call) {
    gl_calls::Unobserved quiet;
    std::vector<Source> out;
    const auto buffer = [&](GLint id, GLbitfield bit, std::string where) {
        if (id > 0) out.push_back({{Object::Buffer, GLuint(id)}, bit, std::move(where)});
    };
    // With no vertex array bound, GL refuses the draw and the queries alike.
    if (draw && get_integer(GL_VERTEX_ARRAY_BINDING) != 0) {
        for (GLint location : p.inputs) {
            GLint enabled = 0, id = 0;
            glGetVertexAttribiv(GLuint(location), GL_VERTEX_ATTRIB_ARRAY_ENABLED, &enabled);
            glGetVertexAttribiv(GLuint(location), GL_VERTEX_ATTRIB_ARRAY_BUFFER_BINDING, &id);
            if (enabled)
                buffer(id, GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT,
                       "vertex attributes (location " + std::to_string(location) + ")");
        }
        if (std::strstr(call, "Elements"))
            buffer(get_integer(GL_ELEMENT_ARRAY_BUFFER_BINDING), GL_ELEMENT_ARRAY_BARRIER_BIT,
                   "indices");
    }
    if (std::strstr(call, "Indirect"))
        buffer(get_integer(draw ? GL_DRAW_INDIRECT_BUFFER_BINDING
                                : GL_DISPATCH_INDIRECT_BUFFER_BINDING),
               GL_COMMAND_BARRIER_BIT, "the indirect command");
    for (GLint b = 0; b < p.uniform_blocks; ++b) {
        GLint binding = 0;
        glGetActiveUniformBlockiv(program, GLuint(b), GL_UNIFORM_BLOCK_BINDING, &binding);
        buffer(get_integer(GL_UNIFORM_BUFFER_BINDING, GLuint(binding)), GL_UNIFORM_BARRIER_BIT,
               "a uniform block (binding " + std::to_string(binding) + ")");
    }
    for (const StorageBlock& s : p.storage)
        buffer(get_integer(GL_SHADER_STORAGE_BUFFER_BINDING, storage_binding(program, s)),
               GL_SHADER_STORAGE_BARRIER_BIT, "the storage block " + s.name);
    for (const Opaque& image : p.images) {
        GLint unit = 0;
        glGetUniformiv(program, image.location, &unit);
        const GLint texture = get_integer(GL_IMAGE_BINDING_NAME, GLuint(unit));
        if (texture > 0)
            out.push_back({{Object::Texture, GLuint(texture)},
                           GL_SHADER_IMAGE_ACCESS_BARRIER_BIT,
                           "the image " + image.name});
    }
    return out;
}

std::vector<Source> read_back_sources(const char* call, va_list args) {
    gl_calls::Unobserved quiet;
    const std::string n = call;
    std::vector<Source> out;
    if (n == "glGetBufferSubData" || n == "glMapBuffer" || n == "glMapBufferRange" ||
        n == "glCopyBufferSubData") {
        const GLenum binding = buffer_binding_query(va_arg(args, unsigned));
        if (binding)
            out.push_back({{Object::Buffer, GLuint(get_integer(binding))},
                           GL_BUFFER_UPDATE_BARRIER_BIT,
                           "a buffer read back or mapped (" + n + ")"});
        return out;
    }
    const GLint pack = get_integer(GL_PIXEL_PACK_BUFFER_BINDING);
    if (pack > 0)
        out.push_back({{Object::Buffer, GLuint(pack)},
                       GL_PIXEL_BUFFER_BARRIER_BIT,
                       "the pixel pack buffer " + n + " writes into"});
    if (n == "glGetTexImage") {
        const GLenum binding = texture_binding_query(va_arg(args, unsigned));
        if (binding)
            out.push_back({{Object::Texture, GLuint(get_integer(binding))},
                           GL_TEXTURE_UPDATE_BARRIER_BIT,
                           "a texture read back (" + n + ")"});
    } else if (const GLuint attached = read_attachment()) {
        out.push_back({{Object::Texture, attached},
                       GL_FRAMEBUFFER_BARRIER_BIT,
                       "a framebuffer attachment (" + n + ")"});
    }
    return out;
}

}  // namespace fw::gl_usage::detail
