#include "framework/gl/debug.hpp"

#include <algorithm>
#include <cstdio>
#include <utility>

#include "framework/error.hpp"
#include "framework/text.hpp"

namespace fw {

namespace {

// Bounded so that a program that never calls check_gl() cannot grow it forever.
constexpr std::size_t kMaxMessages = 32;
thread_local std::vector<std::string> t_messages;
thread_local std::size_t t_dropped = 0;

void GLAD_API_PTR on_debug_message(GLenum /*source*/, GLenum type, GLuint /*id*/, GLenum severity,
                                   GLsizei length, const GLchar* message, const void* /*user*/) {
    if (type != GL_DEBUG_TYPE_ERROR && severity != GL_DEBUG_SEVERITY_HIGH) return;
    if (t_messages.size() >= kMaxMessages) {
        ++t_dropped;
        return;
    }
    std::string text =
        length >= 0 ? std::string(message, static_cast<std::size_t>(length)) : std::string(message);
    while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
    t_messages.push_back(std::move(text));
}

std::string bound_label(GLenum binding, GLenum identifier, const char* what) {
    GLint id = 0;
    glGetIntegerv(binding, &id);
    std::string out = what;
    if (id == 0) {
        if (identifier == GL_FRAMEBUFFER) return out + " 0 (default)";
        return out + " none";
    }
    std::string label = object_label(identifier, static_cast<GLuint>(id));
    if (label.empty()) return out + " " + std::to_string(id) + " (unlabelled)";
    return out + " '" + label + "'";
}

}  // namespace

void enable_debug_output() {
    glEnable(GL_DEBUG_OUTPUT);
    glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
    glDebugMessageCallback(on_debug_message, nullptr);
    glDebugMessageControl(GL_DONT_CARE, GL_DONT_CARE, GL_DONT_CARE, 0, nullptr, GL_TRUE);
}

std::vector<std::string> take_debug_messages() {
    std::vector<std::string> out = std::move(t_messages);
    t_messages.clear();
    if (t_dropped > 0) {
        out.push_back("(" + std::to_string(t_dropped) + " more messages dropped)");
        t_dropped = 0;
    }
    return out;
}

void check_gl(const char* where) {
    std::vector<GLenum> codes;
    // glGetError returns one recorded flag per call; several may be set.
    for (int i = 0; i < 16; ++i) {
        GLenum e = glGetError();
        if (e == GL_NO_ERROR) break;
        codes.push_back(e);
    }
    std::vector<std::string> messages = take_debug_messages();
    if (codes.empty() && messages.empty()) return;

    std::string text = "GL error after " + std::string(where) + ": ";
    text += codes.empty() ? "debug message" : join(codes, ", ", [](GLenum e) {
        return gl_enum_name(e, GLAD_GL_GROUP_ErrorCode);
    });
    if (!messages.empty()) text += ": " + join(messages, "; ");
    text += " [" + bound_label(GL_CURRENT_PROGRAM, GL_PROGRAM, "program") + ", " +
            bound_label(GL_VERTEX_ARRAY_BINDING, GL_VERTEX_ARRAY, "vertex array") + ", " +
            bound_label(GL_DRAW_FRAMEBUFFER_BINDING, GL_FRAMEBUFFER, "framebuffer") + "]";
    throw Error(text);
}

void set_object_label(GLenum identifier, GLuint id, const std::string& label) {
    if (label.empty()) return;
    GLint max_length = 0;
    glGetIntegerv(GL_MAX_LABEL_LENGTH, &max_length);
    std::size_t n = label.size();
    if (max_length > 0 && n >= static_cast<std::size_t>(max_length))
        n = static_cast<std::size_t>(max_length) - 1;
    glObjectLabel(identifier, id, static_cast<GLsizei>(n), label.data());
}

std::string object_label(GLenum identifier, GLuint id) {
    GLsizei length = 0;
    glGetObjectLabel(identifier, id, 0, &length, nullptr);
    if (length <= 0) return {};
    std::string label(static_cast<std::size_t>(length) + 1, '\0');
    glGetObjectLabel(identifier, id, length + 1, &length, label.data());
    label.resize(static_cast<std::size_t>(length));
    return label;
}

const char* gl_enum_name_or_null(GLenum value, GladGlGroup group) {
    const GladGlName* begin = glad_gl_names;
    const GladGlName* end = glad_gl_names + glad_gl_name_count;
    const auto before = [](const GladGlName& row, std::pair<unsigned, GLenum> key) {
        return std::make_pair(unsigned{row.group}, row.value) < key;
    };
    const GladGlName* it =
        std::lower_bound(begin, end, std::make_pair(unsigned(group), value), before);
    return it != end && it->group == group && it->value == value ? it->name : nullptr;
}

std::string gl_enum_name(GLenum value, GladGlGroup group) {
    if (const char* name = gl_enum_name_or_null(value, group)) return name;
    char buf[16];
    std::snprintf(buf, sizeof buf, "0x%04X", value);
    return buf;
}

}  // namespace fw
