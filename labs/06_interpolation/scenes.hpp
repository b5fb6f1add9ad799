// Lab 6's geometry and cameras, with the numbers of labs/06_interpolation/README.md.
#pragma once

#include <glad/gl.h>

#include <glm/glm.hpp>
#include <vector>

namespace interpolation {

// scene=triangle and scene=plane: a position and the value the rasterizer
// interpolates (a colour, or the texture coordinates (u, v, 0)). Read by
// shaders/06_interpolation/interpolate.vert.
struct Vertex {
    glm::vec3 position;
    glm::vec3 value;
};

// scene=shading: a point of the sphere and its unit normal. Read by
// shaders/06_interpolation/shading.vert.
struct SurfaceVertex {
    glm::vec3 position;
    glm::vec3 normal;
};

// scene=triangle: A (-0.8, -0.8), B (0.8, -0.8), C (0, 0.8) in NDC, in that
// order, so C is the provoking (last) vertex of the one triangle.
std::vector<Vertex> triangle_vertices(glm::vec3 color_a, glm::vec3 color_b, glm::vec3 color_c);

// scene=plane: the floor y = -1, x in [-2, 2], z in [-16, -4], corners
// (-2,-1,-4), (2,-1,-4), (2,-1,-16), (-2,-1,-16) with
// uv = ((x + 2) / 4, (-z - 4) / 12), and the triangles (0,1,2), (0,2,3).
std::vector<Vertex> plane_vertices();
std::vector<GLuint> plane_indices();
glm::mat4 plane_view_projection(float aspect);

// scene=shading: the icosphere of radius 1, `subdiv` times subdivided, and
// its camera at (0, 0, 3) looking at the origin.
struct SphereMesh {
    std::vector<SurfaceVertex> vertices;
    std::vector<GLuint> indices;
};
SphereMesh sphere_mesh(int subdiv);
const glm::vec3 kSphereEye{0.0f, 0.0f, 3.0f};
glm::mat4 sphere_view_projection(float aspect);

}  // namespace interpolation
