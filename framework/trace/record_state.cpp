// The record's queries: what a draw, dispatch, clear or read-back reads of
// GL's state, where it is live (record.hpp); the queries the other parts
// share (record_state.hpp) and the names of GL's objects.
#include "framework/trace/record_state.hpp"

#include <cstdlib>

#include "framework/gl/debug.hpp"
#include "framework/text.hpp"

namespace fw::gl_record::detail {

namespace {

// The capabilities a draw's result can depend on, in the order they are
// listed; the clip distances only up to GL_MAX_CLIP_DISTANCES (8 in GL 4.3).
const GLenum kDrawCapabilities[] = {GL_RASTERIZER_DISCARD,
                                    GL_BLEND,
                                    GL_DEPTH_TEST,
                                    GL_STENCIL_TEST,
                                    GL_SCISSOR_TEST,
                                    GL_CULL_FACE,
                                    GL_CLIP_DISTANCE0,
                                    GL_CLIP_DISTANCE1,
                                    GL_CLIP_DISTANCE2,
                                    GL_CLIP_DISTANCE3,
                                    GL_CLIP_DISTANCE4,
                                    GL_CLIP_DISTANCE5,
                                    GL_CLIP_DISTANCE6,
                                    GL_CLIP_DISTANCE7,
                                    GL_DEPTH_CLAMP,
                                    GL_POLYGON_OFFSET_FILL,
                                    GL_POLYGON_OFFSET_LINE,
                                    GL_POLYGON_OFFSET_POINT,
                                    GL_PROGRAM_POINT_SIZE,
                                    GL_PRIMITIVE_RESTART,
                                    GL_PRIMITIVE_RESTART_FIXED_INDEX,
                                    GL_SAMPLE_ALPHA_TO_COVERAGE,
                                    GL_SAMPLE_COVERAGE,
                                    GL_SAMPLE_SHADING,
                                    GL_SAMPLE_MASK,
                                    GL_FRAMEBUFFER_SRGB,
                                    GL_COLOR_LOGIC_OP,
                                    GL_LINE_SMOOTH,
                                    GL_POLYGON_SMOOTH,
                                    GL_TEXTURE_CUBE_MAP_SEAMLESS};

}  // namespace

std::string name(GLenum v, EnumKind kind) { return enum_name(kind, v); }
std::string name_of(GLenum pname, EnumKind kind) {
    return name(static_cast<GLenum>(get_integer(pname)), kind);
}

json floats(GLenum pname, int n) {
    GLfloat v[4] = {0, 0, 0, 0};
    glGetFloatv(pname, v);
    json out = json::array();
    for (int i = 0; i < n; ++i) out.push_back(number(v[i]));
    return out;
}

json ints(GLenum pname, int n) {
    GLint v[4] = {0, 0, 0, 0};
    glGetIntegerv(pname, v);
    return json(std::vector<GLint>(v, v + n));
}

json number(double v) {
    if (v == 0.0) return 0;  // -0 too
    // Six significant digits, as fw::number_text writes them.
    const double rounded = std::strtod(fw::number_text(v).c_str(), nullptr);
    if (rounded == static_cast<double>(static_cast<long long>(rounded)) && std::abs(rounded) < 1e15)
        return static_cast<long long>(rounded);
    return rounded;
}

void Names::created(GLenum identifier, GLuint id) {
    order_[{identifier, id}] = ++count_[identifier];
}

std::string Names::of(GLenum identifier, GLuint id) const {
    if (id == 0) return identifier == GL_FRAMEBUFFER ? "default" : "none";
    std::string label = object_label(identifier, id);
    if (!label.empty()) return label;
    auto it = order_.find({identifier, id});
    const char* kind = identifier == GL_BUFFER         ? "buffer"
                       : identifier == GL_TEXTURE      ? "texture"
                       : identifier == GL_VERTEX_ARRAY ? "vertex array"
                       : identifier == GL_FRAMEBUFFER  ? "framebuffer"
                       : identifier == GL_RENDERBUFFER ? "renderbuffer"
                       : identifier == GL_SAMPLER      ? "sampler"
                       : identifier == GL_PROGRAM      ? "program"
                                                       : "transform feedback";
    return it == order_.end() ? std::string("unlabelled ") + kind
                              : std::string(kind) + " #" + std::to_string(it->second);
}

void StateReader::draw(json& event, GLenum mode, bool elements) {
    const GLuint program = static_cast<GLuint>(get_integer(GL_CURRENT_PROGRAM));
    json enabled = json::array();
    bool discard = false;
    for (GLenum cap : kDrawCapabilities)
        if (glIsEnabled(cap)) {
            enabled.push_back(name(cap));
            discard = discard || cap == GL_RASTERIZER_DISCARD;
        }
    event["enabled"] = enabled;
    program_state(event, program, true);
    if (program) vertex_state(event, interface_of(program), elements);
    if (mode == GL_PATCHES) event["patch_vertices"] = get_integer(GL_PATCH_VERTICES);
    // With the rasterizer off no fragment is made: what follows is dead.
    if (!discard) fragment_state(event, mode);
}

void StateReader::dispatch(json& event) {
    program_state(event, static_cast<GLuint>(get_integer(GL_CURRENT_PROGRAM)), false);
}

void StateReader::clear(json& event, bool color, bool depth, bool stencil) {
    // A clear obeys the rasterizer discard, the scissor test and the write masks.
    if (glIsEnabled(GL_RASTERIZER_DISCARD)) {
        event["enabled"] = {"GL_RASTERIZER_DISCARD"};
        return;
    }
    if (glIsEnabled(GL_SCISSOR_TEST)) event["scissor"] = ints(GL_SCISSOR_BOX, 4);
    if (color) {
        event["clear_color"] = floats(GL_COLOR_CLEAR_VALUE, 4);
        GLboolean mask[4] = {};
        glGetBooleanv(GL_COLOR_WRITEMASK, mask);
        event["color_mask"] = {mask[0] != 0, mask[1] != 0, mask[2] != 0, mask[3] != 0};
    }
    if (depth) {
        GLboolean mask = GL_TRUE;
        glGetBooleanv(GL_DEPTH_WRITEMASK, &mask);
        event["clear_depth"] = number(floats(GL_DEPTH_CLEAR_VALUE, 1)[0]);
        event["depth_mask"] = mask != 0;
    }
    if (stencil) {
        event["clear_stencil"] = get_integer(GL_STENCIL_CLEAR_VALUE);
        event["stencil_write_mask"] = get_integer(GL_STENCIL_WRITEMASK) & 0xFF;
    }
    event["framebuffer"] = framebuffer(GL_DRAW_FRAMEBUFFER_BINDING, GL_DRAW_FRAMEBUFFER);
}

void StateReader::read_pixels(json& event) {
    event["framebuffer"] = framebuffer(GL_READ_FRAMEBUFFER_BINDING, GL_READ_FRAMEBUFFER);
    event["read_buffer"] = name_of(GL_READ_BUFFER);
    event["pack_alignment"] = get_integer(GL_PACK_ALIGNMENT);
    const GLuint pack = static_cast<GLuint>(get_integer(GL_PIXEL_PACK_BUFFER_BINDING));
    if (pack) event["pack_buffer"] = names_.of(GL_BUFFER, pack);
}

}  // namespace fw::gl_record::detail
