// What fw::gl_usage knows of a program: the clip distances and readonly
// storage blocks its sources declare (GL has no query for either), and its
// samplers, images, inputs and blocks as GL's interface queries give them.
#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <map>
#include <regex>

#include "framework/gl/debug.hpp"
#include "framework/trace/calls.hpp"
#include "framework/trace/usage.hpp"
#include "framework/trace/usage_detail.hpp"

namespace fw::gl_usage {

namespace {

// The source with its comments blanked (newlines kept).
std::string without_comments(const std::string& s) {
    std::string out = s;
    for (size_t i = 0; i + 1 < out.size(); ++i) {
        if (out[i] == '/' && out[i + 1] == '/') {
            while (i < out.size() && out[i] != '\n') out[i++] = ' ';
        } else if (out[i] == '/' && out[i + 1] == '*') {
            const size_t end = out.find("*/", i + 2);
            const size_t stop = end == std::string::npos ? out.size() : end + 2;
            for (; i < stop; ++i)
                if (out[i] != '\n') out[i] = ' ';
            --i;
        }
    }
    return out;
}

bool is_word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

std::string trimmed(const std::string& s) {
    const size_t a = s.find_first_not_of(" \t\r\n"), b = s.find_last_not_of(" \t\r\n");
    return a == std::string::npos ? "" : s.substr(a, b - a + 1);
}

// The integer constants a source names: `#define NAME 2`, `const int NAME = 2;`.
std::map<std::string, long> constants(const std::string& source) {
    std::map<std::string, long> out;
    static const std::regex define(R"(#\s*define\s+(\w+)\s+(\d+)[uU]?\s*(?:\n|$))");
    static const std::regex constant(R"(\bconst\s+u?int\s+(\w+)\s*=\s*(\d+)[uU]?\s*;)");
    for (const std::regex* re : {&define, &constant})
        for (std::sregex_iterator m(source.begin(), source.end(), *re), end; m != end; ++m)
            out[(*m)[1]] = std::strtol((*m)[2].str().c_str(), nullptr, 10);
    return out;
}

// A constant index: a literal or a name of `names`; -1 when it is neither.
long constant_index(const std::string& expression, const std::map<std::string, long>& names) {
    const std::string e = trimmed(expression);
    static const std::regex literal(R"(^(\d+)[uU]?$)");
    std::smatch m;
    if (std::regex_match(e, m, literal)) return std::strtol(m[1].str().c_str(), nullptr, 10);
    auto found = names.find(e);
    return found == names.end() ? -1 : found->second;
}

// The size an output redeclaration gives gl_ClipDistance, or -1.
long redeclared_size(const std::string& source, const std::map<std::string, long>& names) {
    static const std::regex plain(R"(\bout\s+float\s+gl_ClipDistance\s*\[([^\]]*)\])");
    static const std::regex block(
        R"(\bout\s+gl_PerVertex\s*\{[^}]*\bfloat\s+gl_ClipDistance\s*\[([^\]]*)\])");
    std::smatch m;
    if (std::regex_search(source, m, plain) || std::regex_search(source, m, block))
        return constant_index(m[1], names);
    return -1;
}

size_t skip_space(const std::string& s, size_t i) {
    while (i < s.size() && std::isspace(static_cast<unsigned char>(s[i]))) ++i;
    return i;
}

// Whether an assignment operator starts at s[i]: = (not ==), or +=, -=, ...
bool assigns_at(const std::string& s, size_t i) {
    if (i >= s.size()) return false;
    if (s[i] == '=') return i + 1 >= s.size() || s[i + 1] != '=';
    static const std::string ops = "+-*/%&|^";
    return ops.find(s[i]) != std::string::npos && i + 1 < s.size() && s[i + 1] == '=';
}

}  // namespace

ClipWrites clip_distances_written(const std::string& raw) {
    const std::string source = without_comments(raw);
    const std::map<std::string, long> names = constants(source);
    const long size = redeclared_size(source, names);
    std::set<int> indices;
    ClipWrites out;
    auto all_below_size = [&] {
        if (size < 0) out.known = false;
        for (long i = 0; i < size; ++i) indices.insert(static_cast<int>(i));
    };
    const std::string word = "gl_ClipDistance";
    for (size_t at = source.find(word); at != std::string::npos; at = source.find(word, at + 1)) {
        const size_t end = at + word.size();
        if ((at > 0 && is_word_char(source[at - 1])) ||
            (end < source.size() && is_word_char(source[end])))
            continue;
        // gl_in[i].gl_ClipDistance reads an input.
        size_t before = at;
        while (before > 0 && std::isspace(static_cast<unsigned char>(source[before - 1]))) --before;
        if (before > 0 && source[before - 1] == '.') continue;
        size_t i = skip_space(source, end);
        if (i < source.size() && source[i] == '[') {
            const size_t close = source.find(']', i);
            if (close == std::string::npos) continue;
            const std::string index = source.substr(i + 1, close - i - 1);
            if (!assigns_at(source, skip_space(source, close + 1))) continue;
            const long k = constant_index(index, names);
            if (k >= 0)
                indices.insert(static_cast<int>(k));
            else
                all_below_size();
        } else if (assigns_at(source, i)) {
            all_below_size();
        }
    }
    out.indices.assign(indices.begin(), indices.end());
    return out;
}

namespace detail {

std::set<std::string> readonly_blocks(const std::string& raw) {
    const std::string source = without_comments(raw);
    std::set<std::string> out;
    static const std::regex block(R"(\bbuffer\s+(\w+)\s*\{)");
    static const std::regex readonly(R"(\breadonly\b)");
    for (std::sregex_iterator m(source.begin(), source.end(), block), end; m != end; ++m) {
        // The qualifiers before `buffer`: back to the end of the last statement.
        const size_t at = static_cast<size_t>(m->position(0));
        const size_t from = source.find_last_of(";}", at);
        const std::string qualifiers =
            source.substr(from == std::string::npos ? 0 : from + 1, at - (from + 1));
        if (std::regex_search(qualifiers, readonly)) out.insert((*m)[1]);
    }
    return out;
}

void read_sources(GLuint program, ProgramInfo& info) {
    gl_calls::Unobserved quiet;
    GLint count = 0;
    glGetProgramiv(program, GL_ATTACHED_SHADERS, &count);
    std::vector<GLuint> shaders(static_cast<size_t>(std::max(count, 0)));
    if (count > 0) glGetAttachedShaders(program, count, nullptr, shaders.data());
    // The last stage before the rasterizer writes the clip distances it uses.
    const std::pair<GLenum, const char*> order[] = {
        {GL_GEOMETRY_SHADER, "geometry shader"},
        {GL_TESS_EVALUATION_SHADER, "tessellation evaluation shader"},
        {GL_VERTEX_SHADER, "vertex shader"}};
    std::map<GLenum, std::string> sources;
    for (GLuint s : shaders) {
        GLint type = 0, length = 0;
        glGetShaderiv(s, GL_SHADER_TYPE, &type);
        glGetShaderiv(s, GL_SHADER_SOURCE_LENGTH, &length);
        std::string text(static_cast<size_t>(std::max(length, 1)), '\0');
        GLsizei got = 0;
        glGetShaderSource(s, static_cast<GLsizei>(text.size()), &got, text.data());
        text.resize(static_cast<size_t>(got));
        sources[static_cast<GLenum>(type)] += text + "\n";
    }
    info = ProgramInfo();
    info.sources_seen = true;
    for (const auto& [type, name] : order) {
        auto found = sources.find(type);
        if (found == sources.end()) continue;
        const ClipWrites w = clip_distances_written(found->second);
        info.clip = w.indices;
        info.clip_stage = name;
        break;
    }
    auto compute = sources.find(GL_COMPUTE_SHADER);
    if (compute != sources.end()) info.readonly_blocks = readonly_blocks(compute->second);
}

void read_resources(GLuint program, ProgramInfo& info) {
    gl_calls::Unobserved quiet;
    info.resources = true;
    GLint count = 0;
    glGetProgramInterfaceiv(program, GL_UNIFORM, GL_ACTIVE_RESOURCES, &count);
    const GLenum props[] = {GL_TYPE, GL_ARRAY_SIZE, GL_LOCATION, GL_NAME_LENGTH};
    for (GLint i = 0; i < count; ++i) {
        GLint v[4] = {};
        glGetProgramResourceiv(program, GL_UNIFORM, static_cast<GLuint>(i), 4, props, 4, nullptr,
                               v);
        const auto type = static_cast<GLenum>(v[0]);
        if (v[2] < 0 || !(is_sampler(type) || is_image(type))) continue;
        std::string name(static_cast<size_t>(std::max(v[3], 1)), '\0');
        GLsizei length = 0;
        glGetProgramResourceName(program, GL_UNIFORM, static_cast<GLuint>(i), v[3], &length,
                                 name.data());
        name.resize(static_cast<size_t>(length));
        std::vector<Opaque>& list = is_sampler(type) ? info.samplers : info.images;
        const std::string base = name.size() > 3 && name.compare(name.size() - 3, 3, "[0]") == 0
                                     ? name.substr(0, name.size() - 3)
                                     : name;
        for (GLint e = 0; e < std::max(v[1], 1); ++e) {
            const std::string element = v[1] > 1 ? base + "[" + std::to_string(e) + "]" : name;
            const GLint location =
                e == 0 ? v[2] : glGetProgramResourceLocation(program, GL_UNIFORM, element.c_str());
            if (location >= 0) list.push_back({element, location, type});
        }
    }
    glGetProgramInterfaceiv(program, GL_PROGRAM_INPUT, GL_ACTIVE_RESOURCES, &count);
    for (GLint i = 0; i < count; ++i) {
        const GLenum location_prop = GL_LOCATION;
        GLint location = -1;
        glGetProgramResourceiv(program, GL_PROGRAM_INPUT, static_cast<GLuint>(i), 1, &location_prop,
                               1, nullptr, &location);
        if (location >= 0) info.inputs.push_back(location);
    }
    glGetProgramInterfaceiv(program, GL_UNIFORM_BLOCK, GL_ACTIVE_RESOURCES, &info.uniform_blocks);
    glGetProgramInterfaceiv(program, GL_SHADER_STORAGE_BLOCK, GL_ACTIVE_RESOURCES, &count);
    for (GLint i = 0; i < count; ++i) {
        char name[256] = {};
        glGetProgramResourceName(program, GL_SHADER_STORAGE_BLOCK, static_cast<GLuint>(i),
                                 sizeof name, nullptr, name);
        std::string block = name;
        // An array of blocks is named by element ("Block[0]"): its declaration by the block's name.
        const std::string declared = block.substr(0, block.find('['));
        info.storage.push_back(
            {static_cast<GLuint>(i), block, info.readonly_blocks.count(declared) > 0});
    }
    GLint mode = 0, varyings = 0;
    glGetProgramiv(program, GL_TRANSFORM_FEEDBACK_BUFFER_MODE, &mode);
    glGetProgramiv(program, GL_TRANSFORM_FEEDBACK_VARYINGS, &varyings);
    info.feedback_buffers = varyings == 0 ? 0 : (mode == GL_INTERLEAVED_ATTRIBS ? 1 : varyings);
}

namespace {

std::string named(GLenum identifier, GLuint id, const char* kind) {
    gl_calls::Unobserved quiet;
    const std::string label = object_label(identifier, id);
    return label.empty() ? std::string(kind) + " " + std::to_string(id)
                         : std::string("the ") + kind + " '" + label + "'";
}

}  // namespace

std::string buffer_name(GLuint buffer) { return named(GL_BUFFER, buffer, "buffer"); }
std::string texture_name(GLuint texture) { return named(GL_TEXTURE, texture, "texture"); }
std::string program_name(GLuint program) { return named(GL_PROGRAM, program, "program"); }

}  // namespace detail

}  // namespace fw::gl_usage
