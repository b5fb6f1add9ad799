// The record's program part: what a program declares (its interface, read
// once per link) and, at a draw or a dispatch, its uniforms' values, the
// texture and image units its samplers and images read, the buffers of its
// blocks and the transform feedback buffers it writes (record_state.hpp).
#include <algorithm>

#include "framework/trace/record_state.hpp"

namespace fw::gl_record::detail {

namespace {

// A uniform type's components, and how to read them (f, i, u, d).
struct TypeInfo {
    int components;
    char base;
};

TypeInfo type_info(GLenum type) {
    switch (type) {
        case GL_FLOAT:
            return {1, 'f'};
        case GL_FLOAT_VEC2:
            return {2, 'f'};
        case GL_FLOAT_VEC3:
            return {3, 'f'};
        case GL_FLOAT_VEC4:
            return {4, 'f'};
        case GL_FLOAT_MAT2:
            return {4, 'f'};
        case GL_FLOAT_MAT3:
            return {9, 'f'};
        case GL_FLOAT_MAT4:
            return {16, 'f'};
        case GL_FLOAT_MAT2x3:
        case GL_FLOAT_MAT3x2:
            return {6, 'f'};
        case GL_FLOAT_MAT2x4:
        case GL_FLOAT_MAT4x2:
            return {8, 'f'};
        case GL_FLOAT_MAT3x4:
        case GL_FLOAT_MAT4x3:
            return {12, 'f'};
        case GL_DOUBLE:
            return {1, 'd'};
        case GL_DOUBLE_VEC2:
            return {2, 'd'};
        case GL_DOUBLE_VEC3:
            return {3, 'd'};
        case GL_DOUBLE_VEC4:
            return {4, 'd'};
        case GL_DOUBLE_MAT4:
            return {16, 'd'};
        case GL_INT_VEC2:
        case GL_BOOL_VEC2:
            return {2, 'i'};
        case GL_INT_VEC3:
        case GL_BOOL_VEC3:
            return {3, 'i'};
        case GL_INT_VEC4:
        case GL_BOOL_VEC4:
            return {4, 'i'};
        case GL_UNSIGNED_INT:
            return {1, 'u'};
        case GL_UNSIGNED_INT_VEC2:
            return {2, 'u'};
        case GL_UNSIGNED_INT_VEC3:
            return {3, 'u'};
        case GL_UNSIGNED_INT_VEC4:
            return {4, 'u'};
        default:
            return {1, 'i'};  // int, bool, samplers and images: one int
    }
}

// The texture target a sampler type reads, or 0 for an image or a non-sampler.
GLenum sampler_target(GLenum type) {
    switch (type) {
        case GL_SAMPLER_1D:
        case GL_SAMPLER_1D_SHADOW:
        case GL_INT_SAMPLER_1D:
        case GL_UNSIGNED_INT_SAMPLER_1D:
            return GL_TEXTURE_1D;
        case GL_SAMPLER_2D:
        case GL_SAMPLER_2D_SHADOW:
        case GL_INT_SAMPLER_2D:
        case GL_UNSIGNED_INT_SAMPLER_2D:
            return GL_TEXTURE_2D;
        case GL_SAMPLER_3D:
        case GL_INT_SAMPLER_3D:
        case GL_UNSIGNED_INT_SAMPLER_3D:
            return GL_TEXTURE_3D;
        case GL_SAMPLER_CUBE:
        case GL_SAMPLER_CUBE_SHADOW:
        case GL_INT_SAMPLER_CUBE:
        case GL_UNSIGNED_INT_SAMPLER_CUBE:
            return GL_TEXTURE_CUBE_MAP;
        case GL_SAMPLER_2D_ARRAY:
        case GL_SAMPLER_2D_ARRAY_SHADOW:
        case GL_INT_SAMPLER_2D_ARRAY:
        case GL_UNSIGNED_INT_SAMPLER_2D_ARRAY:
            return GL_TEXTURE_2D_ARRAY;
        case GL_SAMPLER_CUBE_MAP_ARRAY:
            return GL_TEXTURE_CUBE_MAP_ARRAY;
        case GL_SAMPLER_2D_RECT:
            return GL_TEXTURE_RECTANGLE;
        case GL_SAMPLER_BUFFER:
            return GL_TEXTURE_BUFFER;
        case GL_SAMPLER_2D_MULTISAMPLE:
            return GL_TEXTURE_2D_MULTISAMPLE;
        default:
            return 0;
    }
}

bool is_image(GLenum type) {
    return (type >= GL_IMAGE_1D && type <= GL_UNSIGNED_INT_IMAGE_2D_MULTISAMPLE_ARRAY);
}

json uniform_value(GLuint program, GLint location, TypeInfo t) {
    GLfloat f[16] = {};
    GLint i[16] = {};
    GLuint u[16] = {};
    GLdouble d[16] = {};
    json out = json::array();
    for (int k = 0; k < t.components; ++k) {
        if (k == 0) {
            if (t.base == 'f') glGetUniformfv(program, location, f);
            if (t.base == 'i') glGetUniformiv(program, location, i);
            if (t.base == 'u') glGetUniformuiv(program, location, u);
            if (t.base == 'd') glGetUniformdv(program, location, d);
        }
        switch (t.base) {
            case 'f':
                out.push_back(number(f[k]));
                break;
            case 'd':
                out.push_back(number(d[k]));
                break;
            case 'u':
                out.push_back(u[k]);
                break;
            default:
                out.push_back(i[k]);
                break;
        }
    }
    return t.components == 1 ? out[0] : out;
}

// The active uniforms outside blocks, sorted by name; an atomic counter
// (which has no location) is left out.
std::vector<ProgramInterface::Uniform> active_uniforms(GLuint program) {
    std::vector<ProgramInterface::Uniform> uniforms;
    GLint count = 0, length = 0;
    glGetProgramiv(program, GL_ACTIVE_UNIFORMS, &count);
    glGetProgramiv(program, GL_ACTIVE_UNIFORM_MAX_LENGTH, &length);
    std::string buf(static_cast<size_t>(std::max(length, 1)) + 1, '\0');
    for (GLuint u = 0; u < static_cast<GLuint>(count); ++u) {
        GLint size = 0, block = -1;
        GLenum type = 0;
        GLsizei n = 0;
        glGetActiveUniform(program, u, static_cast<GLsizei>(buf.size()), &n, &size, &type,
                           buf.data());
        glGetActiveUniformsiv(program, 1, &u, GL_UNIFORM_BLOCK_INDEX, &block);
        if (block != -1) continue;  // its block's buffer binding is recorded instead
        ProgramInterface::Uniform un;
        un.name = buf.substr(0, static_cast<size_t>(n));
        un.type = type;
        un.array = un.name.size() > 3 && un.name.compare(un.name.size() - 3, 3, "[0]") == 0;
        if (un.array) un.name.resize(un.name.size() - 3);
        for (GLint e = 0; e < size; ++e) {
            const std::string element =
                un.array ? un.name + "[" + std::to_string(e) + "]" : un.name;
            un.locations.push_back(glGetUniformLocation(program, element.c_str()));
        }
        if (un.locations.empty() || un.locations[0] < 0) continue;  // an atomic counter
        uniforms.push_back(std::move(un));
    }
    std::sort(uniforms.begin(), uniforms.end(),
              [](const auto& a, const auto& b) { return a.name < b.name; });
    return uniforms;
}

// The active attributes that have a location (not gl_VertexID), sorted by
// location.
std::vector<std::pair<std::string, GLint>> active_attributes(GLuint program) {
    std::vector<std::pair<std::string, GLint>> attributes;
    GLint count = 0, length = 0;
    glGetProgramiv(program, GL_ACTIVE_ATTRIBUTES, &count);
    glGetProgramiv(program, GL_ACTIVE_ATTRIBUTE_MAX_LENGTH, &length);
    std::string buf(static_cast<size_t>(std::max(length, 1)) + 1, '\0');
    for (GLuint a = 0; a < static_cast<GLuint>(count); ++a) {
        GLint size = 0;
        GLenum type = 0;
        GLsizei n = 0;
        glGetActiveAttrib(program, a, static_cast<GLsizei>(buf.size()), &n, &size, &type,
                          buf.data());
        const std::string attr = buf.substr(0, static_cast<size_t>(n));
        const GLint location = glGetAttribLocation(program, attr.c_str());
        if (location >= 0) attributes.emplace_back(attr, location);  // not gl_VertexID
    }
    std::sort(attributes.begin(), attributes.end(),
              [](const auto& a, const auto& b) { return a.second < b.second; });
    return attributes;
}

// The blocks of `interface` (GL_UNIFORM_BLOCK, GL_SHADER_STORAGE_BLOCK): name
// and index, sorted by name.
std::vector<std::pair<std::string, GLuint>> active_blocks(GLuint program, GLenum interface) {
    std::vector<std::pair<std::string, GLuint>> blocks;
    GLint count = 0;
    glGetProgramInterfaceiv(program, interface, GL_ACTIVE_RESOURCES, &count);
    for (GLuint b = 0; b < static_cast<GLuint>(count); ++b) {
        char block[256];
        GLsizei n = 0;
        glGetProgramResourceName(program, interface, b, sizeof block, &n, block);
        blocks.emplace_back(std::string(block, static_cast<size_t>(n)), b);
    }
    std::sort(blocks.begin(), blocks.end());
    return blocks;
}

// Image unit `unit`: the texture bound there, its level and layer, access and format.
json image_unit(const Names& names, GLuint unit) {
    return {{"texture",
             names.of(GL_TEXTURE, static_cast<GLuint>(get_integer(GL_IMAGE_BINDING_NAME, unit)))},
            {"level", get_integer(GL_IMAGE_BINDING_LEVEL, unit)},
            {"layered", get_integer(GL_IMAGE_BINDING_LAYERED, unit)},
            {"layer", get_integer(GL_IMAGE_BINDING_LAYER, unit)},
            {"access", name(static_cast<GLenum>(get_integer(GL_IMAGE_BINDING_ACCESS, unit)))},
            {"format", name(static_cast<GLenum>(get_integer(GL_IMAGE_BINDING_FORMAT, unit)))}};
}

// The buffers bound where the program's uniform and storage blocks read:
// each block's binding point, the buffer there and its range.
void block_buffers(json& event, GLuint program, const ProgramInterface& p, const Names& names) {
    const struct {
        const char* field;
        GLenum interface, binding, start, size;
        const std::vector<std::pair<std::string, GLuint>>& blocks;
    } kinds[] = {{"uniform_buffers", GL_UNIFORM_BLOCK, GL_UNIFORM_BUFFER_BINDING,
                  GL_UNIFORM_BUFFER_START, GL_UNIFORM_BUFFER_SIZE, p.uniform_blocks},
                 {"storage_buffers", GL_SHADER_STORAGE_BLOCK, GL_SHADER_STORAGE_BUFFER_BINDING,
                  GL_SHADER_STORAGE_BUFFER_START, GL_SHADER_STORAGE_BUFFER_SIZE, p.storage_blocks}};
    for (const auto& k : kinds) {
        if (k.blocks.empty()) continue;
        json blocks = json::object();
        for (const auto& [block, index] : k.blocks) {
            const GLenum prop = GL_BUFFER_BINDING;
            GLint b = 0;
            glGetProgramResourceiv(program, k.interface, index, 1, &prop, 1, nullptr, &b);
            const GLuint bi = static_cast<GLuint>(b);
            blocks[block] = {
                {"binding", b},
                {"buffer", names.of(GL_BUFFER, static_cast<GLuint>(get_integer(k.binding, bi)))},
                {"offset", get_integer(k.start, bi)},
                {"size", get_integer(k.size, bi)}};
        }
        event[k.field] = blocks;
    }
}

// While transform feedback is active: whether it is paused, and the buffers
// its outputs are captured into.
void feedback_buffers(json& event, const ProgramInterface& p, const Names& names) {
    GLboolean active = GL_FALSE, paused = GL_FALSE;
    glGetBooleanv(GL_TRANSFORM_FEEDBACK_ACTIVE, &active);
    if (!active) return;
    glGetBooleanv(GL_TRANSFORM_FEEDBACK_PAUSED, &paused);
    json buffers = json::array();
    for (GLuint i = 0; i < static_cast<GLuint>(p.feedback_buffers); ++i)
        buffers.push_back(
            {{"buffer", names.of(GL_BUFFER, static_cast<GLuint>(get_integer(
                                                GL_TRANSFORM_FEEDBACK_BUFFER_BINDING, i)))},
             {"offset", get_integer(GL_TRANSFORM_FEEDBACK_BUFFER_START, i)},
             {"size", get_integer(GL_TRANSFORM_FEEDBACK_BUFFER_SIZE, i)}});
    event["transform_feedback"] = {{"paused", paused == GL_TRUE}, {"buffers", buffers}};
}

}  // namespace

const ProgramInterface& StateReader::interface_of(GLuint program) {
    auto found = programs_.find(program);
    if (found != programs_.end()) return found->second;
    ProgramInterface p;
    p.uniforms = active_uniforms(program);
    p.attributes = active_attributes(program);
    p.uniform_blocks = active_blocks(program, GL_UNIFORM_BLOCK);
    p.storage_blocks = active_blocks(program, GL_SHADER_STORAGE_BLOCK);
    GLint varyings = 0, mode = 0;
    glGetProgramiv(program, GL_TRANSFORM_FEEDBACK_VARYINGS, &varyings);
    glGetProgramiv(program, GL_TRANSFORM_FEEDBACK_BUFFER_MODE, &mode);
    p.feedback_buffers = varyings == 0 ? 0 : mode == GL_SEPARATE_ATTRIBS ? varyings : 1;
    return programs_[program] = std::move(p);
}

// The program by its label; its uniforms' values, its samplers' textures,
// images, and blocks' buffers; at a draw, the transform feedback buffers.
void StateReader::program_state(json& event, GLuint program, bool draw) {
    event["program"] = names_.of(GL_PROGRAM, program);
    if (program == 0) return;
    const ProgramInterface& p = interface_of(program);
    uniform_state(event, program, p);
    block_buffers(event, program, p, names_);
    if (draw) feedback_buffers(event, p, names_);
}

// Each active uniform's value (an array's as a list); for a sampler, the
// texture unit it names, for an image, the image unit.
void StateReader::uniform_state(json& event, GLuint program, const ProgramInterface& p) {
    json uniforms = json::object(), textures = json::object(), images = json::object();
    for (const ProgramInterface::Uniform& u : p.uniforms) {
        const TypeInfo t = type_info(u.type);
        json value = json::array();
        for (GLint location : u.locations) value.push_back(uniform_value(program, location, t));
        uniforms[u.name] = u.array ? value : value[0];
        const GLenum target = sampler_target(u.type);
        if (!target && !is_image(u.type)) continue;
        for (const json& unit : value) {
            const std::string key = std::to_string(unit.get<GLint>());
            if (target) textures[key] = texture_unit(unit.get<GLint>(), target);
            if (is_image(u.type)) images[key] = image_unit(names_, unit.get<GLuint>());
        }
    }
    event["uniforms"] = uniforms;
    if (!textures.empty()) event["textures"] = textures;
    if (!images.empty()) event["images"] = images;
}

}  // namespace fw::gl_record::detail
