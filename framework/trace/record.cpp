#include "framework/trace/record.hpp"

#include <cstdint>
#include <cstring>
#include <sstream>
#include <unordered_map>

#include "framework/trace/record_state.hpp"

namespace fw::gl_record {

namespace {

using detail::json;
using detail::number;

// How an argument is written: a primitive mode, another enum, an integer, a
// buffer offset passed as a pointer, a client pointer (left out: its address
// says nothing), a float, a clear's or a barrier's bits, a transform feedback
// object's number, a glClearBuffer value.
enum class Arg {
    Mode,
    Enum,
    Int,
    IntPtr,
    Uint,
    Offset,
    Pointer,
    Float,
    ClearBits,
    BarrierBits,
    Access,
    Feedback,
    ClearValue
};

enum class Kind {
    Other,
    Draw,
    DrawElements,
    Dispatch,
    Clear,
    ClearBuffer,
    ReadPixels,
    BufferRead,
    Barrier,
    Create,
    Relink
};

struct Call {
    Kind kind = Kind::Other;
    std::vector<std::pair<std::string, Arg>> args;
    GLenum identifier = 0;  // Create: the objects' kind
};

// The calls the record knows, each a line "NAME ARG:CODE ...", CODE saying
// how the argument is written: M mode, e enum, i int, I GLintptr or
// GLsizeiptr, u unsigned, o offset, p pointer, f float, c clear bits, b
// barrier bits, a access bits, t transform feedback, v glClearBuffer value.
const std::pair<Kind, const char*> kSignatures[] = {
    {Kind::Draw, "glDrawArrays mode:M first:i count:i"},
    {Kind::Draw, "glDrawArraysInstanced mode:M first:i count:i instancecount:i"},
    {Kind::Draw,
     "glDrawArraysInstancedBaseInstance mode:M first:i count:i instancecount:i baseinstance:u"},
    {Kind::Draw, "glDrawArraysIndirect mode:M indirect:o"},
    {Kind::Draw, "glMultiDrawArrays mode:M first:p count:p drawcount:i"},
    {Kind::DrawElements, "glDrawElements mode:M count:i type:e indices:o"},
    {Kind::DrawElements, "glDrawElementsBaseVertex mode:M count:i type:e indices:o basevertex:i"},
    {Kind::DrawElements, "glDrawElementsInstanced mode:M count:i type:e indices:o instancecount:i"},
    {Kind::DrawElements,
     "glDrawElementsInstancedBaseVertex mode:M count:i type:e indices:o instancecount:i "
     "basevertex:i"},
    {Kind::DrawElements,
     "glDrawElementsInstancedBaseInstance mode:M count:i type:e indices:o instancecount:i "
     "baseinstance:u"},
    {Kind::DrawElements,
     "glDrawElementsInstancedBaseVertexBaseInstance mode:M count:i type:e indices:o "
     "instancecount:i basevertex:i baseinstance:u"},
    {Kind::DrawElements, "glDrawRangeElements mode:M start:u end:u count:i type:e indices:o"},
    {Kind::DrawElements,
     "glDrawRangeElementsBaseVertex mode:M start:u end:u count:i type:e indices:o basevertex:i"},
    {Kind::DrawElements, "glDrawElementsIndirect mode:M type:e indirect:o"},
    {Kind::DrawElements, "glMultiDrawElements mode:M count:p type:e indices:p drawcount:i"},
    {Kind::Draw, "glDrawTransformFeedback mode:M id:t"},
    {Kind::Draw, "glDrawTransformFeedbackInstanced mode:M id:t instancecount:i"},
    {Kind::Draw, "glDrawTransformFeedbackStream mode:M id:t stream:u"},
    {Kind::Dispatch, "glDispatchCompute num_groups_x:u num_groups_y:u num_groups_z:u"},
    {Kind::Dispatch, "glDispatchComputeIndirect indirect:I"},
    {Kind::Clear, "glClear mask:c"},
    {Kind::ClearBuffer, "glClearBufferiv buffer:e drawbuffer:i value:v"},
    {Kind::ClearBuffer, "glClearBufferuiv buffer:e drawbuffer:i value:v"},
    {Kind::ClearBuffer, "glClearBufferfv buffer:e drawbuffer:i value:v"},
    {Kind::ClearBuffer, "glClearBufferfi buffer:e drawbuffer:i depth:f stencil:i"},
    {Kind::ReadPixels, "glReadPixels x:i y:i width:i height:i format:e type:e pixels:p"},
    {Kind::BufferRead, "glGetBufferSubData target:e offset:I size:I data:p"},
    {Kind::BufferRead, "glMapBuffer target:e access:e"},
    {Kind::BufferRead, "glMapBufferRange target:e offset:I length:I access:a"},
    {Kind::Barrier, "glMemoryBarrier barriers:b"},
    {Kind::Barrier, "glMemoryBarrierByRegion barriers:b"},
    {Kind::Relink, "glLinkProgram"},
    {Kind::Relink, "glDeleteProgram"}};

// The calls that make objects, numbered in a record by creation (record_state.hpp).
const std::pair<const char*, GLenum> kCreators[] = {{"Buffers", GL_BUFFER},
                                                    {"Textures", GL_TEXTURE},
                                                    {"VertexArrays", GL_VERTEX_ARRAY},
                                                    {"Framebuffers", GL_FRAMEBUFFER},
                                                    {"Renderbuffers", GL_RENDERBUFFER},
                                                    {"Samplers", GL_SAMPLER},
                                                    {"TransformFeedbacks", GL_TRANSFORM_FEEDBACK}};

Arg arg_of(char code) {
    switch (code) {
        case 'M':
            return Arg::Mode;
        case 'e':
            return Arg::Enum;
        case 'I':
            return Arg::IntPtr;
        case 'u':
            return Arg::Uint;
        case 'o':
            return Arg::Offset;
        case 'p':
            return Arg::Pointer;
        case 'f':
            return Arg::Float;
        case 'c':
            return Arg::ClearBits;
        case 'b':
            return Arg::BarrierBits;
        case 'a':
            return Arg::Access;
        case 't':
            return Arg::Feedback;
        case 'v':
            return Arg::ClearValue;
        default:
            return Arg::Int;
    }
}

std::unordered_map<std::string, Call> known_calls() {
    std::unordered_map<std::string, Call> calls;
    for (const auto& [kind, signature] : kSignatures) {
        std::istringstream words(signature);
        std::string name, arg;
        words >> name;
        Call& c = calls[name];
        c.kind = kind;
        while (words >> arg) c.args.emplace_back(arg.substr(0, arg.find(':')), arg_of(arg.back()));
    }
    for (const auto& [objects, identifier] : kCreators)
        for (const char* verb : {"glGen", "glCreate"})
            calls[verb + std::string(objects)] = {Kind::Create, {}, identifier};
    return calls;
}

// What the record does with the call `name`: Kind::Other for most.
Call call_named(const char* name) {
    static const std::unordered_map<std::string, Call> kCalls = known_calls();
    auto it = kCalls.find(name);
    return it == kCalls.end() ? Call{} : it->second;
}

// The value glClearBuffer{i,ui,f}v `name` is given for `buffer`: four
// components for GL_COLOR, one for GL_DEPTH or GL_STENCIL.
json clear_value(const char* name, GLenum buffer, const void* p) {
    const int n = buffer == GL_COLOR ? 4 : 1;
    const bool floats = std::strcmp(name, "glClearBufferfv") == 0;
    const bool uints = std::strcmp(name, "glClearBufferuiv") == 0;
    json v = json::array();
    for (int k = 0; k < n && p; ++k) {
        if (floats)
            v.push_back(number(static_cast<const GLfloat*>(p)[k]));
        else if (uints)
            v.push_back(static_cast<const GLuint*>(p)[k]);
        else
            v.push_back(static_cast<const GLint*>(p)[k]);
    }
    return v;
}

}  // namespace

struct Recorder::Impl {
    // Each entry point passes the same literal every call: its address is the key.
    std::unordered_map<const char*, Call> calls;
    detail::Names names;
    detail::StateReader state{names};
    bool recording = false, dispatched = false;
    json events = json::array();
    json barriers = json::array();  // issued since the last dispatch

    const Call& call(const char* name) {
        auto it = calls.find(name);
        if (it == calls.end()) it = calls.emplace(name, call_named(name)).first;
        return it->second;
    }
    json arguments(const char* name, const Call& c, va_list args, GLenum& mode, GLbitfield& mask,
                   GLenum& target);
    void record(const char* name, const Call& c, va_list args);
};

json Recorder::Impl::arguments(const char* name, const Call& c, va_list args, GLenum& mode,
                               GLbitfield& mask, GLenum& target) {
    json out = json::object();
    GLenum buffer = 0;
    for (size_t i = 0; i < c.args.size(); ++i) {
        const auto& [arg, how] = c.args[i];
        switch (how) {
            case Arg::Mode:
                mode = va_arg(args, unsigned);
                out[arg] = enum_name(EnumKind::Mode, mode);
                break;
            case Arg::Enum: {
                const GLenum v = va_arg(args, unsigned);
                if (i == 0) target = buffer = v;
                out[arg] = enum_name(EnumKind::Other, v);
                break;
            }
            case Arg::Int:  // GLint and GLsizei come as int
                out[arg] = va_arg(args, int);
                break;
            case Arg::IntPtr:  // GLintptr and GLsizeiptr as long
                out[arg] = va_arg(args, long);
                break;
            case Arg::Uint:
                out[arg] = va_arg(args, unsigned);
                break;
            case Arg::Offset:
                out[arg] = reinterpret_cast<std::uintptr_t>(va_arg(args, const void*));
                break;
            case Arg::Pointer:
                (void)va_arg(args, const void*);
                break;
            case Arg::Float:
                out[arg] = number(va_arg(args, double));
                break;
            case Arg::ClearBits:
                mask = va_arg(args, unsigned);
                out[arg] =
                    bits_name(GLAD_GL_GROUP_ClearBufferMask, mask,
                              {GL_COLOR_BUFFER_BIT, GL_DEPTH_BUFFER_BIT, GL_STENCIL_BUFFER_BIT});
                break;
            case Arg::BarrierBits:
                mask = va_arg(args, unsigned);
                out[arg] = bits_name(GLAD_GL_GROUP_MemoryBarrierMask, mask);
                break;
            case Arg::Access:
                out[arg] = bits_name(GLAD_GL_GROUP_MapBufferAccessMask, va_arg(args, unsigned));
                break;
            case Arg::Feedback:
                out[arg] = names.of(GL_TRANSFORM_FEEDBACK, va_arg(args, unsigned));
                break;
            case Arg::ClearValue:
                out[arg] = clear_value(name, buffer, va_arg(args, const void*));
                break;
        }
    }
    return out;
}

void Recorder::Impl::record(const char* name, const Call& c, va_list args) {
    GLenum mode = GL_TRIANGLES, target = 0;
    GLbitfield mask = 0;
    json event = {{"call", name}};
    json args_json = arguments(name, c, args, mode, mask, target);
    if (c.kind == Kind::Barrier) {
        barriers.push_back(args_json["barriers"]);
        return;
    }
    if (!args_json.empty()) event["args"] = args_json;
    gl_calls::Unobserved quiet;
    switch (c.kind) {
        case Kind::Draw:
        case Kind::DrawElements:
            state.draw(event, mode, c.kind == Kind::DrawElements);
            break;
        case Kind::Dispatch:
            state.dispatch(event);
            break;
        case Kind::Clear:
            state.clear(event, mask & GL_COLOR_BUFFER_BIT, mask & GL_DEPTH_BUFFER_BIT,
                        mask & GL_STENCIL_BUFFER_BIT);
            break;
        case Kind::ClearBuffer:
            state.clear(event, false, false, false);
            break;
        case Kind::ReadPixels:
            state.read_pixels(event);
            break;
        case Kind::BufferRead:
            state.buffer_read(event, target);
            break;
        default:
            break;
    }
    if (c.kind != Kind::Clear && c.kind != Kind::ClearBuffer && (dispatched || !barriers.empty()))
        event["barriers"] = barriers;
    if (c.kind == Kind::Dispatch) {
        dispatched = true;
        barriers = json::array();
    }
    events.push_back(std::move(event));
}

Recorder::Recorder() : impl_(new Impl) {}
Recorder::~Recorder() { delete impl_; }

void Recorder::begin() {
    impl_->recording = true;
    impl_->dispatched = false;
    impl_->events = json::array();
    impl_->barriers = json::array();
}

nlohmann::json Recorder::end() {
    impl_->recording = false;
    json record = {{"version", kVersion}, {"events", std::move(impl_->events)}};
    impl_->events = json::array();
    return record;
}

void Recorder::before(const char* name, int, va_list args) {
    const Call& c = impl_->call(name);
    if (c.kind == Kind::Other || c.kind == Kind::Create) return;
    if (c.kind == Kind::Relink) {
        impl_->state.forget(va_arg(args, unsigned));
        return;
    }
    if (impl_->recording) impl_->record(name, c, args);
}

void Recorder::after(const char* name, int, va_list args) {
    const Call& c = impl_->call(name);
    if (c.kind != Kind::Create) return;
    const int n = va_arg(args, int);
    const GLuint* ids = va_arg(args, const GLuint*);
    for (int i = 0; i < n && ids; ++i) impl_->names.created(c.identifier, ids[i]);
}

std::string record_text(const nlohmann::json& record) {
    std::string out =
        "{\"version\": " + record.value("version", json(kVersion)).dump() + ", \"events\": [";
    const json& events = record.at("events");
    for (size_t i = 0; i < events.size(); ++i)
        out += std::string(i ? "," : "") + "\n" + events[i].dump();
    return out + "\n]}\n";
}

}  // namespace fw::gl_record
