// Lab 12's numbers: the planar shadow matrix and the fog factor. Student
// parts (shadow_math.cpp); the lab draws with shadow_matrix(), and the grader
// checks both against its own references.
#pragma once

#include <glm/glm.hpp>

#include "framework/names.hpp"
// FOG_*: the values of u_fog_mode, shared with fog.frag.
#include "shared.glsl"

namespace shadows {

// The values of `fog`; each is the one sent to u_fog_mode (shared.glsl).
enum class Fog { None = FOG_NONE, Linear = FOG_LINEAR, Exp = FOG_EXP, Exp2 = FOG_EXP2 };
constexpr fw::Choice<Fog> kFogs[] = {
    {Fog::None, "none"}, {Fog::Linear, "linear"}, {Fog::Exp, "exp"}, {Fog::Exp2, "exp2"}};

// The matrix that flattens a point onto the ground plane y = 0 along the
// ray from `light`: a point light (x, y, z, 1) or a directional light
// (dx, dy, dz, 0), the direction towards the light. With the plane
// P = (0, 1, 0, 0): M = (P . L) I - L P^T; M p has y = 0 and, divided by its
// w, is where the ray from the light through p meets the ground.
glm::mat4 shadow_matrix(glm::vec4 light);

// The fog factor at eye-space distance d: 1 for none; linear (end - d) /
// (end - start); exp exp(-density d); exp2 exp(-(density d)^2); each clamped
// to [0, 1]. The colour is mix(fog colour, surface colour, f).
float fog_factor(Fog mode, float d, float start, float end, float density);

}  // namespace shadows

// The fog modes' names, for the grader.
template <>
struct fw::ChoicesOf<shadows::Fog> {
    static constexpr const auto& list = shadows::kFogs;
};
