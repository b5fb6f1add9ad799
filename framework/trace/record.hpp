// The record of what each draw was told: at every draw (glDraw*), dispatch
// (glDispatchCompute*), clear (glClear, glClearBuffer*) and read-back
// (glReadPixels, glGetBufferSubData, glMapBuffer*), the GL state that decides
// its result, asked of GL at that call, and only where it is live: blend
// factors only with blending on, the depth function and mask only with the
// depth test on, no fragment state with the rasterizer off, the textures of
// the program's active samplers only, and so on.
//
// The grading child records a checkpoint's render when its job asks
// ("record": true, docs/contract.md); `course bless` keeps the solution's
// records beside the reference images, and grading/diagnosis/state_diff compares
// a student's with them draw by draw. So a record names no GL object by its
// number: a program by its label (the shader files it was built from), a
// buffer, texture, vertex array or framebuffer by its label, or, without
// one, by its creation order ("buffer #3"); floats are written to six
// significant digits. The same calls give the same bytes on any backend.
//
//   fw::gl_record::Recorder recorder;    // from before the lab creates its objects
//   fw::gl_calls::observe(&recorder);
//   recorder.begin();
//   ... the checkpoint renders ...
//   nlohmann::json record = recorder.end();  // {"version": 1, "events": [...]}
//   std::string text = fw::gl_record::record_text(record);
#pragma once

#include <glad/gl.h>
#include <glad/gl_names.h>

#include <initializer_list>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "framework/trace/calls.hpp"

namespace fw::gl_record {

// The format's version, in every record and in the reference files.
constexpr int kVersion = 1;

class Recorder : public gl_calls::Observer {
public:
    Recorder();
    ~Recorder() override;
    Recorder(const Recorder&) = delete;
    Recorder& operator=(const Recorder&) = delete;

    // Starts keeping events (none are kept before); end() stops and returns
    // the record. Objects are numbered by creation from the Recorder's start,
    // whether or not it is keeping events.
    void begin();
    nlohmann::json end();

    void before(const char* name, int count, va_list args) override;
    void after(const char* name, int count, va_list args) override;

    struct Impl;

private:
    Impl* impl_;
};

// A record as text: one event a line, so that a reference's changes read
// well in a diff; the same record gives the same bytes.
std::string record_text(const nlohmann::json& record);

// record_enums.cpp: the name of `value` among the enums of one kind of state
// (GL's one table of names, fw::gl_enum_name, by its groups).
enum class EnumKind { Mode, Factor, StencilOp, Other };
std::string enum_name(EnumKind kind, GLenum value);
// "GL_COLOR_BUFFER_BIT|GL_DEPTH_BUFFER_BIT": the names in `group` of the set
// bits, in the order of `order` (ascending where it is empty), then any bits
// left as one hex number; "0" for none.
std::string bits_name(GladGlGroup group, GLbitfield value,
                      std::initializer_list<GLbitfield> order = {});

}  // namespace fw::gl_record
