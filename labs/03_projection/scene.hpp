// Lab 3's two scenes (see README.md for the numbers). Every object is the
// same square, [-1, 1]^2 in the plane z = 0 facing +z, placed in the world by
// its own model matrix M.
#pragma once

#include <glm/glm.hpp>
#include <string>
#include <vector>

namespace projection {

// 12 bytes: one vec3. Read by shaders/03_projection/projection.vert.
struct Vertex {
    glm::vec3 position;
};

// The square as two counter-clockwise triangles (6 vertices).
std::vector<Vertex> unit_square();

struct Object {
    std::string name;  // its colour: "red", "green", ...
    glm::mat4 model;   // M
    glm::vec3 color;
};

// scene=cards: five squares facing +z; card i has centre (u_i d_i t, 0, -d_i)
// and half-size 0.15 d_i t, t = tan(30 deg), u = (-0.8, -0.4, 0, 0.4, 0.8),
// d = (2, 4, 8, 16, 32), colours red, green, blue, yellow, magenta.
// scene=zfight: a red quad and, 0.002 behind it along its normal, a blue one
// (drawn first), both 16 x 16 and tilted by 30 degrees about x (the top
// leans away), the red one centred at (0, 0, -20).
// The `scene` parameter's values.
enum class Scene { Cards, ZFight };
std::vector<Object> scene_objects(Scene scene);

}  // namespace projection
