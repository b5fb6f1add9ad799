// Lab 7's arithmetic of the frame buffer operations, written by hand: the
// blend equation as GL computes it, and the order translucent objects are
// drawn in. Student parts (blending.cpp), kept apart from the drawing code so
// that tests and the grader can call them directly.
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "framework/names.hpp"

namespace framebuffer_ops {

// glBlendFunc's factors (GL 4.3 core, section 17.3.8, table 17.2), without
// the constant-colour ones.
enum class BlendFactor {
    Zero,
    One,
    SrcColor,
    OneMinusSrcColor,
    DstColor,
    OneMinusDstColor,
    SrcAlpha,
    OneMinusSrcAlpha,
    DstAlpha,
    OneMinusDstAlpha,
};
constexpr fw::Choice<BlendFactor> kBlendFactors[] = {
    {BlendFactor::Zero, "zero"},          {BlendFactor::One, "one"},
    {BlendFactor::SrcColor, "src_color"}, {BlendFactor::OneMinusSrcColor, "one_minus_src_color"},
    {BlendFactor::DstColor, "dst_color"}, {BlendFactor::OneMinusDstColor, "one_minus_dst_color"},
    {BlendFactor::SrcAlpha, "src_alpha"}, {BlendFactor::OneMinusSrcAlpha, "one_minus_src_alpha"},
    {BlendFactor::DstAlpha, "dst_alpha"}, {BlendFactor::OneMinusDstAlpha, "one_minus_dst_alpha"},
};

// glBlendEquation's modes (table 17.1).
enum class BlendEquation { Add, Subtract, ReverseSubtract, Min, Max };
constexpr fw::Choice<BlendEquation> kBlendEquations[] = {
    {BlendEquation::Add, "add"},
    {BlendEquation::Subtract, "subtract"},
    {BlendEquation::ReverseSubtract, "reverse_subtract"},
    {BlendEquation::Min, "min"},
    {BlendEquation::Max, "max"},
};

// What GL writes into an RGBA8 colour buffer when a fragment of colour `src`
// meets the colour `dst` already there, with glBlendFunc(src_factor,
// dst_factor) and glBlendEquation(equation): each factor is a vec4 (the
// *_COLOR factors take alpha from the same colour, the *_ALPHA ones repeat
// alpha four times), the equation combines S = src * factor_s and
// D = dst * factor_d per component (MIN and MAX ignore the factors), and the
// result is clamped to [0, 1], as a fixed-point buffer stores it.
glm::vec4 blend(glm::vec4 src, glm::vec4 dst, BlendFactor src_factor, BlendFactor dst_factor,
                BlendEquation equation);

// The indices of `centres` in the order to draw them back to front as seen
// from `eye`: the farthest (by distance from the eye) first; of two at the
// same distance, the one listed first.
std::vector<int> back_to_front(const std::vector<glm::vec3>& centres, glm::vec3 eye);
// back_to_front() for four centres: the form the grader calls (the unit
// function "back_to_front").
std::vector<int> back_to_front4(glm::vec3 eye, glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d);

}  // namespace framebuffer_ops

// The factors' and equations' names, for the grader.
template <>
struct fw::ChoicesOf<framebuffer_ops::BlendFactor> {
    static constexpr const auto& list = framebuffer_ops::kBlendFactors;
};
template <>
struct fw::ChoicesOf<framebuffer_ops::BlendEquation> {
    static constexpr const auto& list = framebuffer_ops::kBlendEquations;
};
