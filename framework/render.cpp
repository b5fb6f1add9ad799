#include "framework/render.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>

#include "framework/error.hpp"
#include "framework/gl/debug.hpp"
#include "framework/gl/framebuffer.hpp"
#include "framework/gl/query.hpp"
#include "framework/lab_buffers.hpp"

namespace fw {

Viewport scene_viewport(double aspect, int width, int height) {
    if (!(aspect > 0.0) || width <= 0 || height <= 0) return {0, 0, width, height};
    if (double(width) > aspect * height) {
        const int w = std::max(1, static_cast<int>(std::lround(aspect * height)));
        return {(width - w) / 2, 0, w, height};
    }
    const int h = std::max(1, static_cast<int>(std::lround(width / aspect)));
    return {0, (height - h) / 2, width, h};
}

Frame scene_frame(const LabInfo& info, const Frame& frame) {
    const Viewport v = scene_viewport(info.aspect, frame.width, frame.height);
    return {v.width, v.height, frame.time};
}

void reset_write_state() {
    // With the rasterizer off, glClear is ignored too (GL 4.3, 14.1).
    glDisable(GL_RASTERIZER_DISCARD);
    glDisable(GL_SCISSOR_TEST);
    glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
    glDepthMask(GL_TRUE);
    glStencilMask(0xFFu);
}

namespace {

// The bound framebuffer's `mask` buffers cleared to where every frame starts:
// colour black, depth 1, stencil 0 (the write state reset first).
void clear_to_start(GLbitfield mask) {
    glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
    glClearDepth(1.0);
    glClearStencil(0);
    glClear(mask);
}

}  // namespace

void present_frame(const Framebuffer* frame, int width, int height) {
    // A scissor rectangle the lab left would clip the copy.
    reset_write_state();
    glBindFramebuffer(GL_DRAW_FRAMEBUFFER, 0);
    if (frame) {
        glBindFramebuffer(GL_READ_FRAMEBUFFER, frame->id());
        glBlitFramebuffer(0, 0, frame->width(), frame->height(), 0, 0, frame->width(),
                          frame->height(), GL_COLOR_BUFFER_BIT, GL_NEAREST);
    } else {
        glViewport(0, 0, width, height);
        clear_to_start(GL_COLOR_BUFFER_BIT);
    }
    glBindFramebuffer(GL_FRAMEBUFFER, 0);
}

LabRenderer::LabRenderer(const RegisteredLab& lab, ContextInfo context)
    : registered_(lab), context_(std::move(context)), programs_(lab.info.dir), lab_(lab.create()) {
    enable_debug_output();
    primitives_ = std::make_unique<Query>(GL_PRIMITIVES_GENERATED, "primitives generated");
    elapsed_ = std::make_unique<Query>(GL_TIME_ELAPSED, "frame time");
    lab_->init(programs_);
    check_gl(("init of lab " + lab.info.id).c_str());
}

LabRenderer::~LabRenderer() = default;

// A framebuffer of the frame's size, bound and cleared as Lab::draw expects:
// colour black, depth 1, stencil 0. glClear obeys the write masks and the
// scissor test, which a lab may have left set: both are reset first.
void LabRenderer::begin_frame(int width, int height) {
    if (!framebuffer_ || framebuffer_->width() != width || framebuffer_->height() != height) {
        framebuffer_.reset();
        framebuffer_ = std::make_unique<Framebuffer>(FramebufferDesc{
            width, height, "offscreen " + std::to_string(width) + "x" + std::to_string(height)});
    }
    framebuffer_->bind();
    reset_write_state();
    clear_to_start(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
}

// The lab's draw inside the frame's queries, finished by GL.
void LabRenderer::draw_queried(const ParamValues& params, const Frame& frame) {
    primitives_->begin();
    elapsed_->begin();
    try {
        lab_->draw(params, frame);
    } catch (...) {
        // The next frame starts clean: its queries can begin, and GL errors
        // this draw left are not blamed on it (the exception says what failed).
        elapsed_->end();
        primitives_->end();
        while (glGetError() != GL_NO_ERROR) {
        }
        throw;
    }
    elapsed_->end();
    primitives_->end();
    glFinish();
}

FrameResult LabRenderer::draw(const ParamValues& params, int width, int height, double time) {
    const std::string& id = registered_.info.id;
    const std::string rejected = lab_->validate(params);
    const auto start = std::chrono::steady_clock::now();
    begin_frame(width, height);
    if (!rejected.empty()) throw UsageError("lab '" + id + "': " + rejected);
    const Viewport v = scene_viewport(registered_.info.aspect, width, height);
    glViewport(v.x, v.y, v.width, v.height);
    const Frame frame{v.width, v.height, time};
    draw_queried(params, frame);
    const double render_ms =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
    check_gl(("draw of lab " + id).c_str());
    return {{
        {"lab", id},
        {"params", params.to_json()},
        {"backend", context_.backend},
        {"platform", context_.platform},
        {"gl_version", context_.gl_version},
        {"gl_renderer", context_.gl_renderer},
        {"width", width},
        {"height", height},
        {"primitives_generated", primitives_->result()},
        {"render_ms", render_ms},
        {"gpu_ms", static_cast<double>(elapsed_->result()) / 1e6},
        {"lab_stats", lab_->stats(params, frame)},
    }};
}

RenderOutput LabRenderer::render(const ParamValues& params, int width, int height, double time,
                                 ReadBack read) {
    RenderOutput out;
    out.stats = draw(params, width, height, time).stats;
    out.color = framebuffer_->read_color();
    read_back(params, width, height, time, read, out);
    return out;
}

void LabRenderer::read_back(const ParamValues& params, int width, int height, double time,
                            ReadBack read, RenderOutput& out) {
    if (read.depth) out.depth = framebuffer_->read_depth();
    if (read.buffers) {
        // Read back with glGetBufferSubData, which sees what shaders wrote
        // only after this barrier; the lab's draw needs only those of its own reads.
        glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
        // The lab sees the frame its draw() saw.
        out.buffers = lab_->buffers(params, scene_frame(registered_.info, {width, height, time}));
        check_lab_buffers(out.buffers, registered_.info.id);
    }
    check_gl(("read-back of lab " + registered_.info.id).c_str());
}

void parse_size(const std::string& text, int& width, int& height) {
    size_t x = text.find('x');
    auto bad = [&](const std::string& why) {
        throw UsageError("--size '" + text + "': " + why + "; expected WxH, e.g. 512x512");
    };
    if (x == std::string::npos) bad("no 'x'");
    std::string ws = text.substr(0, x), hs = text.substr(x + 1);
    char* end = nullptr;
    long w = std::strtol(ws.c_str(), &end, 10);
    if (ws.empty() || *end) bad("width '" + ws + "' is not a whole number");
    long h = std::strtol(hs.c_str(), &end, 10);
    if (hs.empty() || *end) bad("height '" + hs + "' is not a whole number");
    if (w <= 0 || h <= 0) bad("width and height must be at least 1");
    if (w > 65536 || h > 65536)
        bad("width and height must be at most the GL limit (65536 here at most)");
    width = static_cast<int>(w);
    height = static_cast<int>(h);
}

}  // namespace fw
