// Program::set: the checked uniform setters (see program.hpp).
#include <cstdio>
#include <glm/gtc/type_ptr.hpp>

#include "framework/error.hpp"
#include "framework/gl/program.hpp"

namespace fw {

namespace {

struct TypeName {
    GLenum type;
    const char* name;
};

// Opaque types (samplers, images) are set with an int: the unit they read.
constexpr TypeName kBasicTypes[] = {
    {GL_FLOAT, "float"},
    {GL_FLOAT_VEC2, "vec2"},
    {GL_FLOAT_VEC3, "vec3"},
    {GL_FLOAT_VEC4, "vec4"},
    {GL_DOUBLE, "double"},
    {GL_DOUBLE_VEC2, "dvec2"},
    {GL_DOUBLE_VEC3, "dvec3"},
    {GL_DOUBLE_VEC4, "dvec4"},
    {GL_INT, "int"},
    {GL_INT_VEC2, "ivec2"},
    {GL_INT_VEC3, "ivec3"},
    {GL_INT_VEC4, "ivec4"},
    {GL_UNSIGNED_INT, "uint"},
    {GL_UNSIGNED_INT_VEC2, "uvec2"},
    {GL_UNSIGNED_INT_VEC3, "uvec3"},
    {GL_UNSIGNED_INT_VEC4, "uvec4"},
    {GL_BOOL, "bool"},
    {GL_BOOL_VEC2, "bvec2"},
    {GL_BOOL_VEC3, "bvec3"},
    {GL_BOOL_VEC4, "bvec4"},
    {GL_FLOAT_MAT2, "mat2"},
    {GL_FLOAT_MAT3, "mat3"},
    {GL_FLOAT_MAT4, "mat4"},
    {GL_FLOAT_MAT2x3, "mat2x3"},
    {GL_FLOAT_MAT2x4, "mat2x4"},
    {GL_FLOAT_MAT3x2, "mat3x2"},
    {GL_FLOAT_MAT3x4, "mat3x4"},
    {GL_FLOAT_MAT4x2, "mat4x2"},
    {GL_FLOAT_MAT4x3, "mat4x3"},
    {GL_DOUBLE_MAT4, "dmat4"},
};

constexpr TypeName kOpaqueTypes[] = {
    {GL_SAMPLER_1D, "sampler1D"},
    {GL_SAMPLER_2D, "sampler2D"},
    {GL_SAMPLER_3D, "sampler3D"},
    {GL_SAMPLER_CUBE, "samplerCube"},
    {GL_SAMPLER_2D_SHADOW, "sampler2DShadow"},
    {GL_SAMPLER_CUBE_SHADOW, "samplerCubeShadow"},
    {GL_SAMPLER_2D_ARRAY, "sampler2DArray"},
    {GL_SAMPLER_2D_ARRAY_SHADOW, "sampler2DArrayShadow"},
    {GL_SAMPLER_2D_MULTISAMPLE, "sampler2DMS"},
    {GL_SAMPLER_BUFFER, "samplerBuffer"},
    {GL_SAMPLER_2D_RECT, "sampler2DRect"},
    {GL_INT_SAMPLER_2D, "isampler2D"},
    {GL_UNSIGNED_INT_SAMPLER_2D, "usampler2D"},
    {GL_INT_SAMPLER_3D, "isampler3D"},
    {GL_UNSIGNED_INT_SAMPLER_3D, "usampler3D"},
    {GL_IMAGE_2D, "image2D"},
    {GL_IMAGE_3D, "image3D"},
    {GL_INT_IMAGE_2D, "iimage2D"},
    {GL_UNSIGNED_INT_IMAGE_2D, "uimage2D"},
    {GL_IMAGE_CUBE, "imageCube"},
    {GL_IMAGE_2D_ARRAY, "image2DArray"},
    {GL_IMAGE_BUFFER, "imageBuffer"},
    {GL_UNSIGNED_INT_ATOMIC_COUNTER, "atomic_uint"},
};

bool is_opaque(GLenum type) {
    for (const TypeName& t : kOpaqueTypes)
        if (t.type == type) return true;
    // Types outside the table that are still samplers or images: GL gives
    // them names, but only these two ranges of enums.
    return (type >= GL_SAMPLER_1D && type <= GL_SAMPLER_2D_SHADOW) ||
           (type >= GL_IMAGE_1D && type <= GL_UNSIGNED_INT_IMAGE_2D_MULTISAMPLE_ARRAY);
}

// GL accepts more than this (any glUniform*i on a float, say, is an error,
// but glUniform1i on a bool is not). The framework accepts exactly what the
// GLSL type says, plus ints for bools and for the units of samplers.
bool accepts(GLenum declared, GLenum given) {
    if (declared == given) return true;
    switch (given) {
        case GL_INT:
            return declared == GL_BOOL || is_opaque(declared);
        case GL_INT_VEC2:
            return declared == GL_BOOL_VEC2;
        case GL_INT_VEC3:
            return declared == GL_BOOL_VEC3;
        case GL_INT_VEC4:
            return declared == GL_BOOL_VEC4;
        default:
            return false;
    }
}

std::string array_type(GLenum type, GLint size) {
    return glsl_type_name(type) + "[" + std::to_string(size) + "]";
}

}  // namespace

std::string glsl_type_name(GLenum type) {
    for (const TypeName& t : kBasicTypes)
        if (t.type == type) return t.name;
    for (const TypeName& t : kOpaqueTypes)
        if (t.type == type) return t.name;
    char buf[32];
    std::snprintf(buf, sizeof buf, "GL type 0x%04X", type);
    return buf;
}

GLint Program::checked_location(const std::string& name, GLenum given, GLsizei count) const {
    const UniformInfo* u = uniform(name);
    if (!u) throw_unknown(name);
    // The common case first: every draw sets uniforms, so the checks must
    // cost no more than the lookup. Messages are built only on failure.
    if (count != 0 && accepts(u->type, given) && count <= u->array_size - u->first_element)
        return u->location;
    const std::string declared =
        u->is_array ? array_type(u->type, u->array_size) : glsl_type_name(u->type);
    const std::string given_text = count < 0 ? glsl_type_name(given) : array_type(given, count);
    const std::string where = "program '" + label_ + "' (files: " + files_text() + "): ";
    if (count == 0)
        throw Error(where + "uniform '" + name + "' was set with an empty array; give at least " +
                    "one value");
    if (!accepts(u->type, given))
        throw Error(where + "uniform '" + name + "' is declared " + declared +
                    " but was set with " + given_text + "; pass a value of type " +
                    glsl_type_name(u->type));
    const GLint room = u->array_size - u->first_element;
    if (count > room) {
        std::string from = u->first_element > 0
                               ? " from element " + std::to_string(u->first_element) +
                                     ", which leaves room for " + std::to_string(room)
                               : "";
        throw Error(where + "uniform '" + name + "' is declared " + declared +
                    " but was set with " + given_text + from +
                    "; pass at most that many values or enlarge the array in the shader");
    }
    return u->location;
}

// Scalars and vectors: one glProgramUniform call each. `count` is -1 for a
// single value, so the type check and the error text know it is no array.
void Program::set(const std::string& name, float v) const {
    glProgramUniform1f(id(), checked_location(name, GL_FLOAT, -1), v);
}
void Program::set(const std::string& name, double v) const {
    const UniformInfo* u = uniform(name);
    if (u && u->type == GL_DOUBLE)
        glProgramUniform1d(id(), u->location, v);
    else
        set(name, static_cast<float>(v));
}
void Program::set(const std::string& name, int v) const {
    glProgramUniform1i(id(), checked_location(name, GL_INT, -1), v);
}
void Program::set(const std::string& name, unsigned v) const {
    glProgramUniform1ui(id(), checked_location(name, GL_UNSIGNED_INT, -1), v);
}
void Program::set(const std::string& name, bool v) const {
    glProgramUniform1i(id(), checked_location(name, GL_BOOL, -1), v ? 1 : 0);
}

#define FW_SET_VALUE(T, TYPE, CALL)                                         \
    void Program::set(const std::string& name, const T& v) const {          \
        CALL(id(), checked_location(name, TYPE, -1), 1, glm::value_ptr(v)); \
    }
#define FW_SET_MATRIX(T, TYPE, CALL)                                                  \
    void Program::set(const std::string& name, const T& v) const {                    \
        CALL(id(), checked_location(name, TYPE, -1), 1, GL_FALSE, glm::value_ptr(v)); \
    }
// Arrays: std::vector stores its elements contiguously, and each glm type is
// tightly packed, so v.data() is exactly what glProgramUniform*v expects.
#define FW_SET_ARRAY(T, SCALAR, TYPE, CALL)                                                        \
    void Program::set(const std::string& name, const std::vector<T>& v) const {                    \
        const auto n = static_cast<GLsizei>(v.size());                                             \
        CALL(id(), checked_location(name, TYPE, n), n, reinterpret_cast<const SCALAR*>(v.data())); \
    }

FW_SET_VALUE(glm::vec2, GL_FLOAT_VEC2, glProgramUniform2fv)
FW_SET_VALUE(glm::vec3, GL_FLOAT_VEC3, glProgramUniform3fv)
FW_SET_VALUE(glm::vec4, GL_FLOAT_VEC4, glProgramUniform4fv)
FW_SET_VALUE(glm::ivec2, GL_INT_VEC2, glProgramUniform2iv)
FW_SET_VALUE(glm::ivec3, GL_INT_VEC3, glProgramUniform3iv)
FW_SET_VALUE(glm::ivec4, GL_INT_VEC4, glProgramUniform4iv)
FW_SET_VALUE(glm::uvec2, GL_UNSIGNED_INT_VEC2, glProgramUniform2uiv)
FW_SET_VALUE(glm::uvec3, GL_UNSIGNED_INT_VEC3, glProgramUniform3uiv)
FW_SET_VALUE(glm::uvec4, GL_UNSIGNED_INT_VEC4, glProgramUniform4uiv)
FW_SET_MATRIX(glm::mat2, GL_FLOAT_MAT2, glProgramUniformMatrix2fv)
FW_SET_MATRIX(glm::mat3, GL_FLOAT_MAT3, glProgramUniformMatrix3fv)
FW_SET_MATRIX(glm::mat4, GL_FLOAT_MAT4, glProgramUniformMatrix4fv)
#undef FW_SET_VALUE
#undef FW_SET_MATRIX

FW_SET_ARRAY(float, GLfloat, GL_FLOAT, glProgramUniform1fv)
FW_SET_ARRAY(int, GLint, GL_INT, glProgramUniform1iv)
FW_SET_ARRAY(glm::vec2, GLfloat, GL_FLOAT_VEC2, glProgramUniform2fv)
FW_SET_ARRAY(glm::vec3, GLfloat, GL_FLOAT_VEC3, glProgramUniform3fv)
FW_SET_ARRAY(glm::vec4, GLfloat, GL_FLOAT_VEC4, glProgramUniform4fv)
FW_SET_ARRAY(glm::ivec2, GLint, GL_INT_VEC2, glProgramUniform2iv)
FW_SET_ARRAY(glm::ivec3, GLint, GL_INT_VEC3, glProgramUniform3iv)
FW_SET_ARRAY(glm::ivec4, GLint, GL_INT_VEC4, glProgramUniform4iv)
#undef FW_SET_ARRAY

// Matrices: GLM stores columns one after another, which is what GL reads
// with transpose = GL_FALSE.
void Program::set(const std::string& name, const std::vector<glm::mat3>& v) const {
    const auto n = static_cast<GLsizei>(v.size());
    glProgramUniformMatrix3fv(id(), checked_location(name, GL_FLOAT_MAT3, n), n, GL_FALSE,
                              reinterpret_cast<const GLfloat*>(v.data()));
}
void Program::set(const std::string& name, const std::vector<glm::mat4>& v) const {
    const auto n = static_cast<GLsizei>(v.size());
    glProgramUniformMatrix4fv(id(), checked_location(name, GL_FLOAT_MAT4, n), n, GL_FALSE,
                              reinterpret_cast<const GLfloat*>(v.data()));
}

}  // namespace fw
