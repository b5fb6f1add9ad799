// Lab 7's per-fragment state: the student parts that configure the frame
// buffer operations (fragment_state.hpp says what each sets).
#include "fragment_state.hpp"

#include <glad/gl.h>

namespace framebuffer_ops {

// GL_BLEND and the blend state for `mode`: none: blending off, the fragment
// replaces the pixel; over: alpha * src + (1 - alpha) * dst; additive:
// alpha * src + dst; multiply: src * dst; premultiplied: src + (1 - alpha) *
// dst, for a colour already multiplied by its alpha. All with GL_FUNC_ADD.
void set_blend_mode(Mode mode) {
    // BEGIN SOLUTION
    // STUDENT: (void)mode;  // TODO: glDisable(GL_BLEND) for none; else glEnable(GL_BLEND),
    // STUDENT: // glBlendEquation(GL_FUNC_ADD) and glBlendFunc(source factor, destination factor)
    if (mode == Mode::None) {
        glDisable(GL_BLEND);
        return;
    }
    glEnable(GL_BLEND);
    glBlendEquation(GL_FUNC_ADD);
    switch (mode) {
        case Mode::Over:
            glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
            break;
        case Mode::Additive:
            glBlendFunc(GL_SRC_ALPHA, GL_ONE);
            break;
        case Mode::Multiply:
            glBlendFunc(GL_DST_COLOR, GL_ZERO);
            break;
        case Mode::Premultiplied:
            glBlendFunc(GL_ONE, GL_ONE_MINUS_SRC_ALPHA);
            break;
        case Mode::None:
            break;
    }
    // END SOLUTION
}

// Whether fragments that pass the depth test write their depth. Translucent
// objects test against the depth of what is opaque but must not hide what is
// drawn after them.
void set_depth_writes(bool on) {
    // BEGIN SOLUTION
    // STUDENT: (void)on;  // TODO: glDepthMask
    glDepthMask(on ? GL_TRUE : GL_FALSE);
    // END SOLUTION
}

// scene=stencil, pass 1: the stencil test on, and every fragment drawn sets
// the stencil to 1 (GL_REPLACE when the stencil and depth tests pass); the
// colour buffer is left alone (glColorMask).
void mark_stencil() {
    // BEGIN SOLUTION
    // STUDENT: // TODO: glEnable(GL_STENCIL_TEST), glStencilMask(0xFF),
    // STUDENT: // glStencilFunc(GL_ALWAYS, ...), glStencilOp(..., GL_REPLACE), glColorMask off
    glEnable(GL_STENCIL_TEST);
    glStencilMask(0xFF);
    glStencilFunc(GL_ALWAYS, 1, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_REPLACE);
    glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_FALSE);
    // END SOLUTION
}

// Pass 2: colour written again, only where the stencil is 1; the stencil
// itself is left as it is.
void draw_where_marked() {
    // BEGIN SOLUTION
    // STUDENT: // TODO: glColorMask on, glStencilFunc(GL_EQUAL, ...),
    // STUDENT: // glStencilOp keeping the stencil
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glStencilFunc(GL_EQUAL, 1, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_KEEP);
    // END SOLUTION
}

// Pass 3: only where the stencil is not 1.
void draw_where_unmarked() {
    // BEGIN SOLUTION
    // STUDENT: // TODO: glStencilFunc(GL_NOTEQUAL, ...)
    glStencilFunc(GL_NOTEQUAL, 1, 0xFF);
    // END SOLUTION
}

// The scissor test on, limited to `r` (x, y, width, height in pixels of a
// 512 x 512 scene, y from the bottom), scaled to the viewport `v` (x, y,
// width, height, as glGetIntegerv(GL_VIEWPORT) gives it).
void scissor_to(glm::ivec4 v, glm::ivec4 r) {
    const float sx = float(v[2]) / 512.0f, sy = float(v[3]) / 512.0f;
    // BEGIN SOLUTION
    // STUDENT: (void)v, (void)r, (void)sx, (void)sy;
    // STUDENT: // TODO: glEnable(GL_SCISSOR_TEST) and glScissor(x, y, width, height),
    // STUDENT: // in window pixels
    glEnable(GL_SCISSOR_TEST);
    glScissor(v[0] + int(float(r[0]) * sx), v[1] + int(float(r[1]) * sy), int(float(r[2]) * sx),
              int(float(r[3]) * sy));
    // END SOLUTION
}

}  // namespace framebuffer_ops
