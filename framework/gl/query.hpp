// fw::Query: asks GL to count something between begin() and end().
//
//   fw::Query prims(GL_PRIMITIVES_GENERATED, "frame primitives");
//   prims.begin();  ... draws ...  prims.end();
//   std::uint64_t n = prims.result();   // waits until the GPU has finished
//
// Targets: GL_PRIMITIVES_GENERATED, GL_SAMPLES_PASSED (fragments that passed
// the depth test), GL_ANY_SAMPLES_PASSED, GL_ANY_SAMPLES_PASSED_CONSERVATIVE,
// GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN, GL_TIME_ELAPSED (nanoseconds).
// Only one query per target may be active at a time.
#pragma once

#include <glad/gl.h>

#include <cstdint>
#include <string>

#include "framework/gl/handle.hpp"

namespace fw {

class Query {
public:
    Query() = default;
    // Throws UsageError for a target not listed above.
    explicit Query(GLenum target, std::string label = {});

    GLuint id() const { return handle_.get(); }
    GLenum target() const { return target_; }
    const std::string& label() const { return label_; }

    // glBeginQuery / glEndQuery. Throws UsageError when begun twice, ended
    // without begin(), and so on.
    void begin();
    void end();

    // Whether the result is ready without waiting.
    bool available() const;
    // The count (or nanoseconds) of the last begin/end pair; waits for the
    // GPU. Throws UsageError before the first end().
    std::uint64_t result() const;

private:
    detail::Handle handle_;
    GLenum target_ = 0;
    std::string label_;
    bool active_ = false, ended_ = false, labelled_ = false;
};

}  // namespace fw
