// Lab 9's pairs of buffers for transform feedback: a draw reads one buffer
// while the other captures what the shaders wrote, then the two swap roles
// (the particles of scene feedback, the triangles of scene subdivide).
#pragma once

#include <cstddef>
#include <string>

#include "framework/gl.hpp"

namespace buffers {

// vertices[i] reads buffer[i] through the layout; capture[i] is the
// transform feedback object that captures into buffer[i] (its binding 0).
struct CapturePair {
    fw::Buffer buffer[2];
    fw::VertexArray vertices[2];
    fw::TransformFeedback capture[2];
};

// Two buffers of `bytes` each, labelled "NAME 0" and "NAME 1".
CapturePair make_capture_pair(std::size_t bytes, const fw::VertexLayout& layout,
                              const std::string& name);

}  // namespace buffers
