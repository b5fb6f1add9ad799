// Lab 0's geometry, as plain vertex lists (see README.md for the numbers).
// Every vertex carries its own colour; positions of the first three meshes
// are already in NDC, so they are drawn with the identity matrix.
#pragma once

#include <glad/gl.h>

#include <glm/glm.hpp>
#include <vector>

namespace pipeline {

// 24 bytes: two vec3, no padding. Read by shaders/00_pipeline/pipeline.vert.
struct Vertex {
    glm::vec3 position;
    glm::vec3 color;
};

// scene=order: 12 vertices, the red quad's two triangles (vertices 0-5), then
// the blue quad's (vertices 6-11).
constexpr GLint kRedQuadFirst = 0;
constexpr GLint kBlueQuadFirst = 6;
constexpr GLsizei kQuadVertices = 6;
std::vector<Vertex> order_quads();

// scene=indexed and scene=primitives: the lecture's indexed face set.
std::vector<Vertex> face_set_vertices();  // 6 vertices, one colour each
std::vector<GLuint> face_set_indices();   // {0,2,1, 1,3,4, 1,4,2, 2,4,5}

// storage=flat: the vertex list that `indices` expands to, one vertex per
// index (12 for the face set). A student part.
std::vector<Vertex> expand_indices(const std::vector<Vertex>& vertices,
                                   const std::vector<GLuint>& indices);

// Unit check `expand_quad` (checkpoints.json): the quad a b c d as the
// triangles (a, b, c) and (a, c, d), 4 vertices and 6 indices that
// expand_indices() turns into 6 positions; course compares them with its own.
std::vector<glm::vec3> expand_quad(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d);

// scene=culling: the cube [-0.5, 0.5]^3, 4 vertices per face (24) so that
// each face has its own colour, and 36 indices, every face counter-clockwise
// seen from outside. Face order and colours: +x red, -x cyan, +y green,
// -y magenta, +z blue, -z yellow.
std::vector<Vertex> cube_vertices();
std::vector<GLuint> cube_indices();

}  // namespace pipeline
