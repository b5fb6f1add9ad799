#include "framework/gl/framebuffer.hpp"

#include "framework/error.hpp"
#include "framework/gl/binding.hpp"
#include "framework/gl/debug.hpp"

namespace fw {

namespace {

// The smallest of the GL limits that bound one side of a framebuffer, and its name.
struct Limit {
    GLint value;
    const char* name;
};

Limit size_limit(GLenum framebuffer_limit, const char* framebuffer_limit_name) {
    GLint texture = 0, framebuffer = 0;
    glGetIntegerv(GL_MAX_TEXTURE_SIZE, &texture);
    glGetIntegerv(framebuffer_limit, &framebuffer);
    if (framebuffer > 0 && framebuffer < texture) return {framebuffer, framebuffer_limit_name};
    return {texture, "GL_MAX_TEXTURE_SIZE"};
}

void check_size(const char* field, int value, Limit limit, const std::string& label) {
    if (value > 0 && value <= limit.value) return;
    throw UsageError(std::string("FramebufferDesc.") + field + " must be 1 to " +
                     std::to_string(limit.value) + " (" + limit.name + " on this GL), not " +
                     std::to_string(value) + " (framebuffer '" + label + "')");
}

Texture2D attachment(int width, int height, GLenum format, const std::string& label) {
    Texture2DDesc desc;
    desc.width = width;
    desc.height = height;
    desc.internal_format = format;
    desc.min_filter = GL_NEAREST;
    desc.mag_filter = GL_NEAREST;
    desc.label = label;
    return Texture2D(desc);
}

}  // namespace

Framebuffer::Framebuffer(const FramebufferDesc& desc)
    : width_(desc.width), height_(desc.height), label_(desc.label) {
    if (label_.empty())
        label_ = "framebuffer " + std::to_string(desc.width) + "x" + std::to_string(desc.height);
    check_size("width", desc.width,
               size_limit(GL_MAX_FRAMEBUFFER_WIDTH, "GL_MAX_FRAMEBUFFER_WIDTH"), label_);
    check_size("height", desc.height,
               size_limit(GL_MAX_FRAMEBUFFER_HEIGHT, "GL_MAX_FRAMEBUFFER_HEIGHT"), label_);

    color_ = attachment(width_, height_, GL_RGBA8, label_ + " colour");
    // Depth and stencil in one texture: 32-bit float depth (the precision the
    // depth probes rely on) and 8 stencil bits, on every backend alike.
    depth_ = attachment(width_, height_, GL_DEPTH32F_STENCIL8, label_ + " depth-stencil");

    GLuint id = 0;
    glGenFramebuffers(1, &id);
    handle_ = detail::Handle(id, [](GLuint n) { glDeleteFramebuffers(1, &n); });
    GLenum status = GL_NONE;
    {
        ScopedBinding bind = bind_framebuffer_scoped(GL_DRAW_FRAMEBUFFER, id);
        glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_TEXTURE_2D,
                               color_.id(), 0);
        glFramebufferTexture2D(GL_DRAW_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_TEXTURE_2D,
                               depth_.id(), 0);
        status = glCheckFramebufferStatus(GL_DRAW_FRAMEBUFFER);
    }
    if (status != GL_FRAMEBUFFER_COMPLETE)
        throw Error("framebuffer '" + label_ + "' is incomplete: " + gl_enum_name(status) +
                    " (RGBA8 colour + DEPTH32F_STENCIL8 depth-stencil, " + std::to_string(width_) +
                    "x" + std::to_string(height_) + ")");
    set_object_label(GL_FRAMEBUFFER, id, label_);
}

void Framebuffer::bind() const {
    glBindFramebuffer(GL_FRAMEBUFFER, id());
    glViewport(0, 0, width_, height_);
}

void Framebuffer::read_pixels(GLenum format, GLenum type, void* out) const {
    if (id() == 0) throw UsageError("Framebuffer: read from an empty Framebuffer");
    ScopedBinding read = bind_framebuffer_scoped(GL_READ_FRAMEBUFFER, id());
    // With a pixel pack buffer bound, glReadPixels would write into it and
    // treat `out` as an offset.
    ScopedBinding pack_buffer = bind_buffer_scoped(GL_PIXEL_PACK_BUFFER, 0);
    ScopedBinding alignment = pixel_store_scoped(GL_PACK_ALIGNMENT, 1);
    // glReadPixels returns rows from window y = 0 (the bottom) upwards, the
    // order fw::Image stores.
    glReadPixels(0, 0, width_, height_, format, type, out);
}

Image Framebuffer::read_color() const {
    static_assert(sizeof(Rgba8) == 4, "fw::Image pixels must be tightly packed RGBA8");
    Image img;
    img.width = width_;
    img.height = height_;
    img.pixels.resize(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_));
    read_pixels(GL_RGBA, GL_UNSIGNED_BYTE, img.pixels.data());
    return img;
}

DepthImage Framebuffer::read_depth() const {
    DepthImage img;
    img.width = width_;
    img.height = height_;
    img.values.resize(static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_));
    read_pixels(GL_DEPTH_COMPONENT, GL_FLOAT, img.values.data());
    return img;
}

}  // namespace fw
