// Lab 9's pairs of buffers for transform feedback (capture.hpp).
#include "capture.hpp"

namespace buffers {

CapturePair make_capture_pair(std::size_t bytes, const fw::VertexLayout& layout,
                              const std::string& name) {
    CapturePair pair;
    for (int i = 0; i < 2; ++i) {
        const std::string label = name + " " + std::to_string(i);
        fw::BufferDesc desc;
        desc.size = bytes;
        desc.usage = GL_DYNAMIC_COPY;
        desc.label = label;
        pair.buffer[i] = fw::Buffer(desc);
        pair.vertices[i] = fw::VertexArray(
            fw::VertexArrayDesc{.vertices = &pair.buffer[i], .layout = layout, .label = label});
        // A transform feedback object remembers its buffer bindings.
        pair.capture[i] = fw::TransformFeedback("into " + label);
        glBindTransformFeedback(GL_TRANSFORM_FEEDBACK, pair.capture[i].id());
        glBindBufferBase(GL_TRANSFORM_FEEDBACK_BUFFER, 0, pair.buffer[i].id());
    }
    glBindTransformFeedback(GL_TRANSFORM_FEEDBACK, 0);
    return pair;
}

}  // namespace buffers
