// Lab 10's clipped draw, draw_clipped(): a student part (marked TODO) of the
// lab in advanced_geometry_lab.cpp.
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
