// Lab 8's geometry and cameras, with the numbers of
// labs/08_texture_mapping/README.md.
#pragma once

#include <glad/gl.h>

#include <glm/glm.hpp>
#include <vector>

namespace texture_mapping {

// A position, texture coordinates and a normal; read by
// shaders/08_texture_mapping/textured.vert.
struct Vertex {
    glm::vec3 position;
    glm::vec2 uv;
    glm::vec3 normal;
};

struct Mesh {
    std::vector<Vertex> vertices;
    std::vector<GLuint> indices;
};

// scene=coordinates: the unit icosphere subdivided 4 times (5120
// triangles), each vertex's (s, t) from spherical() (mappings.cpp), seen from
// (0, 0, 3), 45 degrees; lit by a directional light towards (1, 1, 1).
Mesh sphere();
const glm::vec3 kSphereEye{0.0f, 0.0f, 3.0f};
glm::mat4 sphere_view_projection();
const glm::vec3 kLightDirection = glm::normalize(glm::vec3(1.0f, 1.0f, 1.0f));
constexpr float kKa = 0.2f, kKd = 0.8f;

// A rectangle [x0, x1] x [y0, y1] at z = 0 (NDC) with (s, t) running from
// (s0, t0) at its lower left corner to (s1, t1) at its upper right one, as
// the triangles (0, 1, 2), (0, 2, 3).
Mesh rectangle(glm::vec2 lo, glm::vec2 hi, glm::vec2 st_lo, glm::vec2 st_hi);
// scene=wrap: [-0.9, 0.9]^2 with (s, t) from (-1, -1) to (2, 2).
Mesh wrap_quad();
// scene=magnify: the whole frame, (s, t) from (0, 0) to (1, 1).
Mesh magnify_quad();
// scene=minify: [-0.25, 0.25]^2 (128 x 128 pixels) with (s, t) from
// (h, h) to (1 + h, 1 + h), h = half a texel of the 256-texel texture.
Mesh minify_quad();
// scene=lightmap: [-0.9, 0.9]^2, (s, t) from (0, 0) to (1, 1).
Mesh lightmap_quad();

// scene=perspective: the floor y = -1, x in [-2, 2], z in [-16, -4], corners
// (-2,-1,-4), (2,-1,-4), (2,-1,-16), (-2,-1,-16) with
// (s, t) = ((x + 2) / 4, (-z - 4) / 12), the triangles (0,1,2), (0,2,3);
// seen in each half of the frame (aspect 1/2) from (0, 1.5, -1) looking at
// (0, -1, -9), 60 degrees.
Mesh floor_plane();
glm::mat4 floor_view_projection();

}  // namespace texture_mapping
