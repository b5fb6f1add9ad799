// Lab 6's parameters: the choices draw() switches on and each parameter's
// id, named once (labs/06_interpolation/README.md lists them).
#pragma once

#include <cctype>
#include <glm/glm.hpp>
#include <string>

#include "framework/lab.hpp"
// The QUALIFIER_* and SHADING_* values of u_qualifier and u_shading.
#include "shared.glsl"

namespace interpolation {

// The parameters' choices. Each enum is what draw() switches on; the names
// are what --set, checkpoints.json and the window's panel use.
enum class Scene { Triangle, Plane, Shading };
constexpr fw::Choice<Scene> kScenes[] = {
    {Scene::Triangle, "triangle"}, {Scene::Plane, "plane"}, {Scene::Shading, "shading"}};
// Each value is the one sent to u_qualifier (shared.glsl).
enum class Qualifier {
    Smooth = QUALIFIER_SMOOTH,
    Noperspective = QUALIFIER_NOPERSPECTIVE,
    Flat = QUALIFIER_FLAT,
};
constexpr fw::Choice<Qualifier> kQualifiers[] = {{Qualifier::Smooth, "smooth"},
                                                 {Qualifier::Noperspective, "noperspective"},
                                                 {Qualifier::Flat, "flat"}};
// Each value is the one sent to u_shading (shared.glsl).
enum class Shading { Gouraud = SHADING_GOURAUD, Phong = SHADING_PHONG, Toon = SHADING_TOON };
constexpr fw::Choice<Shading> kShadings[] = {
    {Shading::Gouraud, "gouraud"}, {Shading::Phong, "phong"}, {Shading::Toon, "toon"}};

// The lab's parameters, each named once.
constexpr fw::ParamId<Scene> kScene{"scene"};
constexpr fw::ParamId<Qualifier> kQualifier{"qualifier"};
constexpr fw::ParamId<glm::vec3> kColorA{"color_a"};
constexpr fw::ParamId<glm::vec3> kColorB{"color_b"};
constexpr fw::ParamId<glm::vec3> kColorC{"color_c"};
constexpr fw::ParamId<int> kChecks{"checks"};
constexpr fw::ParamId<Shading> kShading{"shading"};
constexpr fw::ParamId<int> kSubdiv{"subdiv"};
constexpr fw::ParamId<float> kLightX{"light_x"};
constexpr fw::ParamId<float> kLightY{"light_y"};
constexpr fw::ParamId<float> kLightZ{"light_z"};

// The light's coordinates, in world units; on_drag clamps them to this range.
constexpr float kLightRange = 10.0f;
inline fw::Param light_coordinate(fw::ParamId<float> id, char axis, double def) {
    return fw::Param::number(id, def)
        .range(-kLightRange, kLightRange)
        .step(0.5)
        .help(std::string("the point light's ") + axis + " (shading)")
        .key(std::toupper(axis));
}

}  // namespace interpolation
