// Lab 10's cube-map faces and the world they see (layers.hpp); the student
// part is cube_face_view().
#include "layers.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace advanced_geometry {

glm::mat4 cube_face_view(int face) {
    // The face's axis, and the up vector that makes the view's x and y
    // the face's s and t (table 8.19): y down for the four side faces.
    // BEGIN SOLUTION
    // STUDENT: (void)face;
    // STUDENT: return glm::mat4(1.0f);  // TODO: lookAt from the origin along the face's axis
    const glm::vec3 axis[6] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    const glm::vec3 up[6] = {{0, -1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}, {0, -1, 0}, {0, -1, 0}};
    return glm::lookAt(glm::vec3(0.0f), axis[face], up[face]);
    // END SOLUTION
}

namespace {

// The two triangles of the square with centre c and half-sides u and v.
void add_square(std::vector<glm::vec3>& out, glm::vec3 c, glm::vec3 u, glm::vec3 v) {
    out.insert(out.end(), {c - u - v, c + u - v, c + u + v, c - u - v, c + u + v, c - u + v});
}

}  // namespace

std::vector<glm::vec3> layer_world() {
    // The room's walls, then the markers: squares at +-distance on each
    // axis k, their sides along the two other axes.
    struct Squares {
        float distance, half;
    };
    std::vector<glm::vec3> out;
    for (const Squares q : {Squares{3.0f, 3.0f}, Squares{1.0f, 0.5f}})
        for (int k = 0; k < 3; ++k) {
            glm::vec3 axis(0.0f), i(0.0f), j(0.0f);
            axis[k] = q.distance;
            i[(k + 1) % 3] = q.half;
            j[(k + 2) % 3] = q.half;
            add_square(out, axis, i, j);
            add_square(out, -axis, i, j);
        }
    return out;
}

}  // namespace advanced_geometry
