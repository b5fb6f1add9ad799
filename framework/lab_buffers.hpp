// The buffers a frame's shaders wrote (Lab::buffers), as a file: the grading
// child's NAME.buffers.json and `lab render --buffers FILE.json`
// (docs/contract.md, `--buffers FILE.json`). One JSON object, a member per
// buffer, by name:
//
//   {"particles": {"components": 3, "values": [0.4, 1.2, 0, 0.5, ...]}}
//
// `values` holds the floats element after element, each in the fewest
// digits that read back as the same float; one that is not finite is the
// string "NaN", "Infinity" or "-Infinity" (framework/json_glm.hpp).
#pragma once

#include <string>
#include <vector>

#include "framework/lab.hpp"

namespace fw {

// LabBuffer::components: 1 (a float) to 64 (a few matrices per element).
constexpr int kMaxBufferComponents = 64;

// Throws Error naming the lab and the buffer for an empty or repeated name, or
// components outside 1..kMaxBufferComponents: a mistake in the lab's
// buffers(), not in what the shaders wrote (a count of values that is not a
// multiple of components is left for the grader to report).
void check_lab_buffers(const std::vector<LabBuffer>& buffers, const std::string& lab);

// The file's text, and the file itself (throws Error when it cannot be written).
std::string buffers_json(const std::vector<LabBuffer>& buffers);
void write_buffers(const std::string& path, const std::vector<LabBuffer>& buffers);

// Reads the text of a buffers file, from anyone: throws Error naming `file`,
// the buffer and what is wrong (not JSON, not an object, a missing or wrong
// field, a value that is not a number). Buffers come in the order of their names.
std::vector<LabBuffer> parse_buffers(const std::string& text, const std::string& file);

}  // namespace fw
