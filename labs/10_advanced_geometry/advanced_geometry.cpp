// Lab 10 `advanced-geometry`: one draw, many results.
//
// Teaches: instancing (one draw of many copies, each placed by gl_InstanceID
// and coloured by an attribute that advances once per instance); a user clip
// plane (gl_ClipDistance); layered rendering (one draw into all six faces of
// a cube map, the face chosen by the geometry shader's gl_Layer, each with
// its own view); adjacency primitives (a geometry shader that sees a
// triangle's neighbours and draws a mesh's silhouette).
// Lecture: the vertex shader's built-ins gl_InstanceID and gl_ClipDistance;
// the geometry stage's inputs (triangles_adjacency: 6 vertices) and outputs
// (line_strip, gl_Layer, gl_ViewportIndex); layered rendering into a cube
// map's 6 layers; the primitive types GL_TRIANGLES_ADJACENCY.
// GL: glBindBuffer, glVertexAttribPointer, glEnableVertexAttribArray,
// glVertexAttribDivisor, glDrawElementsInstanced, glDrawArraysInstanced;
// glEnable and glDisable of GL_CLIP_DISTANCE0; glBindFramebuffer and
// glViewport around the draw into a fw::CubeFramebuffer (a cube map attached
// whole, as layers, by the framework), a samplerCube; glDrawElements with
// GL_TRIANGLES_ADJACENCY; glBindVertexArray, glDrawArrays, glDrawElements.
// Student parts (marked TODO): draw_instances() in instances.cpp,
// draw_clipped() below, cube_face_view() in layers.cpp, adjacency_indices()
// in silhouette.cpp; the instance's cell in shaders/10_advanced_geometry/
// grid.vert, the clip distance in sphere.vert, the six faces in layers.geom
// and the outline in silhouette.geom. The lab itself (its scenes drawn with
// these, and what its frames report) is in advanced_geometry_lab.cpp.
#include "advanced_geometry.hpp"

#include <cmath>

namespace advanced_geometry {

namespace {

constexpr const char* kPlaneUniform = "u_plane";  // sphere.vert

}  // namespace

// Draws the sphere with `sphere` (in use, its projection set) cut by the
// plane (n, d): n at `angle` degrees from +x towards +y in the xy plane,
// d = `offset`. Clip distance 0 is on for this draw only: the next draw's
// shaders may not write gl_ClipDistance[0], and a distance that is not
// enabled is ignored (GL 4.3 core, 13.5).
void draw_clipped(const fw::Program& sphere, const fw::VertexArray& mesh, GLsizei count,
                  float angle, float offset) {
    glBindVertexArray(mesh.id());
    // BEGIN SOLUTION
    // STUDENT: (void)sphere, (void)angle, (void)offset;  // TODO: set u_plane to (n, d), then
    // STUDENT: // draw with GL_CLIP_DISTANCE0 on: glEnable before, glDisable after
    // STUDENT: glDrawElements(GL_TRIANGLES, count, GL_UNSIGNED_INT, nullptr);
    const float a = glm::radians(angle);
    sphere.set_if_active(kPlaneUniform, glm::vec4(std::cos(a), std::sin(a), 0.0f, offset));
    glEnable(GL_CLIP_DISTANCE0);
    glDrawElements(GL_TRIANGLES, count, GL_UNSIGNED_INT, nullptr);
    glDisable(GL_CLIP_DISTANCE0);
    // END SOLUTION
}

}  // namespace advanced_geometry
