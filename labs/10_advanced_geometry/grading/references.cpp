// Lab 10 `advanced-geometry`: the course's reference for the views of a cube
// map's faces, written from the GL specification's table of cube-map face
// selection (GL 4.3 core, table 8.19), never from the lab's code.
#include <glm/glm.hpp>

#include "framework/error.hpp"
#include "grading/units/reference.hpp"

namespace {

// Face f's s and t directions and its axis, as table 8.19 reads them: for
// +x, sc = -rz and tc = -ry, so s runs along -z and t along -y.
struct FaceAxes {
    glm::vec3 s, t, axis;
};
constexpr FaceAxes kFaces[6] = {
    {{0, 0, -1}, {0, -1, 0}, {1, 0, 0}}, {{0, 0, 1}, {0, -1, 0}, {-1, 0, 0}},
    {{1, 0, 0}, {0, 0, 1}, {0, 1, 0}},   {{1, 0, 0}, {0, 0, -1}, {0, -1, 0}},
    {{1, 0, 0}, {0, -1, 0}, {0, 0, 1}},  {{-1, 0, 0}, {0, -1, 0}, {0, 0, -1}},
};

// The view whose x, y and z axes are s, t and minus the face's axis (the
// eye at the origin looks along the axis): its rows are s, t and -axis.
glm::mat4 ref_cube_face_view(int face) {
    if (face < 0 || face > 5) throw fw::Error("cube_face_view: face must be 0 to 5");
    const FaceAxes& f = kFaces[face];
    glm::mat4 view(1.0f);
    for (int c = 0; c < 3; ++c) {
        view[c][0] = f.s[c];
        view[c][1] = f.t[c];
        view[c][2] = -f.axis[c];
    }
    return view;
}

}  // namespace

COURSE_REFERENCE(cube_face_view, &ref_cube_face_view, {grading::integer(0, 5)})
