// Lab 4's scene: the icosphere and the camera (labs/04_geometry/README.md,
// The scene), and the parameters that choose the mode and shape the scene.
#pragma once

#include <glad/gl.h>

#include <glm/glm.hpp>
#include <vector>

#include "framework/params.hpp"

namespace geometry {

// The values of `mode`: the lab switches on the enum; the names are what
// --set, checkpoints.json and the window's panel use.
enum class Mode { Passthrough, Duplicate, Explode, Normals, Wireframe };
constexpr fw::Choice<Mode> kModes[] = {{Mode::Passthrough, "passthrough"},
                                       {Mode::Duplicate, "duplicate"},
                                       {Mode::Explode, "explode"},
                                       {Mode::Normals, "normals"},
                                       {Mode::Wireframe, "wireframe"}};

// The finest icosphere: `subdiv` runs from 0 to kMaxSubdiv.
constexpr int kMaxSubdiv = 5;

// The lab's parameters: each named once, by its handle, for params() and draw().
constexpr fw::ParamId<Mode> kMode{"mode"};
constexpr fw::ParamId<int> kSubdiv{"subdiv"};
constexpr fw::ParamId<float> kSpin{"spin"};
constexpr fw::ParamId<float> kAmount{"amount"};
constexpr fw::ParamId<float> kOffsetX{"offset_x"};
constexpr fw::ParamId<float> kOffsetY{"offset_y"};
constexpr fw::ParamId<float> kOffsetZ{"offset_z"};
constexpr fw::ParamId<float> kLength{"length"};
std::vector<fw::Param> params();

// 24 bytes: two vec3, no padding. Read by shaders/04_geometry/mesh.vert.
struct Vertex {
    glm::vec3 position;
    glm::vec3 normal;
};

// The icosphere of radius 1, `subdiv` times subdivided: its vertices (normals
// equal to positions) and its triangles, 3 indices each, counter-clockwise
// seen from outside.
struct SphereMesh {
    std::vector<Vertex> vertices;
    std::vector<GLuint> indices;
};
SphereMesh sphere_mesh(int subdiv);

// M = rotateY(spin), spin in degrees.
glm::mat4 model_matrix(float spin);
// P V: lookAt((0,0,4), (0,0,0), (0,1,0)) seen through perspective(45 deg,
// aspect, 0.1, 100).
glm::mat4 view_projection(float aspect);

}  // namespace geometry
