// Lab 13's ray-cast picture: every pixel's nearest triangle and its shading
// with shadows (given code around the student parts of raycast.cpp).
#pragma once

#include <vector>

#include "framework/image.hpp"
#include "raycast.hpp"

namespace surface_detail {

struct CastImage {
    fw::Image color{kCast, kCast};  // the shaded picture, bottom row first
    std::vector<int> triangle;      // the nearest triangle of each pixel, -1 for none
    std::vector<bool> shadowed;     // whether some light's shadow ray was blocked there
    Counts counts;
};

// The shading of both pictures, ray-cast and GL's: albedo (0.2 + the sum over
// the lights of 0.5 max(n . l, 0)), a light counting only where it is not in
// shadow (visible[k]), clamped to [0, 1].
glm::vec3 shade(glm::vec3 albedo, glm::vec3 n, int lights, const bool* visible);

// The scene ray-cast: a primary ray per pixel, and from each hit a shadow ray
// per light (the first `lights` of kRayLights).
CastImage cast_scene(const std::vector<Triangle>& scene, int lights);

}  // namespace surface_detail
