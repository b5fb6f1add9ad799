#include "framework/gl/cube_map.hpp"

#include "framework/error.hpp"
#include "framework/gl/binding.hpp"
#include "framework/gl/debug.hpp"
#include "framework/gl/texture.hpp"

namespace fw {

TextureCube::TextureCube(const TextureCubeDesc& desc)
    : size_(desc.size), internal_format_(desc.internal_format), label_(desc.label) {
    const std::string where = " (cube map '" + label_ + "')";
    GLint max_size = 0;
    glGetIntegerv(GL_MAX_CUBE_MAP_TEXTURE_SIZE, &max_size);
    if (desc.size <= 0 || desc.size > max_size)
        throw UsageError("TextureCubeDesc.size must be 1 to GL_MAX_CUBE_MAP_TEXTURE_SIZE (" +
                         std::to_string(max_size) + "), not " + std::to_string(desc.size) + where);
    if (is_mipmap_filter(desc.min_filter))
        throw UsageError("TextureCubeDesc.min_filter " + gl_enum_name(desc.min_filter) +
                         " reads mipmaps, which a cube map of one level lacks; use GL_LINEAR or "
                         "GL_NEAREST" +
                         where);

    GLuint id = 0;
    glGenTextures(1, &id);
    handle_ = detail::Handle(id, [](GLuint n) { glDeleteTextures(1, &n); });
    GLint immutable = GL_FALSE;
    {
        ScopedBinding bind = bind_texture_cube_scoped(id);
        // One call allocates all six faces, each size x size.
        glTexStorage2D(GL_TEXTURE_CUBE_MAP, 1, desc.internal_format, size_, size_);
        glGetTexParameteriv(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_IMMUTABLE_FORMAT, &immutable);
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MIN_FILTER,
                        static_cast<GLint>(desc.min_filter));
        glTexParameteri(GL_TEXTURE_CUBE_MAP, GL_TEXTURE_MAG_FILTER,
                        static_cast<GLint>(desc.mag_filter));
        for (GLenum wrap : {GL_TEXTURE_WRAP_S, GL_TEXTURE_WRAP_T, GL_TEXTURE_WRAP_R})
            glTexParameteri(GL_TEXTURE_CUBE_MAP, wrap, GL_CLAMP_TO_EDGE);
    }
    if (immutable != GL_TRUE)
        throw UsageError("TextureCubeDesc.internal_format " + gl_enum_name(desc.internal_format) +
                         " was rejected by glTexStorage2D; use a sized format such as GL_RGBA8 "
                         "or GL_DEPTH_COMPONENT32F" +
                         where);
    set_object_label(GL_TEXTURE, id, label_);
}

void TextureCube::bind(GLuint unit) const {
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(GL_TEXTURE_CUBE_MAP, id());
}

Image TextureCube::read_face(int face) const {
    if (id() == 0) throw UsageError("TextureCube::read_face on an empty TextureCube");
    if (face < 0 || face > 5)
        throw UsageError(
            "TextureCube::read_face: face must be 0 to 5 (+x, -x, +y, -y, +z, -z), "
            "not " +
            std::to_string(face) + " (cube map '" + label_ + "')");
    Image img;
    img.width = size_;
    img.height = size_;
    img.pixels.resize(static_cast<std::size_t>(size_) * static_cast<std::size_t>(size_));
    ScopedBinding texture = bind_texture_cube_scoped(id());
    // With a pixel pack buffer bound, glGetTexImage would write into it.
    ScopedBinding pack_buffer = bind_buffer_scoped(GL_PIXEL_PACK_BUFFER, 0);
    ScopedBinding alignment = pixel_store_scoped(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(GL_TEXTURE_CUBE_MAP_POSITIVE_X + static_cast<GLenum>(face), 0, GL_RGBA,
                  GL_UNSIGNED_BYTE, img.pixels.data());
    return img;
}

CubeFramebuffer::CubeFramebuffer(const CubeFramebufferDesc& desc) : label_(desc.label) {
    if (label_.empty()) label_ = "cube framebuffer " + std::to_string(desc.size);
    TextureCubeDesc color{desc.size, GL_RGBA8, GL_LINEAR, GL_LINEAR, label_ + " colour"};
    color_ = TextureCube(color);
    TextureCubeDesc depth{desc.size, GL_DEPTH_COMPONENT32F, GL_NEAREST, GL_NEAREST,
                          label_ + " depth"};
    depth_ = TextureCube(depth);

    GLuint id = 0;
    glGenFramebuffers(1, &id);
    handle_ = detail::Handle(id, [](GLuint n) { glDeleteFramebuffers(1, &n); });
    GLenum status = GL_NONE;
    {
        ScopedBinding bind = bind_framebuffer_scoped(GL_DRAW_FRAMEBUFFER, id);
        // The whole cube map, not one face (glFramebufferTexture2D): the
        // attachment is layered, and gl_Layer chooses the face a primitive
        // goes to (GL 4.3 core, 9.8). Every attachment must then be layered.
        glFramebufferTexture(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, color_.id(), 0);
        glFramebufferTexture(GL_DRAW_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, depth_.id(), 0);
        status = glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER);
    }
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw Error("cube framebuffer '" + label_ + "' is incomplete: " + gl_enum_name(status) +
                    " (RGBA8 colour + DEPTH_COMPONENT32F depth cube maps, " +
                    std::to_string(desc.size) + "x" + std::to_string(desc.size) + " a face)");
    set_object_label(GL_FRAMEBUFFER, id, label_);
}

void CubeFramebuffer::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, id());
    glViewport(0, 0, size(), size());
}

}  // namespace fw
