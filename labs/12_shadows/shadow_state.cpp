// Lab 12's shadow state: the student parts that configure the stencil, the
// depth-only framebuffer and the depth comparison (shadow_state.hpp says
// what each sets).
#include "shadow_state.hpp"

namespace shadows {

void set_shadow_stencil(bool on) {
    // BEGIN SOLUTION
    // STUDENT: (void)on;  // TODO: with on, a stencil test (glStencilFunc, glStencilOp,
    // STUDENT: // glStencilMask) that draws a fragment only where the stencil still holds 0 and
    // STUDENT: // adds 1 where it draws, every bit written; off: no stencil test
    if (!on) {
        glDisable(GL_STENCIL_TEST);
        return;
    }
    glEnable(GL_STENCIL_TEST);
    glStencilMask(0xFF);
    glStencilFunc(GL_EQUAL, 0, 0xFF);
    glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
    // END SOLUTION
}

void attach_depth(GLuint framebuffer, const fw::Texture2D& depth) {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
    // BEGIN SOLUTION
    // STUDENT: (void)depth;  // TODO: `depth` as this framebuffer's depth buffer
    // STUDENT: // (glFramebufferTexture2D), and no colour buffer to draw into or read from
    // STUDENT: // (glDrawBuffer, glReadBuffer)
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth.id(), 0);
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
    // END SOLUTION
}

void set_shadow_compare(bool pcf) {
    const GLint filter = pcf ? GL_LINEAR : GL_NEAREST;
    // BEGIN SOLUTION
    // STUDENT: (void)filter;  // TODO: with glTexParameteri, the bound depth texture compares
    // STUDENT: // a reference with its depth (passing where the reference is at most the depth)
    // STUDENT: // instead of returning the depth; both its filters `filter`
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    // END SOLUTION
}

}  // namespace shadows
