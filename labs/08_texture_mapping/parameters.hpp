// Lab 8's parameters: each named once, by its handle, for params() and the
// lab's draw(); the choices are the enums draw() switches on.
#pragma once

#include <vector>

#include "framework/params.hpp"
#include "sampler_state.hpp"
// MAPPING_* and MAPS_*: the values of u_mapping and u_maps, shared with the shaders.
#include "shared.glsl"

namespace texture_mapping {

enum class Scene { Coordinates, Perspective, Wrap, Magnify, Minify, Lightmap };
constexpr fw::Choice<Scene> kScenes[] = {{Scene::Coordinates, "coordinates"},
                                         {Scene::Perspective, "perspective"},
                                         {Scene::Wrap, "wrap"},
                                         {Scene::Magnify, "magnify"},
                                         {Scene::Minify, "minify"},
                                         {Scene::Lightmap, "lightmap"}};
// Each value is the one sent to u_mapping (shared.glsl).
enum class Mapping {
    Vertex = MAPPING_VERTEX,
    Planar = MAPPING_PLANAR,
    Cylindrical = MAPPING_CYLINDRICAL,
    Spherical = MAPPING_SPHERICAL,
};
constexpr fw::Choice<Mapping> kMappings[] = {{Mapping::Vertex, "vertex"},
                                             {Mapping::Planar, "planar"},
                                             {Mapping::Cylindrical, "cylindrical"},
                                             {Mapping::Spherical, "spherical"}};
// Each value is the one sent to u_maps (shared.glsl).
enum class Maps { Base = MAPS_BASE, Light = MAPS_LIGHT, Modulate = MAPS_MODULATE };
constexpr fw::Choice<Maps> kMapsChoices[] = {
    {Maps::Base, "base"}, {Maps::Light, "light"}, {Maps::Modulate, "modulate"}};

constexpr fw::ParamId<Scene> kScene{"scene"};
constexpr fw::ParamId<Mapping> kMapping{"mapping"};
constexpr fw::ParamId<bool> kImage{"image"};
constexpr fw::ParamId<bool> kLit{"lit"};
constexpr fw::ParamId<Wrap> kWrap{"wrap"};
constexpr fw::ParamId<MagFilter> kMagFilter{"mag_filter"};
constexpr fw::ParamId<MinFilter> kMinFilter{"min_filter"};
constexpr fw::ParamId<Maps> kMaps{"maps"};

// The declaration of every parameter above, with its default, range, help
// and window key (docs/labs.md, Lab 8).
std::vector<fw::Param> params();

}  // namespace texture_mapping
