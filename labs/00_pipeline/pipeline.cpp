// Lab 0's drawing steps, the student parts (marked TODO) of the lab in
// pipeline_lab.cpp: describe_vertex_layout(), draw_face_set(),
// set_depth_test() and set_culling().
#include "pipeline.hpp"

#include <cstddef>

#include "meshes.hpp"
// A_POSITION, A_COLOR: attribute locations, shared with pipeline.vert.
#include "shared.glsl"

namespace pipeline {

namespace {

// With the vertex array bound: where each vertex's attributes are in
// `vertices`, a buffer of Vertex structs (meshes.hpp: position, then colour,
// 24 bytes a vertex). For each attribute, at its location (A_POSITION,
// A_COLOR): how many floats, the stride between vertices and the offset of
// the member in the struct; then enable it. glVertexAttribPointer reads from
// the buffer bound to GL_ARRAY_BUFFER when it is called.
void describe_vertex_layout(const fw::Buffer& vertices) {
    // BEGIN SOLUTION
    // STUDENT: (void)vertices;  // TODO: glBindBuffer(GL_ARRAY_BUFFER, vertices.id()), then for
    // STUDENT: // each attribute glVertexAttribPointer and glEnableVertexAttribArray
    glBindBuffer(GL_ARRAY_BUFFER, vertices.id());
    glVertexAttribPointer(A_POSITION, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                          reinterpret_cast<const void*>(offsetof(Vertex, position)));
    glEnableVertexAttribArray(A_POSITION);
    glVertexAttribPointer(A_COLOR, 3, GL_FLOAT, GL_FALSE, sizeof(Vertex),
                          reinterpret_cast<const void*>(offsetof(Vertex, color)));
    glEnableVertexAttribArray(A_COLOR);
    // END SOLUTION
}

}  // namespace

// scene=indexed: the face set's 4 triangles, from `indexed` (6 vertices and
// `count` = 12 indices, GL_UNSIGNED_INT, in its element buffer) or from
// `flat` (the `count` vertices the indices expand to). Bind the vertex array
// the storage names, then draw triangles: glDrawElements reads the indices,
// glDrawArrays reads the vertices in order.
void draw_face_set(Storage storage, const fw::VertexArray& indexed, const fw::VertexArray& flat,
                   GLsizei count) {
    // BEGIN SOLUTION
    // STUDENT: (void)storage, (void)indexed, (void)flat, (void)count;
    // STUDENT: // TODO: glBindVertexArray, then glDrawElements (indexed) or glDrawArrays (flat)
    if (storage == Storage::Indexed) {
        glBindVertexArray(indexed.id());
        glDrawElements(GL_TRIANGLES, count, GL_UNSIGNED_INT, nullptr);
    } else {
        glBindVertexArray(flat.id());
        glDrawArrays(GL_TRIANGLES, 0, count);
    }
    // END SOLUTION
}

// On: of the fragments that land on one pixel, the one with the smallest
// depth is kept (GL_LESS), whatever the draw order. Off: every fragment is
// written and the depth buffer is left alone, so the last one drawn wins.
void set_depth_test(bool on) {
    // BEGIN SOLUTION
    // STUDENT: (void)on;  // TODO: if on: glEnable(GL_DEPTH_TEST), glDepthFunc(GL_LESS); else off
    if (on) {
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
    } else {
        glDisable(GL_DEPTH_TEST);
    }
    // END SOLUTION
}

// A triangle whose vertices run counter-clockwise on screen is a front face
// (the cube's faces are CCW seen from outside); Cull::Back drops the faces
// turned away from the eye, Cull::Front the faces turned towards it.
void set_culling(Cull cull) {
    // BEGIN SOLUTION
    // STUDENT: (void)cull;  // TODO: glFrontFace; unless Cull::None, glEnable(GL_CULL_FACE),
    // STUDENT: // and glCullFace
    glFrontFace(GL_CCW);
    if (cull == Cull::None) {
        glDisable(GL_CULL_FACE);
    } else {
        glEnable(GL_CULL_FACE);
        glCullFace(cull == Cull::Front ? GL_FRONT : GL_BACK);
    }
    // END SOLUTION
}

// A vertex array reading `vertices` through the layout that
// describe_vertex_layout() gives, and `indices` when there are any.
fw::VertexArray make_vertex_array(const std::string& label, const fw::Buffer& vertices,
                                  const fw::Buffer* indices) {
    fw::VertexArray vao = fw::VertexArray::blank(label);
    glBindVertexArray(vao.id());
    describe_vertex_layout(vertices);
    // The element array binding is part of the bound vertex array's state:
    // binding the indices now attaches them to this vertex array.
    if (indices) glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, indices->id());
    glBindVertexArray(0);
    return vao;
}

}  // namespace pipeline
