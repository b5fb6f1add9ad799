#include "framework/gl/texture.hpp"

#include "framework/error.hpp"
#include "framework/gl/binding.hpp"
#include "framework/gl/debug.hpp"

namespace fw {

namespace {

int full_mip_chain(int width, int height) {
    int levels = 1;
    for (int size = width > height ? width : height; size > 1; size /= 2) ++levels;
    return levels;
}

// Uploads with `id` bound to GL_TEXTURE_2D of the active unit, tightly packed
// rows and no pixel unpack buffer (with one bound, `data` would be an offset
// into it), then restores all three. GL_UNPACK_ALIGNMENT defaults to 4, which
// would misread RGB8 rows whose size is not a multiple of 4.
void upload(GLuint id, int width, int height, const void* data, GLenum format, GLenum type,
            bool mipmaps) {
    ScopedBinding texture = bind_texture_2d_scoped(id);
    ScopedBinding unpack_buffer = bind_buffer_scoped(GL_PIXEL_UNPACK_BUFFER, 0);
    ScopedBinding alignment = pixel_store_scoped(GL_UNPACK_ALIGNMENT, 1);
    glTexSubImage2D(GL_TEXTURE_2D, 0, 0, 0, width, height, format, type, data);
    if (mipmaps) glGenerateMipmap(GL_TEXTURE_2D);
}

}  // namespace

bool is_mipmap_filter(GLenum min_filter) {
    return min_filter == GL_NEAREST_MIPMAP_NEAREST || min_filter == GL_LINEAR_MIPMAP_NEAREST ||
           min_filter == GL_NEAREST_MIPMAP_LINEAR || min_filter == GL_LINEAR_MIPMAP_LINEAR;
}

Texture2D::Texture2D(const Texture2DDesc& desc)
    : width_(desc.width),
      height_(desc.height),
      internal_format_(desc.internal_format),
      label_(desc.label) {
    const std::string where = " (texture '" + label_ + "')";
    GLint max_size = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &max_size);
    if (desc.width <= 0 || desc.width > max_size)
        throw UsageError("Texture2DDesc.width must be 1 to GL_MAX_TEXTURE_SIZE (" +
                         std::to_string(max_size) + "), not " + std::to_string(desc.width) + where);
    if (desc.height <= 0 || desc.height > max_size)
        throw UsageError("Texture2DDesc.height must be 1 to GL_MAX_TEXTURE_SIZE (" +
                         std::to_string(max_size) + "), not " + std::to_string(desc.height) +
                         where);
    build_mipmaps_ = desc.levels == 0 && is_mipmap_filter(desc.min_filter);
    const int chain = full_mip_chain(width_, height_);
    if (desc.levels < 0 || desc.levels > chain)
        throw UsageError("Texture2DDesc.levels must be 0 (as min_filter needs) or 1 to " +
                         std::to_string(chain) + " for " + std::to_string(width_) + "x" +
                         std::to_string(height_) + ", not " + std::to_string(desc.levels) + where);
    levels_ = desc.levels > 0 ? desc.levels : build_mipmaps_ ? chain : 1;

    GLuint id = 0;
    glGenTextures(1, &id);
    handle_ = detail::Handle(id, [](GLuint n) { glDeleteTextures(1, &n); });
    GLint immutable = GL_FALSE;
    {
        ScopedBinding bind = bind_texture_2d_scoped(id);
        glTexStorage2D(GL_TEXTURE_2D, levels_, desc.internal_format, width_, height_);
        // glTexStorage2D fails (GL_INVALID_ENUM) for a format that is not sized,
        // such as GL_RGBA instead of GL_RGBA8; catch it here, not at first use.
        glGetTexParameteriv(GL_TEXTURE_2D, GL_TEXTURE_IMMUTABLE_FORMAT, &immutable);
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, static_cast<GLint>(desc.min_filter));
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, static_cast<GLint>(desc.mag_filter));
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, static_cast<GLint>(desc.wrap));
        glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, static_cast<GLint>(desc.wrap));
    }
    if (immutable != GL_TRUE)
        throw UsageError("Texture2DDesc.internal_format " + gl_enum_name(desc.internal_format) +
                         " was rejected by glTexStorage2D; use a sized format such as GL_RGBA8, "
                         "GL_R32F or GL_DEPTH_COMPONENT32F" +
                         where);
    set_object_label(GL_TEXTURE, id, label_);
    if (desc.data) update(desc.data, desc.data_format, desc.data_type);
}

Texture2D Texture2D::from_image(const Image& image, std::string label, GLenum min_filter,
                                GLenum mag_filter) {
    Texture2DDesc desc;
    desc.width = image.width;
    desc.height = image.height;
    desc.data = image.pixels.data();
    desc.min_filter = min_filter;
    desc.mag_filter = mag_filter;
    desc.label = std::move(label);
    return Texture2D(desc);
}

void Texture2D::bind(GLuint unit) const {
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(GL_TEXTURE_2D, id());
}

void Texture2D::update(const void* data, GLenum data_format, GLenum data_type) {
    if (id() == 0) throw UsageError("Texture2D::update on an empty Texture2D");
    upload(id(), width_, height_, data, data_format, data_type, build_mipmaps_);
}

}  // namespace fw
