// Lab 10's layered rendering: the view of each cube-map face (cube_face_view,
// a student part the grader checks, in layers.cpp) and the small world drawn
// into all six faces at once.
#pragma once

#include <glm/glm.hpp>
#include <vector>

namespace advanced_geometry {

// The view matrix of cube-map face `face` (0 .. 5: +x, -x, +y, -y, +z, -z),
// from the origin: the eye looks along the face's axis, and the face's s and
// t directions (GL 4.3 core, table 8.19) are the view's x and y:
//   +x: s along -z, t along -y      -x: s along +z, t along -y
//   +y: s along +x, t along +z      -y: s along +x, t along -z
//   +z: s along +x, t along -y      -z: s along -x, t along -y
// that is lookAt(0, axis, up) with up (0, -1, 0) for +-x and +-z, (0, 0, 1)
// for +y and (0, 0, -1) for -y.
glm::mat4 cube_face_view(int face);

// The world the cube map sees, as triangles (three positions each, no
// indices): the room, a cube of half-size 3 around the origin (12
// triangles), then the six markers, squares of half-size 0.5 facing the
// origin at distance 1 on +x, -x, +y, -y, +z, -z (2 triangles each).
std::vector<glm::vec3> layer_world();

}  // namespace advanced_geometry
