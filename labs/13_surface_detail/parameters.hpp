// Lab 13's parameters: each named once, by its handle, for params() and the
// lab's draw(); the choices are the enums draw() switches on.
#pragma once

#include <vector>

#include "framework/params.hpp"
// NORMALS_*, ENV_*: the values the shaders take, shared with them.
#include "shared.glsl"

namespace surface_detail {

enum class Scene { Bump, Envmap, Raycast };
constexpr fw::Choice<Scene> kScenes[] = {
    {Scene::Bump, "bump"}, {Scene::Envmap, "envmap"}, {Scene::Raycast, "raycast"}};
enum class Normals { Bumped = NORMALS_BUMPED, Interpolated = NORMALS_INTERPOLATED };
constexpr fw::Choice<Normals> kNormals[] = {{Normals::Bumped, "bumped"},
                                            {Normals::Interpolated, "interpolated"}};
enum class Env {
    Fresnel = ENV_FRESNEL,
    Reflect = ENV_REFLECT,
    Refract = ENV_REFRACT,
    Normal = ENV_NORMAL
};
constexpr fw::Choice<Env> kEnvs[] = {{Env::Fresnel, "fresnel"},
                                     {Env::Reflect, "reflect"},
                                     {Env::Refract, "refract"},
                                     {Env::Normal, "normal"}};
enum class View { Split, Cpu, Gl, Difference };
constexpr fw::Choice<View> kViews[] = {
    {View::Split, "split"}, {View::Cpu, "cpu"}, {View::Gl, "gl"}, {View::Difference, "difference"}};
enum class Lights { One = 1, Two = 2 };
constexpr fw::Choice<Lights> kLights[] = {{Lights::One, "one"}, {Lights::Two, "two"}};

constexpr fw::ParamId<Scene> kScene{"scene"};
constexpr fw::ParamId<Normals> kNormalsParam{"normals"};
constexpr fw::ParamId<float> kBumpScale{"bump_scale"};
constexpr fw::ParamId<Env> kEnv{"env"};
constexpr fw::ParamId<float> kIor{"ior"};
constexpr fw::ParamId<View> kView{"view"};
constexpr fw::ParamId<Lights> kLightsParam{"lights"};

// The declaration of every parameter above, with its default, range, help
// and window key (docs/labs.md, Lab 13).
std::vector<fw::Param> params();

}  // namespace surface_detail
