// Lab 9's sphere made on the GPU: the octahedron a subdivision starts from,
// and the passes that feed each pass's captured triangles to the next
// (subdivide.cpp). The student part is the geometry shader,
// shaders/09_buffers/subdivide.geom.
#pragma once

#include <glm/glm.hpp>
#include <vector>

#include "capture.hpp"
#include "framework/gl.hpp"

namespace buffers {

constexpr int kMaxPasses = 4;

// The octahedron with vertices (+-1, 0, 0), (0, +-1, 0), (0, 0, +-1): 8
// triangles, 24 vertices, no index buffer. With the ring r = (+x, -z, -x, +z),
// the upper faces are (r[i], r[i+1], +y) and the lower ones (r[i+1], r[i], -y),
// i = 0..3 (indices mod 4), in that order: every face counter-clockwise
// seen from outside.
std::vector<glm::vec3> octahedron();

// Two buffers, each holding up to 8 * 4^kMaxPasses triangles of positions:
// a pass reads one (vertices[i] reads buffer[i]) and captures into the other
// (capture[i]).
using SubdivisionPair = CapturePair;
SubdivisionPair make_subdivision_pair();

// Runs `passes` passes of `subdivide` (subdivide.vert + subdivide.geom,
// capturing g_position) over the octahedron in pair.buffer[0], and returns
// the index of the buffer that holds the result. Pass one draws the 24
// vertices there; every later pass draws what the one before captured
// (glDrawTransformFeedback: the count never comes back to the CPU).
int subdivide(SubdivisionPair& pair, const fw::Program& subdivide, int passes);

}  // namespace buffers
