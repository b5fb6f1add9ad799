// Lab 12's shadow state: the student parts that configure the stencil, the
// depth-only framebuffer and the depth comparison (shadow_state.hpp says
// what each sets).
#include "shadow_state.hpp"

namespace shadows {

void set_shadow_stencil(bool on) {
    // BEGIN SOLUTION
    // STUDENT: (void)on;  // TODO: with on: glEnable(GL_STENCIL_TEST), glStencilMask(0xFF),
    // STUDENT: // glStencilFunc(GL_EQUAL, 0, 0xFF), glStencilOp(GL_KEEP, GL_KEEP, GL_INCR);
    // STUDENT: // without: glDisable(GL_STENCIL_TEST)
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
    // STUDENT: (void)depth;  // TODO: glFramebufferTexture2D(..., GL_DEPTH_ATTACHMENT, ...),
    // STUDENT: // then glDrawBuffer(GL_NONE) and glReadBuffer(GL_NONE)
    glFramebufferTexture2D(GL_FRAMEBUFFER, GL_DEPTH_ATTACHMENT, GL_TEXTURE_2D, depth.id(), 0);
    glDrawBuffer(GL_NONE);
    glReadBuffer(GL_NONE);
    // END SOLUTION
}

void set_shadow_compare(bool pcf) {
    const GLint filter = pcf ? GL_LINEAR : GL_NEAREST;
    // BEGIN SOLUTION
    // STUDENT: (void)filter;  // TODO: glTexParameteri for GL_TEXTURE_COMPARE_MODE,
    // STUDENT: // GL_TEXTURE_COMPARE_FUNC, GL_TEXTURE_MIN_FILTER and GL_TEXTURE_MAG_FILTER
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_COMPARE_FUNC, GL_LEQUAL);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, filter);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, filter);
    // END SOLUTION
}

}  // namespace shadows
