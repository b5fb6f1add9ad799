// Lab 12's GL state for shadows, set with the GL calls the lab teaches.
// Student parts (shadow_state.cpp); shadows.cpp calls them while drawing.
#pragma once

#include <glad/gl.h>

#include "framework/gl.hpp"

namespace shadows {

// scene=planar, before the flattened shadow is drawn: with `on`, the stencil
// test lets a fragment through only where the stencil is still 0 and
// increments it there (GL_INCR), so each pixel is darkened once however many
// shadow triangles cover it; without, the stencil test is off.
void set_shadow_stencil(bool on);

// scene=shadowmap: `depth` attached as the only attachment of `framebuffer`
// (GL_DEPTH_ATTACHMENT), and no colour buffer drawn or read (glDrawBuffer,
// glReadBuffer with GL_NONE), so that the framebuffer is complete.
void attach_depth(GLuint framebuffer, const fw::Texture2D& depth);

// For the depth texture bound to the active unit: the comparison a
// sampler2DShadow makes (GL_TEXTURE_COMPARE_MODE GL_COMPARE_REF_TO_TEXTURE,
// GL_TEXTURE_COMPARE_FUNC GL_LEQUAL: 1 where the reference is at most the
// stored depth), and both filters GL_LINEAR with `pcf` (percentage-closer
// filtering: four comparisons weighted bilinearly), else GL_NEAREST.
void set_shadow_compare(bool pcf);

}  // namespace shadows
