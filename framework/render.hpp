// Draws frames of one lab, in the current context, into a framework-owned
// framebuffer. `lab render`, the tests and the grading child read each frame
// back (render()); `lab serve` reads back colour only; the window copies the
// framebuffer into itself (draw(), then framebuffer()). One frame protocol
// for all of them: the same clear, validation, queries and error handling.
#pragma once

#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/context.hpp"
#include "framework/image.hpp"
#include "framework/lab.hpp"

namespace fw {

class Framebuffer;
class Query;

// What draw() measured of the frame it drew.
struct FrameResult {
    nlohmann::json stats;  // the --stats fields (docs/contract.md, `--stats FILE.json`)
};

struct RenderOutput {
    Image color;
    DepthImage depth;
    nlohmann::json stats;            // as FrameResult::stats
    std::vector<LabBuffer> buffers;  // Lab::buffers() of the frame, when asked (ReadBack)
};

// What render() reads back besides the colour: the depth buffer, and the
// buffers the lab's shaders wrote (Lab::buffers, checked by check_lab_buffers).
struct ReadBack {
    bool depth = true;
    bool buffers = false;
};

// The state that glClear and glBlitFramebuffer obey, as GL starts: the
// rasterizer and colour, depth and stencil writes on, the scissor test off.
// A lab may leave them otherwise; the renderer and the window set them back
// before a clear or a copy.
void reset_write_state();

// The renderer's frame copied into the default framebuffer (a window's back
// buffer, `width` x `height`); cleared to black while there is no frame yet.
// Every clear of a frame is the frame protocol's: begin_frame() and this.
void present_frame(const Framebuffer* frame, int width, int height);

class LabRenderer {
public:
    // Creates the lab and calls its init(); throws what init throws.
    LabRenderer(const RegisteredLab& lab, ContextInfo context);
    ~LabRenderer();
    LabRenderer(const LabRenderer&) = delete;
    LabRenderer& operator=(const LabRenderer&) = delete;

    // One frame at width x height into framebuffer(), which is made again
    // when the size changes, bound and cleared to (0, 0, 0, 1), depth 1 and
    // stencil 0, with every write mask open and the scissor test off.
    // Throws UsageError for a size of zero or above the GL limit, and, with
    // the frame left cleared, for parameters the lab rejects; what the lab's
    // draw throws, or a GL error it left, is thrown with the frame as far as
    // it got. `time`: seconds for a lab that animates (Frame::time; 0 draws
    // what lab render draws). Waits until GL has finished the frame.
    FrameResult draw(const ParamValues& params, int width, int height, double time = 0.0);
    // draw(), then the frame read back: its colour, and what `read` asks for
    // (what it leaves out stays empty in the output).
    RenderOutput render(const ParamValues& params, int width, int height, double time = 0.0,
                        ReadBack read = {});
    // What `read` asks for of the frame render() last drew with these
    // arguments, into `out`: render() with it, read apart (the grader keeps
    // its own reads out of the record of the lab's draws).
    void read_back(const ParamValues& params, int width, int height, double time, ReadBack read,
                   RenderOutput& out);
    // What the last draw() drew into; null before the first.
    const Framebuffer* framebuffer() const { return framebuffer_.get(); }

    Lab& lab() { return *lab_; }
    const RegisteredLab& registered() const { return registered_; }
    // The lab's programs, those that failed to build included.
    const ProgramLibrary& programs() const { return programs_; }
    ProgramLibrary& programs() { return programs_; }

private:
    void begin_frame(int width, int height);
    void draw_queried(const ParamValues& params, const Frame& frame);

    const RegisteredLab& registered_;
    ContextInfo context_;
    ProgramLibrary programs_;
    std::unique_ptr<Lab> lab_;
    std::unique_ptr<Framebuffer> framebuffer_;
    // Created once, begun and ended around every frame's draw.
    std::unique_ptr<Query> primitives_, elapsed_;
};

// "512x384" -> (512, 384); throws UsageError.
void parse_size(const std::string& text, int& width, int& height);

}  // namespace fw
