// Lab 13's ray caster: a ray through each pixel centre of a 64 x 64 image,
// the nearest of the scene's triangles it meets, and a shadow ray from there
// to each light. Student parts in raycast.cpp; the loop over the pixels and
// the shading are given (raycast_image.cpp).
#pragma once

#include <glm/glm.hpp>
#include <vector>

namespace surface_detail {

// The image is kCast x kCast pixels, pixel (i, j) with centre (i + 0.5, j + 0.5).
constexpr int kCast = 64;
// The camera: lookAt(kEye, (0, 0, 0), (0, 1, 0)) and perspective(45 degrees,
// 1, 0.5, 20), as GL's image uses them; its basis u (right), v (up) and w
// (backwards, from the target to the eye), and tan(fov / 2).
const glm::vec3 kEye{0.0f, 4.5f, 4.5f};
const glm::vec3 kCamU{1.0f, 0.0f, 0.0f};
const glm::vec3 kCamV{0.0f, 0.70710678f, -0.70710678f};
const glm::vec3 kCamW{0.0f, 0.70710678f, 0.70710678f};
const float kTanHalfFov = 0.41421356f;
// How far a shadow ray starts above its surface, along the surface's normal.
constexpr float kShadowEpsilon = 1e-3f;

struct Triangle {
    glm::vec3 a, b, c;  // counter-clockwise seen from outside
    glm::vec3 color;
    glm::vec3 normal() const { return glm::normalize(glm::cross(b - a, c - a)); }
};
struct Ray {
    glm::vec3 origin, dir;
};
// The triangle a ray meets first: its index in the scene and the ray's t
// there; index -1 when it meets none.
struct Hit {
    int index = -1;
    float t = 0.0f;
};
// How many rays were cast and how many ray-triangle tests they made.
struct Counts {
    long primary = 0, shadow = 0, tests = 0;
};

// The unit direction from kEye through the centre of pixel (i, j): at NDC
// x = 2 (i + 0.5) / kCast - 1 (y alike from j), the direction x tan(fov/2) u +
// y tan(fov/2) v - w, normalised.
glm::vec3 pixel_direction(int i, int j);

// Moller-Trumbore: the t > 0 at which o + t d meets the triangle a b c
// (edges and corners included), or -1 when it does not (parallel, outside,
// or behind the origin).
float intersect_triangle(glm::vec3 o, glm::vec3 d, glm::vec3 a, glm::vec3 b, glm::vec3 c);

// One ray-triangle test, counted in `counts` (given; nearest_hit() calls it).
float test_triangle(const Ray& ray, const Triangle& tri, Counts& counts);

// The nearest triangle of `scene` the ray meets: every triangle tested once.
Hit nearest_hit(const Ray& ray, const std::vector<Triangle>& scene, Counts& counts);

// Whether anything of `scene` lies between the point p of a surface of
// normal n and the directional light `towards` (a unit vector towards the
// light): a shadow ray from p + kShadowEpsilon n, tested with nearest_hit().
bool in_shadow(glm::vec3 p, glm::vec3 n, glm::vec3 towards, const std::vector<Triangle>& scene,
               Counts& counts);

}  // namespace surface_detail
