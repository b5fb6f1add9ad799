// fw::Framebuffer: an offscreen render target with an RGBA8 colour texture
// and a DEPTH32F_STENCIL8 depth-stencil texture (32-bit float depth, 8 stencil
// bits), read back as fw::Image/DepthImage.
//
//   fw::Framebuffer fb({512, 512, "offscreen"});
//   fb.bind();                        // draw into it; the viewport is set to 512x512
//   glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
//   ... draw ...
//   fw::Image img = fb.read_color();  // img.at(x, y) is window pixel (x, y), y up
#pragma once

#include <glad/gl.h>

#include <string>

#include "framework/gl/handle.hpp"
#include "framework/gl/texture.hpp"
#include "framework/image.hpp"

namespace fw {

struct FramebufferDesc {
    int width = 512, height = 512;  // 1 .. the GL limits (GL_MAX_FRAMEBUFFER_WIDTH, ...)
    std::string label;              // default "framebuffer WxH"
};

class Framebuffer {
public:
    Framebuffer() = default;
    // Throws UsageError naming the field and the GL limit for a bad size, and
    // fw::Error if GL reports the framebuffer incomplete.
    explicit Framebuffer(const FramebufferDesc& desc);

    GLuint id() const { return handle_.get(); }
    int width() const { return width_; }
    int height() const { return height_; }
    const std::string& label() const { return label_; }
    const Texture2D& color_texture() const { return color_; }
    const Texture2D& depth_texture() const { return depth_; }

    // glBindFramebuffer(GL_FRAMEBUFFER, id()) and glViewport(0, 0, width, height):
    // the viewport is not part of the framebuffer, so binding alone would
    // keep the previous target's size.
    void bind() const;

    // The colour attachment, bottom row first (glReadPixels order).
    Image read_color() const;
    // Window-space depth in [0, 1], bottom row first.
    DepthImage read_depth() const;

private:
    void read_pixels(GLenum format, GLenum type, void* out) const;

    detail::Handle handle_;
    Texture2D color_, depth_;
    int width_ = 0, height_ = 0;
    std::string label_;
};

}  // namespace fw
