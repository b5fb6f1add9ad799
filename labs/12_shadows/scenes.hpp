// Lab 12's scenes: the meshes (in world coordinates), colours, lights and
// cameras of docs/labs.md and the lab's README, written once.
#pragma once

#include <glm/glm.hpp>
#include <vector>

namespace shadows {

struct Vertex {
    glm::vec3 position;
};
using Mesh = std::vector<Vertex>;  // triangles, three vertices each

const glm::vec4 kGroundColor{0.8f, 0.8f, 0.8f, 1.0f};
const glm::vec4 kCasterAColor{0.9f, 0.2f, 0.2f, 1.0f};
const glm::vec4 kCasterBColor{0.2f, 0.3f, 0.9f, 1.0f};
const glm::vec4 kSurfaceColor{0.9f, 0.3f, 0.1f, 1.0f};
const glm::vec3 kFogColor{0.5f, 0.6f, 0.7f};

// scene=planar: the lights, as shadow_matrix() takes them.
const glm::vec4 kDirectionalLight{1.0f, 1.0f, 0.0f, 0.0f};  // towards the light
const glm::vec4 kPointLight{2.0f, 4.0f, 0.0f, 1.0f};

// scene=shadowmap: the depth map's size in texels (each side).
constexpr int kShadowMapSize = 64;

// The ground y = 0, x and z in [-2, 2].
Mesh ground();
// Caster A: y = 1, x and z in [-0.5, 0.5]. Caster B: y = 2, x and z in [0, 1].
Mesh caster_a();
Mesh caster_b();
// scene=fog: four planes facing the eye, plane k at z = -(2 + 2k), x in
// [k - 2, k - 1], y in [-1.5, 1.5].
Mesh fog_planes();
// scene=shadowmap: a wall x = 0, y in [0, 1], z in [-0.5, 0.5].
Mesh wall();

// scene=planar and shadowmap: the camera above, looking down, with -z up
// the frame: window (128 (x + 2), 128 (2 - z)).
glm::mat4 top_view();
glm::mat4 top_projection();
// scene=fog: the eye at the origin looking down -z, orthographic.
glm::mat4 fog_projection();
// scene=shadowmap: the directional light's camera, from (2, 2, 0) towards the
// origin, orthographic; its clip space from the world.
glm::mat4 light_view_projection();

}  // namespace shadows
