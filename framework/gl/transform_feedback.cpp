#include "framework/gl/transform_feedback.hpp"

#include "framework/gl/debug.hpp"

namespace fw {

TransformFeedback::TransformFeedback(std::string label) : label_(std::move(label)) {
    GLuint id = 0;
    glGenTransformFeedbacks(1, &id);
    handle_ = detail::Handle(id, [](GLuint n) { glDeleteTransformFeedbacks(1, &n); });
    // A name becomes an object when first bound; only an object takes a
    // label. The binding in use before is put back.
    GLint previous = 0;
    glGetIntegerv(GL_TRANSFORM_FEEDBACK_BINDING, &previous);
    glBindTransformFeedback(GL_TRANSFORM_FEEDBACK, id);
    glBindTransformFeedback(GL_TRANSFORM_FEEDBACK, static_cast<GLuint>(previous));
    set_object_label(GL_TRANSFORM_FEEDBACK, id, label_);
}

}  // namespace fw
