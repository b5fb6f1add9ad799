// Lab 7's per-fragment state, set with the GL calls the lab teaches: the
// blend modes, depth writes, the stencil passes and the scissor. Student
// parts (fragment_state.cpp); framebuffer_ops.cpp calls them while drawing.
#pragma once

#include <glm/glm.hpp>

#include "framework/names.hpp"

namespace framebuffer_ops {

// The values of the `mode` parameter: how scene blend combines its squares.
enum class Mode { None, Over, Additive, Multiply, Premultiplied };
constexpr fw::Choice<Mode> kModes[] = {{Mode::None, "none"},
                                       {Mode::Over, "over"},
                                       {Mode::Additive, "additive"},
                                       {Mode::Multiply, "multiply"},
                                       {Mode::Premultiplied, "premultiplied"}};
// GL_BLEND and the blend state for `mode`: none: blending off, the fragment
// replaces the pixel; over: alpha * src + (1 - alpha) * dst; additive:
// alpha * src + dst; multiply: src * dst; premultiplied: src + (1 - alpha) *
// dst, for a colour already multiplied by its alpha. All with GL_FUNC_ADD.
void set_blend_mode(Mode mode);

// Whether fragments that pass the depth test write their depth.
void set_depth_writes(bool on);

// scene=stencil's three passes: mark where the mask is drawn, then draw only
// where it is marked, then only where it is not.
void mark_stencil();
void draw_where_marked();
void draw_where_unmarked();

// The scissor test on, limited to `r` (x, y, width, height in pixels of a
// 512 x 512 scene, y from the bottom), scaled to the viewport `v` (x, y,
// width, height, as glGetIntegerv(GL_VIEWPORT) gives it).
void scissor_to(glm::ivec4 v, glm::ivec4 r);

}  // namespace framebuffer_ops
