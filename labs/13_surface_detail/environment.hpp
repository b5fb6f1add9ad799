// Lab 13's cube map: the student part that puts the six face images into the
// cube map's six faces (environment.cpp).
#pragma once

#include <array>

#include "framework/gl.hpp"

namespace surface_detail {

// The six faces in GL's order, +x, -x, +y, -y, +z, -z (the order of
// GL_TEXTURE_CUBE_MAP_POSITIVE_X + face), each kFaceSize x kFaceSize, row 0
// at t = 0 (the order glTexSubImage2D takes).
constexpr int kFaceSize = 2;
using CubeFaces = std::array<fw::Image, 6>;

// Uploads face f of `faces` into face f of `cube` (GL_RGBA, GL_UNSIGNED_BYTE).
void upload_cube_faces(const fw::TextureCube& cube, const CubeFaces& faces);

}  // namespace surface_detail
