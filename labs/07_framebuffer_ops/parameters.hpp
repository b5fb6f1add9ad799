// Lab 7's parameters: each named once, by its handle, for params() and the
// lab's draw(); the choices are the enums draw() switches on.
#pragma once

#include <vector>

#include "fragment_state.hpp"
#include "framework/params.hpp"
// PATTERN_*: the values of u_pattern, shared with faces.frag.
#include "shared.glsl"

namespace framebuffer_ops {

enum class Scene { Blend, Sorting, Discard, Stencil, Faces, Scissor };
constexpr fw::Choice<Scene> kScenes[] = {{Scene::Blend, "blend"},     {Scene::Sorting, "sorting"},
                                         {Scene::Discard, "discard"}, {Scene::Stencil, "stencil"},
                                         {Scene::Faces, "faces"},     {Scene::Scissor, "scissor"}};
enum class First { A, B };
constexpr fw::Choice<First> kFirsts[] = {{First::A, "a"}, {First::B, "b"}};
// Each value is the one sent to u_pattern (shared.glsl).
enum class Pattern {
    Facing = PATTERN_FACING,
    Primitive = PATTERN_PRIMITIVE,
    Screen = PATTERN_SCREEN,
    Object = PATTERN_OBJECT,
};
constexpr fw::Choice<Pattern> kPatterns[] = {{Pattern::Facing, "facing"},
                                             {Pattern::Primitive, "primitive"},
                                             {Pattern::Screen, "screen"},
                                             {Pattern::Object, "object"}};

constexpr fw::ParamId<Scene> kScene{"scene"};
constexpr fw::ParamId<Mode> kMode{"mode"};
constexpr fw::ParamId<First> kFirst{"first"};
constexpr fw::ParamId<bool> kDepthWrite{"depth_write"};
constexpr fw::ParamId<bool> kSorted{"sorted"};
constexpr fw::ParamId<bool> kAlphaTest{"alpha_test"};
constexpr fw::ParamId<float> kCutoff{"cutoff"};
constexpr fw::ParamId<bool> kOutline{"outline"};
constexpr fw::ParamId<bool> kCull{"cull"};
constexpr fw::ParamId<Pattern> kPattern{"pattern"};
constexpr fw::ParamId<bool> kScissor{"scissor"};

// The declaration of every parameter above, with its default, range, help
// and window key (docs/labs.md, Lab 7).
std::vector<fw::Param> params();

}  // namespace framebuffer_ops
