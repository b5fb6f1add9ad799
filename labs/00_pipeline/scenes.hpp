// Lab 0's scenes as the parameters choose them (labs/00_pipeline/README.md,
// The scenes): the choices, the parameters, and the culling scene's camera.
#pragma once

#include <glad/gl.h>

#include <glm/glm.hpp>
#include <vector>

#include "framework/params.hpp"

namespace pipeline {

// The parameters' choices. Each enum is what draw() switches on; the names
// are what --set, checkpoints.json and the window's panel use.
enum class Scene { Order, Indexed, Primitives, Culling };
constexpr fw::Choice<Scene> kScenes[] = {{Scene::Order, "order"},
                                         {Scene::Indexed, "indexed"},
                                         {Scene::Primitives, "primitives"},
                                         {Scene::Culling, "culling"}};
enum class First { Red, Blue };
constexpr fw::Choice<First> kFirsts[] = {{First::Red, "red"}, {First::Blue, "blue"}};
enum class Storage { Indexed, Flat };
constexpr fw::Choice<Storage> kStorages[] = {{Storage::Indexed, "indexed"},
                                             {Storage::Flat, "flat"}};
// Each value is the GL primitive mode itself.
enum class Primitive : GLenum {
    Points = GL_POINTS,
    Lines = GL_LINES,
    LineStrip = GL_LINE_STRIP,
    LineLoop = GL_LINE_LOOP,
    Triangles = GL_TRIANGLES,
    TriangleStrip = GL_TRIANGLE_STRIP,
    TriangleFan = GL_TRIANGLE_FAN,
};
constexpr fw::Choice<Primitive> kPrimitives[] = {
    {Primitive::Points, "points"},
    {Primitive::Lines, "lines"},
    {Primitive::LineStrip, "line_strip"},
    {Primitive::LineLoop, "line_loop"},
    {Primitive::Triangles, "triangles"},
    {Primitive::TriangleStrip, "triangle_strip"},
    {Primitive::TriangleFan, "triangle_fan"},
};
enum class Cull { None, Back, Front };
constexpr fw::Choice<Cull> kCulls[] = {
    {Cull::None, "none"}, {Cull::Back, "back"}, {Cull::Front, "front"}};

// The lab's parameters: each named once, by its handle, for params() and draw().
constexpr fw::ParamId<Scene> kScene{"scene"};
constexpr fw::ParamId<bool> kDepthTest{"depth_test"};
constexpr fw::ParamId<First> kFirst{"first"};
constexpr fw::ParamId<Storage> kStorage{"storage"};
constexpr fw::ParamId<Primitive> kPrimitive{"primitive"};
constexpr fw::ParamId<Cull> kCull{"cull"};
constexpr fw::ParamId<float> kYaw{"yaw"};
constexpr fw::ParamId<float> kPitch{"pitch"};
std::vector<fw::Param> params();

// scene=culling: P * V * M, the camera on the +z axis looking at the cube's
// centre and M = rotateX(pitch) * rotateY(yaw), angles in degrees.
glm::mat4 cube_mvp(float yaw, float pitch, float aspect);

// An angle in degrees brought into [-180, 180] by whole turns.
float wrap_degrees(float a);

}  // namespace pipeline
