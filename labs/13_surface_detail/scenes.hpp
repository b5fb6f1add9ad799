// Lab 13's scenes: the meshes, maps, colours, lights and cameras of
// docs/labs.md and the lab's README, written once.
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "environment.hpp"
#include "raycast.hpp"
#include "surface_math.hpp"

namespace surface_detail {

// scene=bump: a vertex of the squares, with its tangent frame.
struct BumpVertex {
    glm::vec3 position, normal, tangent, bitangent;
    glm::vec2 uv;
};
// Square A (x in [-3.5, -0.5]) and square B (x in [0.5, 3.5]), y in [-1.5,
// 1.5], z = 0, normal +z, two triangles each; A's u runs along +x and v along
// +y, B's u along +y and v along -x. Each vertex takes tangent_frame() of its
// triangle.
std::vector<BumpVertex> bump_squares();
// The height map, 64 x 64 texels: a dome of radius 6 texels in each 16 x 16
// cell, h = max(0, 1 - d^2 / 36), d the distance of the texel's centre from
// the cell's centre.
HeightMap height_map();
// The unit check's form of normal_map(): the normal of texel (i, j) of
// height_map() with `scale`.
glm::vec3 height_normal(int i, int j, float scale);
// scene=bump's light, the unit vector towards it (world space), and the
// shading 0.1 + 0.9 max(n . l, 0) of a white surface.
const glm::vec3 kBumpLight{-0.48f, 0.6f, 0.64f};
// scene=bump's and scene=envmap's camera: V = I, P = ortho(-4, 4, -4, 4, -1,
// 1) for bump; envmap's ortho(-2, 2, -2, 2, -1, 1).
glm::mat4 bump_projection();

// scene=envmap: the faces (environment.hpp): +x red, -x cyan, +y green, -y
// magenta, +z blue, -z yellow, each with its texel (0, 0) white.
CubeFaces cube_faces();
// The sphere's radius (centre at the origin, the camera's square [-2, 2]^2).
constexpr float kSphereRadius = 1.5f;

// scene=raycast: 15 triangles, the ground first, then the cube's 10, then
// the pyramid's 4; the lights' unit vectors towards them.
std::vector<Triangle> ray_scene();
const glm::vec3 kRayLights[2] = {{0.48f, 0.8f, 0.36f}, {-0.6f, 0.8f, 0.0f}};
// GL's camera for the same scene (raycast.hpp).
glm::mat4 ray_view_projection();

}  // namespace surface_detail
