// Lab 8's geometry and cameras; the numbers are those of
// labs/08_texture_mapping/README.md.
#include "scenes.hpp"

#include <cstddef>
#include <glm/gtc/matrix_transform.hpp>

#include "framework/meshes.hpp"
#include "mappings.hpp"

namespace texture_mapping {

namespace {

constexpr float kNear = 0.1f, kFar = 100.0f;

}  // namespace

Mesh sphere() {
    const fw::MeshData mesh = fw::icosphere(4);
    Mesh out;
    for (std::size_t i = 0; i < mesh.positions.size(); ++i)
        out.vertices.push_back({mesh.positions[i], spherical(mesh.positions[i]), mesh.normals[i]});
    out.indices.assign(mesh.indices.begin(), mesh.indices.end());
    return out;
}

glm::mat4 sphere_view_projection() {
    const glm::mat4 view = glm::lookAt(kSphereEye, glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    return glm::perspective(glm::radians(45.0f), 1.0f, kNear, kFar) * view;
}

Mesh rectangle(glm::vec2 lo, glm::vec2 hi, glm::vec2 st_lo, glm::vec2 st_hi) {
    const glm::vec3 n(0.0f, 0.0f, 1.0f);
    return {{{{lo.x, lo.y, 0.0f}, {st_lo.x, st_lo.y}, n},
             {{hi.x, lo.y, 0.0f}, {st_hi.x, st_lo.y}, n},
             {{hi.x, hi.y, 0.0f}, {st_hi.x, st_hi.y}, n},
             {{lo.x, hi.y, 0.0f}, {st_lo.x, st_hi.y}, n}},
            {0, 1, 2, 0, 2, 3}};
}

Mesh wrap_quad() {
    return rectangle(glm::vec2(-0.9f), glm::vec2(0.9f), glm::vec2(-1.0f), glm::vec2(2.0f));
}

Mesh magnify_quad() {
    return rectangle(glm::vec2(-1.0f), glm::vec2(1.0f), glm::vec2(0.0f), glm::vec2(1.0f));
}

Mesh minify_quad() {
    const float h = 0.5f / 256.0f;
    return rectangle(glm::vec2(-0.25f), glm::vec2(0.25f), glm::vec2(h), glm::vec2(1.0f + h));
}

Mesh lightmap_quad() {
    return rectangle(glm::vec2(-0.9f), glm::vec2(0.9f), glm::vec2(0.0f), glm::vec2(1.0f));
}

Mesh floor_plane() {
    Mesh out;
    for (glm::vec3 p : {glm::vec3(-2, -1, -4), glm::vec3(2, -1, -4), glm::vec3(2, -1, -16),
                        glm::vec3(-2, -1, -16)})
        out.vertices.push_back(
            {p, {(p.x + 2.0f) / 4.0f, (-p.z - 4.0f) / 12.0f}, glm::vec3(0.0f, 1.0f, 0.0f)});
    out.indices = {0, 1, 2, 0, 2, 3};
    return out;
}

glm::mat4 floor_view_projection() {
    const glm::mat4 view = glm::lookAt(glm::vec3(0.0f, 1.5f, -1.0f), glm::vec3(0.0f, -1.0f, -9.0f),
                                       glm::vec3(0.0f, 1.0f, 0.0f));
    return glm::perspective(glm::radians(60.0f), 0.5f, kNear, kFar) * view;
}

}  // namespace texture_mapping
