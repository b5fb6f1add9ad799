// fw::Texture2D: an immutable-size 2D texture (glTexStorage2D).
//
//   fw::Texture2D tex({64, 64, GL_RGBA8, pixels.data()});  // width, height, format, data
//   tex.bind(0);                 // glActiveTexture(GL_TEXTURE0) + glBindTexture
//   prog.set("u_texture", 0);    // the sampler reads unit 0
//
// Row 0 of the data is the BOTTOM row of the texture (t = 0), the same order
// fw::Image stores and glReadPixels returns.
#pragma once

#include <glad/gl.h>

#include <string>

#include "framework/gl/handle.hpp"
#include "framework/image.hpp"

namespace fw {

struct Texture2DDesc {
    int width = 0, height = 0;            // required, 1 .. GL_MAX_TEXTURE_SIZE
    GLenum internal_format = GL_RGBA8;    // how GL stores it (sized: GL_RGBA8, GL_R32F, ...)
    const void* data = nullptr;           // nullptr: contents undefined (render targets)
    GLenum data_format = GL_RGBA;         // layout of `data`: GL_RGBA, GL_RGB, GL_RED, ...
    GLenum data_type = GL_UNSIGNED_BYTE;  // type of each value in `data`
    GLenum min_filter = GL_LINEAR;        // a *_MIPMAP_* filter also builds mipmaps
    GLenum mag_filter = GL_LINEAR;
    GLenum wrap = GL_CLAMP_TO_EDGE;  // for both s and t
    // Storage levels: 0, the full chain for a *_MIPMAP_* min_filter (built
    // from the data) and else 1; n > 0, n levels (at most the full chain),
    // level 0 from the data and the others left for glGenerateMipmap.
    int levels = 0;
    std::string label;
};

// Whether a minification filter reads mipmaps (GL_*_MIPMAP_*).
bool is_mipmap_filter(GLenum min_filter);

class Texture2D {
public:
    Texture2D() = default;
    explicit Texture2D(const Texture2DDesc& desc);
    // An RGBA8 texture holding `image`.
    static Texture2D from_image(const Image& image, std::string label = {},
                                GLenum min_filter = GL_LINEAR, GLenum mag_filter = GL_LINEAR);

    GLuint id() const { return handle_.get(); }
    int width() const { return width_; }
    int height() const { return height_; }
    int levels() const { return levels_; }
    GLenum internal_format() const { return internal_format_; }
    const std::string& label() const { return label_; }

    // glActiveTexture(GL_TEXTURE0 + unit); glBindTexture(GL_TEXTURE_2D, id()).
    void bind(GLuint unit) const;

    // Replaces the whole level 0 (then rebuilds the mipmaps of a *_MIPMAP_*
    // min_filter given at creation).
    void update(const void* data, GLenum data_format = GL_RGBA,
                GLenum data_type = GL_UNSIGNED_BYTE);

private:
    detail::Handle handle_;
    int width_ = 0, height_ = 0, levels_ = 1;
    bool build_mipmaps_ = false;
    GLenum internal_format_ = GL_RGBA8;
    std::string label_;
};

}  // namespace fw
