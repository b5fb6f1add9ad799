// Lab 8's textures, made texel by texel so that every lookup has an exact
// expected colour (labs/08_texture_mapping/README.md, The textures), and the
// one image read from a file.
#pragma once

#include <glm/glm.hpp>
#include <string>

#include "framework/image.hpp"

namespace texture_mapping {

// A colour in [0, 1] as the 8 bits an RGBA8 texel stores: round(255 v).
fw::Rgba8 texel(glm::vec3 color);

// scene=coordinates: 16 x 8 texels, (i, j) light (0.9, 0.9, 0.9) where i + j
// is even, else red (0.8, 0.2, 0.1): one cell per texel.
const glm::vec3 kCheckLight{0.9f, 0.9f, 0.9f}, kCheckRed{0.8f, 0.2f, 0.1f};
fw::Image sphere_checker();
// scene=perspective: 8 x 8 texels, light 0.9 where i + j is even, dark 0.1.
fw::Image floor_checker();
// scenes wrap and magnify: 4 x 4 texels, (i, j) = ((2i + 1) / 8, (2j + 1) / 8, 0.25).
fw::Image ramp();
// scene=minify: 256 x 256 texels, white where i + j is even, black elsewhere.
fw::Image fine_checker();
// scene=lightmap: the base, 8 x 8 texels, (0.9, 0.7, 0.3) where i + j is
// even, else (0.5, 0.3, 0.1); the light map, 16 x 16 grey texels,
// max(0.15, 1 - 1.5 d) with d the distance from the texel's centre
// ((i + 0.5) / 16, (j + 0.5) / 16) to (0.5, 0.5).
const glm::vec3 kBaseLight{0.9f, 0.7f, 0.3f}, kBaseDark{0.5f, 0.3f, 0.1f};
fw::Image base_texture();
fw::Image light_map();

// The image file `path` (PNG, JPEG, ... as stb_image reads them) as RGBA8
// texels, row 0 the bottom row (t = 0), as glTexImage2D takes them; throws
// fw::Error naming the file when it cannot be read.
fw::Image load_image(const std::string& path);

}  // namespace texture_mapping
