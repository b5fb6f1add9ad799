// fw::gl_usage: GL usage that llvmpipe tolerates and a GPU does not. An
// observer of the GL calls (framework/trace/calls.hpp) that looks, at every
// draw, dispatch and read-back, for what the GL 4.3 specification leaves
// undefined or forbids, and says what a GPU does instead:
//
//   memory-barrier      a buffer (or image) a compute dispatch wrote, read
//                       with no glMemoryBarrier of the matching bit since
//   clip-distance       a clip distance the shaders write, not enabled
//   incomplete-texture  a sampler reading an incomplete texture (8.17)
//   capture-and-source  a buffer captured by transform feedback and read by
//                       the same draw
//   sampler-unit        a sampler uniform set outside 0..units-1
//   write-past-count    a dispatch that wrote into a guard (guard() below)
//
// llvmpipe finishes each dispatch before it returns, clips by every distance
// a shader writes, and so on: a lab that relies on it scores on Mesa and
// fails on a GPU. The grading child observes with a Checker and writes its
// findings per render (NAME.usage.json); `course` judges them (the check
// kind `portable`). A lab needs nothing of this but guard().
#pragma once

#include <glad/gl.h>

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include "framework/trace/calls.hpp"

namespace fw::gl_usage {

struct Finding {
    std::string rule;    // one of the ids above
    std::string call;    // the GL call it was found at: "glDrawArrays", "glUniform1i"
    int draw = 0;        // the render's draw, dispatch or read-back it concerns, from 1
    std::string detail;  // what the usage is, and what a GPU does instead
    int times = 1;       // how often the same finding came up in the render
};

// The calls of this thread, once observed (gl_calls::observe, or a
// gl_calls::Fanout): it learns each program when it is linked, so it must
// observe before the lab's programs are made.
class Checker : public gl_calls::Observer {
public:
    Checker();
    ~Checker() override;
    Checker(const Checker&) = delete;
    Checker& operator=(const Checker&) = delete;

    void before(const char* name, int count, va_list args) override;
    void after(const char* name, int count, va_list args) override;

    // A render begins: its draws are counted from 1. Findings made before
    // the first render (in the lab's init) are kept for it.
    void begin_render();
    // The render's findings, in the order they were made; checks the guards
    // a dispatch wrote since the last call that read.
    std::vector<Finding> end_render();

    struct State;

private:
    std::unique_ptr<State> state_;
};

// NAME.usage.json: [{"rule", "call", "draw", "detail", "times"}, ...].
std::string findings_json(const std::vector<Finding>& findings);

// For a lab's given code: bytes [offset, offset + size) of `buffer` hold a
// sentinel that no shader may change (a guard after the `count` elements a
// compute shader is given). The bytes are read now; after each dispatch
// that writes the buffer, the next draw, dispatch or read-back finds them
// changed or not. `element` is the size of one element, `what` names the
// data before the guard ("the particles"). Does nothing unless a Checker
// observes this thread. A second guard of the same buffer replaces the first.
void guard(GLuint buffer, std::size_t offset, std::size_t size, std::size_t element,
           const std::string& what);

// The indices i of gl_ClipDistance[i] that a shader's source writes: each
// constant index (a literal, a #define or a const int), and every index below
// the redeclared size for an index that is not constant or a whole-array
// write. `known` is false when the source writes one the size does not bound.
struct ClipWrites {
    bool known = true;
    std::vector<int> indices;  // sorted, each once
};
ClipWrites clip_distances_written(const std::string& source);

}  // namespace fw::gl_usage
