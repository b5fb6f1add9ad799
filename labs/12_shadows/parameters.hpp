// Lab 12's parameters: each named once, by its handle, for params() and the
// lab's draw(); the choices are the enums draw() switches on.
#pragma once

#include <vector>

#include "framework/params.hpp"
#include "shadow_math.hpp"

namespace shadows {

enum class Scene { Planar, Fog, Shadowmap };
constexpr fw::Choice<Scene> kScenes[] = {
    {Scene::Planar, "planar"}, {Scene::Fog, "fog"}, {Scene::Shadowmap, "shadowmap"}};
enum class Light { Directional, Point };
constexpr fw::Choice<Light> kLights[] = {{Light::Directional, "directional"},
                                         {Light::Point, "point"}};

constexpr fw::ParamId<Scene> kScene{"scene"};
constexpr fw::ParamId<Light> kLight{"light"};
constexpr fw::ParamId<bool> kStencil{"stencil"};
constexpr fw::ParamId<float> kShadowAlpha{"shadow_alpha"};
constexpr fw::ParamId<Fog> kFog{"fog"};
constexpr fw::ParamId<float> kFogDensity{"fog_density"};
constexpr fw::ParamId<float> kFogStart{"fog_start"};
constexpr fw::ParamId<float> kFogEnd{"fog_end"};
constexpr fw::ParamId<float> kBias{"bias"};
constexpr fw::ParamId<bool> kPcf{"pcf"};

// The declaration of every parameter above, with its default, range, help
// and window key (docs/labs.md, Lab 12).
std::vector<fw::Param> params();

}  // namespace shadows
