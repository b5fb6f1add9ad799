// Lab 6's geometry and cameras; the numbers are those of labs/06_interpolation/README.md.
#include "scenes.hpp"

#include <cstddef>
#include <glm/gtc/matrix_transform.hpp>

#include "framework/meshes.hpp"

namespace interpolation {

namespace {

constexpr float kNear = 0.1f, kFar = 100.0f;

// scene=plane: the floor's texture coordinates, u across and v away from the
// eye, both 0 at the near left corner and 1 at the far right one.
glm::vec3 floor_uv(glm::vec3 p) { return {(p.x + 2.0f) / 4.0f, (-p.z - 4.0f) / 12.0f, 0.0f}; }

}  // namespace

std::vector<Vertex> triangle_vertices(glm::vec3 color_a, glm::vec3 color_b, glm::vec3 color_c) {
    return {
        {{-0.8f, -0.8f, 0.0f}, color_a},  // A
        {{0.8f, -0.8f, 0.0f}, color_b},   // B
        {{0.0f, 0.8f, 0.0f}, color_c},    // C, the provoking vertex
    };
}

std::vector<Vertex> plane_vertices() {
    std::vector<Vertex> v;
    for (glm::vec3 p : {glm::vec3(-2, -1, -4), glm::vec3(2, -1, -4), glm::vec3(2, -1, -16),
                        glm::vec3(-2, -1, -16)})
        v.push_back({p, floor_uv(p)});
    return v;
}

// Vertex 2 provokes the first triangle and vertex 3 the second: flat shading
// gives them the uv of the far corners, (1, 1) and (0, 1).
std::vector<GLuint> plane_indices() { return {0, 1, 2, 0, 2, 3}; }

glm::mat4 plane_view_projection(float aspect) {
    const glm::mat4 view = glm::lookAt(glm::vec3(0.0f, 1.5f, -1.0f), glm::vec3(0.0f, -1.0f, -9.0f),
                                       glm::vec3(0.0f, 1.0f, 0.0f));
    return glm::perspective(glm::radians(60.0f), aspect, kNear, kFar) * view;
}

SphereMesh sphere_mesh(int subdiv) {
    const fw::MeshData mesh = fw::icosphere(subdiv);
    SphereMesh out;
    for (std::size_t i = 0; i < mesh.positions.size(); ++i)
        out.vertices.push_back({mesh.positions[i], mesh.normals[i]});
    out.indices.assign(mesh.indices.begin(), mesh.indices.end());
    return out;
}

glm::mat4 sphere_view_projection(float aspect) {
    const glm::mat4 view = glm::lookAt(kSphereEye, glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    return glm::perspective(glm::radians(45.0f), aspect, kNear, kFar) * view;
}

}  // namespace interpolation
