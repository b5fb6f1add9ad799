// Lab 13's figures for scene raycast (README.md, Stats): the deck's cost
// counts and the pixel-for-pixel comparison of the ray-cast image with GL's.
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <vector>

#include "framework/image.hpp"
#include "raycast_image.hpp"

namespace surface_detail {

// `lab_stats`: "rays" {primary, shadow, total}, "intersection_tests",
// "triangles", "lights", "hits", "differ" (pixels whose nearest surface is
// not GL's: `ids` holds GL's gl_PrimitiveID + 1 in red; a surface is the
// triangles of one plane and colour, a face of the cube), "shadowed",
// "color_differ" (pixels whose colours differ by more than 2/255) and
// "color_differ_unshadowed" (of those, the pixels no shadow ray was blocked).
nlohmann::json compare_stats(const CastImage& cast, const fw::Image& gl, const fw::Image& ids,
                             const std::vector<Triangle>& scene, int lights);

}  // namespace surface_detail
