// fw::TextureCube, a cube-map texture of immutable size (glTexStorage2D on
// GL_TEXTURE_CUBE_MAP), and fw::CubeFramebuffer, which renders into all six
// faces at once: its colour and depth cube maps are attached whole
// (glFramebufferTexture), so the framebuffer is layered and a geometry
// shader picks each primitive's face with gl_Layer.
//
//   fw::CubeFramebuffer cube({128, "environment"});
//   cube.bind();  // viewport 128x128; glClear clears all six faces
//   ... draw through a geometry shader that writes gl_Layer = face ...
//   cube.color_texture().bind(0);  // a samplerCube reads unit 0
//
// Faces are numbered as GL numbers the layers of a cube map (GL 4.3 core,
// table 9.3): 0 +x, 1 -x, 2 +y, 3 -y, 4 +z, 5 -z, the order of
// GL_TEXTURE_CUBE_MAP_POSITIVE_X + face.
#pragma once

#include <glad/gl.h>

#include <string>

#include "framework/gl/handle.hpp"
#include "framework/image.hpp"

namespace fw {

struct TextureCubeDesc {
    int size = 0;                       // required: each face is size x size, 1 .. the GL limit
    GLenum internal_format = GL_RGBA8;  // sized: GL_RGBA8, GL_DEPTH_COMPONENT32F, ...
    GLenum min_filter = GL_LINEAR;      // one level: no *_MIPMAP_* filter
    GLenum mag_filter = GL_LINEAR;
    std::string label;
};

class TextureCube {
public:
    TextureCube() = default;
    // Throws UsageError naming the field and the label for a size outside 1 ..
    // GL_MAX_CUBE_MAP_TEXTURE_SIZE, an unsized format or a mipmap filter.
    explicit TextureCube(const TextureCubeDesc& desc);

    GLuint id() const { return handle_.get(); }
    int size() const { return size_; }
    GLenum internal_format() const { return internal_format_; }
    const std::string& label() const { return label_; }

    // glActiveTexture(GL_TEXTURE0 + unit); glBindTexture(GL_TEXTURE_CUBE_MAP, id()).
    void bind(GLuint unit) const;

    // Face `face` (0 .. 5) of a colour cube map, row 0 at t = 0 (glGetTexImage's order).
    Image read_face(int face) const;

private:
    detail::Handle handle_;
    int size_ = 0;
    GLenum internal_format_ = GL_RGBA8;
    std::string label_;
};

struct CubeFramebufferDesc {
    int size = 0;       // required: each face is size x size
    std::string label;  // default "cube framebuffer N"
};

class CubeFramebuffer {
public:
    CubeFramebuffer() = default;
    // An RGBA8 colour cube map and a DEPTH_COMPONENT32F depth cube map, both
    // layered attachments. Throws UsageError for a bad size (as TextureCube)
    // and fw::Error if GL reports the framebuffer incomplete.
    explicit CubeFramebuffer(const CubeFramebufferDesc& desc);

    GLuint id() const { return handle_.get(); }
    int size() const { return color_.size(); }
    const std::string& label() const { return label_; }
    const TextureCube& color_texture() const { return color_; }
    const TextureCube& depth_texture() const { return depth_; }

    // glBindFramebuffer(GL_FRAMEBUFFER, id()) and glViewport(0, 0, size, size).
    void bind() const;

private:
    detail::Handle handle_;
    TextureCube color_, depth_;
    std::string label_;
};

}  // namespace fw
