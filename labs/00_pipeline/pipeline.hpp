// Lab 0's drawing steps, defined in pipeline.cpp (its student parts, each
// explained there) and used by the lab in pipeline_lab.cpp.
#pragma once

#include <string>

#include "framework/gl.hpp"
#include "scenes.hpp"

namespace pipeline {

// A vertex array reading `vertices` (Vertex structs, meshes.hpp) through
// describe_vertex_layout(), and `indices` when there are any.
fw::VertexArray make_vertex_array(const std::string& label, const fw::Buffer& vertices,
                                  const fw::Buffer* indices);

// scene=indexed: the face set's triangles from `indexed` or from `flat`.
void draw_face_set(Storage storage, const fw::VertexArray& indexed, const fw::VertexArray& flat,
                   GLsizei count);

// The depth test on (GL_LESS) or off.
void set_depth_test(bool on);

// Front faces counter-clockwise; `cull` says which faces are dropped.
void set_culling(Cull cull);

}  // namespace pipeline
