// Lab 4's scene and parameters; the numbers are those of
// labs/04_geometry/README.md.
#include "scene.hpp"

#include <cstddef>
#include <glm/gtc/matrix_transform.hpp>

#include "framework/meshes.hpp"

namespace geometry {

namespace {

// Eye on +z looking at the sphere's centre.
const glm::vec3 kEye{0.0f, 0.0f, 4.0f};
constexpr float kFovYDegrees = 45.0f, kNear = 0.1f, kFar = 100.0f;

}  // namespace

std::vector<fw::Param> params() {
    return {
        fw::Param::choice(kMode, kModes, Mode::Passthrough)
            .help("passthrough: re-emit each triangle; duplicate: add a moved, tinted copy; "
                  "explode: move each triangle along its face normal; normals: draw vertex "
                  "normals as lines; wireframe: edges from distances in the same pass")
            .key('M'),
        fw::Param::integer(kSubdiv, 2)
            .range(0, kMaxSubdiv)
            .help("subdivisions of the icosahedron: 20 * 4^subdiv triangles")
            .key('S'),
        fw::Param::number(kSpin, 0)
            .range(-180, 180)
            .step(15)
            .unit("deg")
            .help("model rotation about the y axis")
            .key('Y'),
        fw::Param::number(kAmount, 0.2)
            .range(0, 1)
            .step(0.05)
            .help("how far each triangle moves along its face normal (explode)")
            .key('A'),
        fw::Param::number(kOffsetX, 1.5)
            .range(-3, 3)
            .step(0.25)
            .help("x of the copy's offset in object space (duplicate)")
            .key('X'),
        fw::Param::number(kOffsetY, 0)
            .range(-3, 3)
            .step(0.25)
            .help("y (up) of the copy's offset in object space (duplicate)")
            .key('U'),
        fw::Param::number(kOffsetZ, -1.5)
            .range(-3, 3)
            .step(0.25)
            .help("z of the copy's offset in object space (duplicate)")
            .key('Z'),
        fw::Param::number(kLength, 0.15)
            .range(0, 0.5)
            .step(0.05)
            .help("length of each normal line (normals)")
            .key('L'),
    };
}

SphereMesh sphere_mesh(int subdiv) {
    const fw::MeshData data = fw::icosphere(subdiv);
    SphereMesh mesh;
    for (std::size_t v = 0; v < data.positions.size(); ++v)
        mesh.vertices.push_back({data.positions[v], data.normals[v]});
    mesh.indices = data.indices;
    return mesh;
}

glm::mat4 model_matrix(float spin) {
    return glm::rotate(glm::mat4(1.0f), glm::radians(spin), {0.0f, 1.0f, 0.0f});
}

glm::mat4 view_projection(float aspect) {
    return glm::perspective(glm::radians(kFovYDegrees), aspect, kNear, kFar) *
           glm::lookAt(kEye, glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
}

}  // namespace geometry
