// fw::TransformFeedback: a transform feedback object, which records the
// buffers bound to GL_TRANSFORM_FEEDBACK_BUFFER while it is bound and how
// many vertices the last capture wrote (what glDrawTransformFeedback draws).
//
//   fw::TransformFeedback feedback("particles step");
//   glBindTransformFeedback(GL_TRANSFORM_FEEDBACK, feedback.id());
//   glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, target.id());
//   glEnable(GL_RASTERIZER_DISCARD);
//   glBeginTransformFeedback(GL_POINTS);
//   glDrawArrays(GL_POINTS, 0, count);
//   glEndTransformFeedback();
//   glDisable(GL_RASTERIZER_DISCARD);
//   glBindTransformFeedback(GL_TRANSFORM_FEEDBACK, 0);
//
// The program's captured outputs are set when it is linked
// (Program::from_files' `feedback`).
#pragma once

#include <glad/gl.h>

#include <string>

#include "framework/gl/handle.hpp"

namespace fw {

class TransformFeedback {
public:
    TransformFeedback() = default;
    // Needs a current context; `label` is shown in GL debug messages.
    explicit TransformFeedback(std::string label);

    GLuint id() const { return handle_.get(); }
    const std::string& label() const { return label_; }

private:
    detail::Handle handle_;
    std::string label_;
};

}  // namespace fw
