// Lab 0's geometry; the numbers are those of README.md and docs/labs.md.
#include "meshes.hpp"

#include <cstddef>

namespace pipeline {

namespace {

const glm::vec3 kRed{1, 0, 0}, kGreen{0, 1, 0}, kBlue{0, 0, 1};
const glm::vec3 kYellow{1, 1, 0}, kCyan{0, 1, 1}, kMagenta{1, 0, 1};

// The square [lo, hi]^2 at depth z as two counter-clockwise triangles.
void add_quad(std::vector<Vertex>& out, float lo, float hi, float z, glm::vec3 color) {
    const glm::vec3 a{lo, lo, z}, b{hi, lo, z}, c{hi, hi, z}, d{lo, hi, z};
    for (glm::vec3 p : {a, b, c, a, c, d}) out.push_back({p, color});
}

}  // namespace

std::vector<Vertex> order_quads() {
    std::vector<Vertex> v;
    add_quad(v, -0.6f, 0.2f, 0.5f, kRed);    // farther: window depth 0.75
    add_quad(v, -0.2f, 0.6f, -0.5f, kBlue);  // nearer: window depth 0.25
    return v;
}

// A strip of three triangles (0-1-2, 1-4-2, 2-4-5: top row 0 2 5, bottom row
// 1 4) with a fourth hanging below (1-3-4).
std::vector<Vertex> face_set_vertices() {
    return {
        {{-0.8f, 0.5f, 0.0f}, kRed},     // 0
        {{-0.5f, -0.3f, 0.0f}, kGreen},  // 1
        {{0.0f, 0.5f, 0.0f}, kBlue},     // 2
        {{0.0f, -0.8f, 0.0f}, kYellow},  // 3
        {{0.5f, -0.3f, 0.0f}, kCyan},    // 4
        {{0.8f, 0.5f, 0.0f}, kMagenta},  // 5
    };
}

// The lecture's list, as is. Triangles 1-3 are counter-clockwise on screen;
// triangle 0 (0,2,1) is clockwise: it walks the shared edge 2->1 in the same
// direction as triangle 2 (1,4,2) does. README.md asks why that matters.
std::vector<GLuint> face_set_indices() { return {0, 2, 1, 1, 3, 4, 1, 4, 2, 2, 4, 5}; }

std::vector<Vertex> expand_indices(const std::vector<Vertex>& vertices,
                                   const std::vector<GLuint>& indices) {
    std::vector<Vertex> flat(indices.size());
    // BEGIN SOLUTION
    // STUDENT: (void)vertices;  // TODO: flat[i] is the vertex that indices[i] names
    for (std::size_t i = 0; i < indices.size(); ++i) flat[i] = vertices[indices[i]];
    // END SOLUTION
    return flat;
}

std::vector<glm::vec3> expand_quad(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
    std::vector<Vertex> vertices;
    for (const glm::vec3& p : {a, b, c, d}) vertices.push_back({p, glm::vec3(0.0f)});
    std::vector<glm::vec3> positions;
    for (const Vertex& v : expand_indices(vertices, {0, 1, 2, 0, 2, 3}))
        positions.push_back(v.position);
    return positions;
}

std::vector<Vertex> cube_vertices() {
    struct Face {
        glm::vec3 normal, color;
    };
    const Face faces[] = {{{1, 0, 0}, kRed},      {{-1, 0, 0}, kCyan}, {{0, 1, 0}, kGreen},
                          {{0, -1, 0}, kMagenta}, {{0, 0, 1}, kBlue},  {{0, 0, -1}, kYellow}};
    std::vector<Vertex> v;
    for (const Face& f : faces) {
        // Two edge directions u, v of the face with u x v = normal, so that
        // corners -u-v, +u-v, +u+v, -u+v run counter-clockwise seen from outside.
        glm::vec3 up = f.normal.y != 0.0f ? glm::vec3(0, 0, -1) : glm::vec3(0, 1, 0);
        glm::vec3 right = glm::cross(up, f.normal);
        glm::vec3 centre = 0.5f * f.normal;
        for (glm::vec2 s : {glm::vec2(-1, -1), glm::vec2(1, -1), glm::vec2(1, 1), glm::vec2(-1, 1)})
            v.push_back({centre + 0.5f * (s.x * right + s.y * up), f.color});
    }
    return v;
}

std::vector<GLuint> cube_indices() {
    std::vector<GLuint> i;
    for (GLuint face = 0; face < 6; ++face)
        for (GLuint corner : {0u, 1u, 2u, 0u, 2u, 3u}) i.push_back(4 * face + corner);
    return i;
}

}  // namespace pipeline
