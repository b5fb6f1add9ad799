// Lab 8's sampler state and texture units, set with the GL calls the lab
// teaches. Student parts (sampler_state.cpp); texture_mapping.cpp calls them
// while drawing.
#pragma once

#include <glad/gl.h>

#include <glm/glm.hpp>

#include "framework/gl.hpp"
#include "framework/names.hpp"

namespace texture_mapping {

// The values of the `wrap` parameter: what a coordinate outside [0, 1] reads.
enum class Wrap { Repeat, MirroredRepeat, ClampToEdge, ClampToBorder };
constexpr fw::Choice<Wrap> kWraps[] = {{Wrap::Repeat, "repeat"},
                                       {Wrap::MirroredRepeat, "mirrored_repeat"},
                                       {Wrap::ClampToEdge, "clamp_to_edge"},
                                       {Wrap::ClampToBorder, "clamp_to_border"}};
// The border's colour, for CLAMP_TO_BORDER.
const glm::vec4 kBorderColor{1.0f, 0.0f, 1.0f, 1.0f};

// The values of `mag_filter` and `min_filter`.
enum class MagFilter { Nearest, Linear };
constexpr fw::Choice<MagFilter> kMagFilters[] = {{MagFilter::Nearest, "nearest"},
                                                 {MagFilter::Linear, "linear"}};
enum class MinFilter { Nearest, Linear, NearestMipmapNearest, LinearMipmapLinear };
constexpr fw::Choice<MinFilter> kMinFilters[] = {
    {MinFilter::Nearest, "nearest"},
    {MinFilter::Linear, "linear"},
    {MinFilter::NearestMipmapNearest, "nearest_mipmap_nearest"},
    {MinFilter::LinearMipmapLinear, "linear_mipmap_linear"}};

// Texture unit `unit` made active, and `texture` bound to its GL_TEXTURE_2D.
void bind_texture(GLuint unit, const fw::Texture2D& texture);

// For the texture bound to the active unit: both coordinates wrap as `wrap`
// says; CLAMP_TO_BORDER reads kBorderColor outside [0, 1].
void set_wrap(Wrap wrap);

// For the texture bound to the active unit: the magnification and
// minification filters. A mipmapped minification filter reads the levels
// below level 0, which build_mipmaps() made.
void set_filters(MinFilter min, MagFilter mag);

// The levels below `texture`'s level 0, each half the size of the one above,
// made from level 0 by glGenerateMipmap: once, after level 0 is uploaded
// (the texture must have storage for them, Texture2DDesc::levels).
void build_mipmaps(const fw::Texture2D& texture);

// scene=lightmap: the base texture on unit 0 and the light map on unit 1, and
// the program's samplers u_texture and u_light_map reading those units.
void bind_maps(const fw::Program& program, const fw::Texture2D& base, const fw::Texture2D& light);

}  // namespace texture_mapping
