// Lab 8's texture coordinates computed from a position, and the level of
// detail GL picks a mipmap level by: student parts (mappings.cpp), kept apart
// from the drawing code so that tests and the grader can call them directly.
#pragma once

#include <glm/glm.hpp>

namespace texture_mapping {

// The lab sheet's three mappings, for a point p in object coordinates:
//   planar:      (0.5 x + 0.5, 0.5 y + 0.5), along z onto the square [-1, 1]^2;
//   cylindrical: (atan2(x, z) / (2 pi) + 0.5, 0.5 y + 0.5), about the y axis;
//   spherical:   (atan2(x, z) / (2 pi) + 0.5, asin(y / |p|) / pi + 0.5), longitude
//                and latitude; (0.5, 0.5) at the origin, where there is no direction.
// shaders/08_texture_mapping/sphere.frag computes the same three in GLSL.
glm::vec2 planar(glm::vec3 p);
glm::vec2 cylindrical(glm::vec3 p);
glm::vec2 spherical(glm::vec3 p);

// The level of detail lambda = log2(rho) of GL 4.3 core, section 8.14.1,
// for a texture of width x height texels, from the texture coordinates'
// derivatives along the window's x (ds/dx, dt/dx) and y (ds/dy, dt/dy):
// rho = max(|(ds/dx * width, dt/dx * height)|, |(ds/dy * width, dt/dy * height)|),
// the longer of the pixel's two sides measured in texels.
float level_of_detail(glm::vec2 d_dx, glm::vec2 d_dy, int width, int height);

}  // namespace texture_mapping
