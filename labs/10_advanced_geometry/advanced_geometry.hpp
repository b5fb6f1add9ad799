// Lab 10's clipped draw, defined in advanced_geometry.cpp (a student part,
// explained there) and used by the lab in advanced_geometry_lab.cpp.
#pragma once

#include "framework/gl.hpp"

namespace advanced_geometry {

// The sphere drawn with `sphere` (in use) cut by the plane at `angle`
// degrees and `offset` (u_plane), with clip distance 0 on for this draw only.
void draw_clipped(const fw::Program& sphere, const fw::VertexArray& mesh, GLsizei count,
                  float angle, float offset);

}  // namespace advanced_geometry
