// fw::gl_usage's Checker (usage.hpp): each GL call is sorted once by its
// name; a draw, dispatch or read-back is checked before the driver runs it,
// with what GL says is bound at that moment (queried under
// gl_calls::Unobserved, never tracked from every bind call).
#include "framework/trace/usage.hpp"

#include <algorithm>
#include <cstring>
#include <map>
#include <nlohmann/json.hpp>
#include <unordered_map>

#include "framework/gl/binding.hpp"
#include "framework/trace/calls.hpp"
#include "framework/trace/usage_detail.hpp"

namespace fw::gl_usage {

namespace {

using namespace detail;

thread_local Checker::State* t_current = nullptr;

enum class Kind { Other, Draw, Dispatch, ReadBack, Barrier, Link, Uniform, BufferData, Delete };

Kind kind_of(const char* n) {
    const auto is = [&](const char* s) { return std::strcmp(n, s) == 0; };
    const auto starts = [&](const char* s) { return std::strncmp(n, s, std::strlen(s)) == 0; };
    if ((starts("glDraw") && !starts("glDrawBuffer")) || starts("glMultiDraw")) return Kind::Draw;
    if (starts("glDispatchCompute")) return Kind::Dispatch;
    if (is("glGetBufferSubData") || is("glMapBuffer") || is("glMapBufferRange") ||
        is("glCopyBufferSubData") || is("glReadPixels") || is("glGetTexImage"))
        return Kind::ReadBack;
    if (starts("glMemoryBarrier")) return Kind::Barrier;
    if (is("glLinkProgram")) return Kind::Link;
    if (is("glUniform1i") || is("glUniform1iv") || is("glProgramUniform1i") ||
        is("glProgramUniform1iv"))
        return Kind::Uniform;
    if (is("glBufferData")) return Kind::BufferData;
    if (is("glDeleteBuffers") || is("glDeleteTextures") || is("glDeleteProgram"))
        return Kind::Delete;
    return Kind::Other;
}

// Bytes of a buffer, through GL_COPY_READ_BUFFER (its binding put back).
std::vector<std::uint8_t> read_bytes(GLuint buffer, std::size_t offset, std::size_t size) {
    std::vector<std::uint8_t> bytes(size);
    ScopedBinding bound = bind_buffer_scoped(GL_COPY_READ_BUFFER, buffer);
    glGetBufferSubData(GL_COPY_READ_BUFFER, GLintptr(offset), GLsizeiptr(size), bytes.data());
    return bytes;
}

}  // namespace

struct Checker::State {
    std::unordered_map<const char*, Kind> kinds;
    std::unordered_map<GLuint, ProgramInfo> programs;
    // Each object a dispatch wrote: the barrier bits not issued since, and the dispatch.
    struct Written {
        GLbitfield pending = 0;
        int draw = 0;
        std::string call;
    };
    std::map<Key, Written> written;
    struct Guard {
        GLuint buffer = 0;
        std::size_t offset = 0, element = 1;
        std::vector<std::uint8_t> bytes;
        std::string what;
        bool armed = false;  // a dispatch wrote the buffer since the last look
        int draw = 0;
        std::string call;
    };
    std::vector<Guard> guards;
    std::vector<Finding> findings;
    int draws = 0;
    bool rendering = false;  // between begin_render and end_render
    bool rendered = false;   // a render has ended: findings outside one are dropped

    Kind kind(const char* name) {
        auto found = kinds.find(name);
        if (found != kinds.end()) return found->second;
        return kinds[name] = kind_of(name);
    }

    void add(const std::string& rule, const char* call, int draw, const std::string& detail) {
        for (Finding& f : findings)
            if (f.rule == rule && f.call == call && f.detail == detail) {
                ++f.times;
                return;
            }
        findings.push_back({rule, call, draw, detail, 1});
    }

    ProgramInfo* program(GLuint id) {
        if (id == 0) return nullptr;
        ProgramInfo& info = programs[id];
        if (!info.resources) read_resources(id, info);
        return &info;
    }

    // A read with `bit` of an object a dispatch wrote, with no barrier since.
    void check_barrier(const Key& object, GLbitfield bit, const std::string& where,
                       const char* call) {
        auto w = written.find(object);
        if (w == written.end() || !(w->second.pending & bit)) return;
        add("memory-barrier", call, draws,
            object_name(object) + ", which call " + std::to_string(w->second.draw) + " (" +
                w->second.call + ") wrote, is read as " + where + " with no glMemoryBarrier(" +
                barrier_bit_name(bit) +
                ") since: a GPU may read what it held before the dispatch, whose "
                "writes can still be in flight or in a cache (llvmpipe finishes each dispatch "
                "before it returns)");
        w->second.pending &= ~bit;  // once per write
    }

    void check_guards() {
        for (Guard& g : guards) {
            if (!g.armed) continue;
            g.armed = false;
            glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
            const std::vector<std::uint8_t> now = read_bytes(g.buffer, g.offset, g.bytes.size());
            if (now == g.bytes) continue;
            const auto first = std::mismatch(now.begin(), now.end(), g.bytes.begin()).first;
            const std::size_t at = std::size_t(first - now.begin()) / g.element;
            add("write-past-count", g.call.c_str(), g.draw,
                "the shader wrote past " + g.what + ": element " +
                    std::to_string(g.offset / g.element + at) + " of " + buffer_name(g.buffer) +
                    ", in the guard the lab keeps after them, changed. Invocations past the "
                    "count must do nothing; on a GPU, with no guard after the data, they write "
                    "over whatever follows it in memory");
            g.bytes = now;  // reported once
        }
    }

    void draw_or_dispatch(Kind kind, const char* call) {
        const GLuint id = GLuint(get_integer(GL_CURRENT_PROGRAM));
        ProgramInfo* p = program(id);
        if (!p) return;
        const std::vector<Source> read = call_sources(id, *p, kind == Kind::Draw, call);
        for (const Source& s : read) check_barrier(s.object, s.bit, s.where, call);
        check_samplers(id, *p, call);
        if (kind == Kind::Draw) {
            check_clip(id, *p, call);
            check_feedback(read, *p, call);
        }
    }

    void check_samplers(GLuint id, const ProgramInfo& p, const char* call) {
        for (const Opaque& s : p.samplers) {
            GLint unit = 0;
            glGetUniformiv(id, s.location, &unit);
            const GLenum target = sampler_target(s.type);
            if (unit < 0 || unit >= get_integer(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS)) continue;
            const UnitTexture t = texture_on_unit(GLuint(unit), target);
            if (t.texture)
                check_barrier({Object::Texture, t.texture}, GL_TEXTURE_FETCH_BARRIER_BIT,
                              "a texture (the sampler " + s.name + ")", call);
            if (!t.incomplete.empty())
                add("incomplete-texture", call, draws,
                    "the texture on unit " + std::to_string(unit) + " (" + target_name(target) +
                        ", read by the sampler " + s.name + ") is incomplete: " + t.incomplete +
                        " (GL 4.3 section 8.17); a GPU, like GL's rule, reads (0, 0, 0, 1)");
        }
    }

    void check_clip(GLuint id, const ProgramInfo& p, const char* call) {
        for (int i : p.clip)
            if (!glIsEnabled(GLenum(GL_CLIP_DISTANCE0 + i)))
                add("clip-distance", call, draws,
                    program_name(id) + "'s " + p.clip_stage + " writes gl_ClipDistance[" +
                        std::to_string(i) + "], but GL_CLIP_DISTANCE" + std::to_string(i) +
                        " is not enabled: a GPU ignores a distance that is not enabled and "
                        "draws the primitives whole (GL 4.3 section 13.5); llvmpipe clips by "
                        "every distance written");
    }

    void check_feedback(const std::vector<Source>& read, const ProgramInfo& p, const char* call) {
        GLint active = 0, paused = 0;
        glGetIntegerv(GL_TRANSFORM_FEEDBACK_ACTIVE, &active);
        glGetIntegerv(GL_TRANSFORM_FEEDBACK_PAUSED, &paused);
        if (!active || paused) return;
        for (GLint k = 0; k < std::max(p.feedback_buffers, 1); ++k) {
            const GLint captured = get_integer(GL_TRANSFORM_FEEDBACK_BUFFER_BINDING, GLuint(k));
            for (const Source& s : read)
                if (s.object == Key{Object::Buffer, GLuint(captured)})
                    add("capture-and-source", call, draws,
                        buffer_name(GLuint(captured)) +
                            " is captured into by transform feedback (binding " +
                            std::to_string(k) + ") and read by the same draw as " + s.where +
                            ": the GL 4.3 specification leaves both the values read and those "
                            "written undefined; a GPU may read vertices this draw has already "
                            "overwritten");
        }
    }

    // What a dispatch wrote: its storage blocks and images, not read-only.
    void dispatched(const char* call) {
        const GLuint id = GLuint(get_integer(GL_CURRENT_PROGRAM));
        ProgramInfo* p = program(id);
        if (!p) return;
        std::vector<Key> wrote;
        for (const StorageBlock& s : p->storage) {
            const GLint buffer =
                get_integer(GL_SHADER_STORAGE_BUFFER_BINDING, storage_binding(id, s));
            if (buffer > 0 && !s.readonly) wrote.push_back({Object::Buffer, GLuint(buffer)});
        }
        for (const Opaque& image : p->images) {
            GLint unit = 0;
            glGetUniformiv(id, image.location, &unit);
            const GLint texture = get_integer(GL_IMAGE_BINDING_NAME, GLuint(unit));
            if (texture > 0 && get_integer(GL_IMAGE_BINDING_ACCESS, GLuint(unit)) != GL_READ_ONLY)
                wrote.push_back({Object::Texture, GLuint(texture)});
        }
        for (const Key& k : wrote) {
            written[k] = {GL_ALL_BARRIER_BITS, draws, call};
            for (Guard& g : guards)
                if (k == Key{Object::Buffer, g.buffer})
                    g.armed = true, g.draw = draws, g.call = call;
        }
    }

    void sampler_unit(const char* call, va_list args) {
        const bool direct = std::strncmp(call, "glProgram", 9) == 0;
        const GLuint id = direct ? va_arg(args, unsigned) : GLuint(get_integer(GL_CURRENT_PROGRAM));
        const GLint location = va_arg(args, int);
        std::vector<GLint> values;
        if (call[std::strlen(call) - 1] == 'v') {  // glUniform1iv, glProgramUniform1iv
            const GLsizei count = va_arg(args, int);
            const GLint* v = va_arg(args, const GLint*);
            if (v && count > 0) values.assign(v, v + std::min(count, 64));
        } else {
            values.push_back(va_arg(args, int));
        }
        if (id == 0 || !glIsProgram(id)) return;
        GLint linked = 0;
        glGetProgramiv(id, GL_LINK_STATUS, &linked);
        ProgramInfo* p = linked ? program(id) : nullptr;
        if (!p) return;
        const GLint units = get_integer(GL_MAX_COMBINED_TEXTURE_IMAGE_UNITS);
        for (size_t k = 0; k < p->samplers.size(); ++k) {
            const Opaque& s = p->samplers[k];
            const GLint element = s.location - location;
            if (element < 0 || element >= GLint(values.size())) continue;
            const GLint v = values[size_t(element)];
            if (v >= 0 && v < units) continue;
            const bool texture_enum = v >= GLint(GL_TEXTURE0) && v < GLint(GL_TEXTURE0) + units;
            add("sampler-unit", call, draws + 1,
                std::string(call) + " sets the sampler " + s.name + " to " + std::to_string(v) +
                    (texture_enum ? " (GL_TEXTURE" + std::to_string(v - GLint(GL_TEXTURE0)) +
                                        ", an enum: a sampler takes the unit's number, " +
                                        std::to_string(v - GLint(GL_TEXTURE0)) + ")"
                                  : "") +
                    ", outside 0 to " + std::to_string(units - 1) +
                    ": GL raises GL_INVALID_VALUE and leaves the sampler as it was, on a GPU "
                    "as on llvmpipe" +
                    (rendering || rendered ? "" : " (set in the lab's init)"));
        }
    }

    void deleted(const char* call, va_list args) {
        if (std::strcmp(call, "glDeleteProgram") == 0) {
            programs.erase(va_arg(args, unsigned));
            return;
        }
        const Object kind =
            std::strcmp(call, "glDeleteBuffers") == 0 ? Object::Buffer : Object::Texture;
        const GLsizei n = va_arg(args, int);
        const GLuint* names = va_arg(args, const GLuint*);
        for (GLsizei i = 0; names && i < n; ++i) {
            written.erase({kind, names[i]});
            if (kind == Object::Buffer)
                guards.erase(std::remove_if(guards.begin(), guards.end(),
                                            [&](const Guard& g) { return g.buffer == names[i]; }),
                             guards.end());
        }
    }
};

Checker::Checker() : state_(std::make_unique<State>()) {
    if (!t_current) t_current = state_.get();
}

Checker::~Checker() {
    if (t_current == state_.get()) t_current = nullptr;
}

void Checker::before(const char* name, int, va_list args) {
    State& s = *state_;
    const Kind kind = s.kind(name);
    if (kind == Kind::Other || kind == Kind::Link || kind == Kind::BufferData) return;
    gl_calls::Unobserved quiet;
    switch (kind) {
        case Kind::Draw:
        case Kind::Dispatch:
        case Kind::ReadBack:
            ++s.draws;
            s.check_guards();
            if (kind == Kind::ReadBack)
                for (const Source& read : read_back_sources(name, args))
                    s.check_barrier(read.object, read.bit, read.where, name);
            else
                s.draw_or_dispatch(kind, name);
            break;
        case Kind::Barrier: {
            const GLbitfield bits = va_arg(args, unsigned);
            for (auto& [key, w] : s.written) w.pending &= ~bits;
            break;
        }
        case Kind::Uniform:
            s.sampler_unit(name, args);
            break;
        case Kind::Delete:
            s.deleted(name, args);
            break;
        default:
            break;
    }
}

void Checker::after(const char* name, int, va_list args) {
    State& s = *state_;
    const Kind kind = s.kind(name);
    if (kind != Kind::Link && kind != Kind::Dispatch && kind != Kind::BufferData) return;
    gl_calls::Unobserved quiet;
    if (kind == Kind::Dispatch) return s.dispatched(name);
    if (kind == Kind::BufferData) {
        // A new data store: what a dispatch wrote into the old one is gone.
        const GLenum binding = buffer_binding_query(va_arg(args, unsigned));
        if (binding) s.written.erase({Object::Buffer, GLuint(get_integer(binding))});
        return;
    }
    const GLuint program = va_arg(args, unsigned);
    GLint linked = 0;
    if (glIsProgram(program)) glGetProgramiv(program, GL_LINK_STATUS, &linked);
    if (!linked) {
        s.programs.erase(program);
        return;
    }
    ProgramInfo info;
    read_sources(program, info);
    s.programs[program] = info;
}

void Checker::begin_render() {
    if (state_->rendered) state_->findings.clear();
    state_->draws = 0;
    state_->rendering = true;
}

std::vector<Finding> Checker::end_render() {
    {
        gl_calls::Unobserved quiet;
        state_->check_guards();
    }
    state_->rendered = true;
    state_->rendering = false;
    return std::move(state_->findings);
}

std::string findings_json(const std::vector<Finding>& findings) {
    nlohmann::json out = nlohmann::json::array();
    for (const Finding& f : findings)
        out.push_back({{"rule", f.rule},
                       {"call", f.call},
                       {"draw", f.draw},
                       {"detail", f.detail},
                       {"times", f.times}});
    return out.dump() + "\n";
}

void guard(GLuint buffer, std::size_t offset, std::size_t size, std::size_t element,
           const std::string& what) {
    Checker::State* s = t_current;
    if (!s || size == 0) return;
    gl_calls::Unobserved quiet;
    Checker::State::Guard g;
    g.buffer = buffer;
    g.offset = offset;
    g.element = std::max<std::size_t>(element, 1);
    g.what = what;
    g.bytes = read_bytes(buffer, offset, size);
    auto same = std::find_if(s->guards.begin(), s->guards.end(),
                             [&](const Checker::State::Guard& o) { return o.buffer == buffer; });
    if (same != s->guards.end())
        *same = std::move(g);
    else
        s->guards.push_back(std::move(g));
}

}  // namespace fw::gl_usage
