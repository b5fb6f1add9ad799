// fw::Program: linked shader stages plus checked uniform setters.
//
//   fw::Program prog = fw::Program::from_files({"00_pipeline/pipeline.vert",
//                                                "00_pipeline/pipeline.frag"});
//   prog.set("u_mvp", mvp);  // throws fw::Error unless the program has an active mat4 u_mvp
//   prog.use();              // glUseProgram(prog.id()), before the draw call
//
// Uniforms are set with glProgramUniform*, so set() works whether or not the
// program is in use. Each active uniform's location, type and array size is
// read once at link time; set() checks the name, type and size against them
// and throws fw::Error naming the program's files and its active uniforms,
// instead of GL's silent "location -1 is ignored".
#pragma once

#include <glad/gl.h>

#include <glm/glm.hpp>
#include <map>
#include <memory>
#include <string>
#include <unordered_map>
#include <utility>
#include <vector>

#include "framework/error.hpp"
#include "framework/gl/handle.hpp"
#include "framework/gl/shader.hpp"

namespace fw {

// One active uniform of the default block.
struct UniformInfo {
    std::string name;  // as GL reports it: "u_color", "u_lights[0]", "u_mat.kd"
    GLint location = -1;
    GLenum type = 0;  // GL_FLOAT_VEC3, GL_SAMPLER_2D, ...
    bool is_array = false;
    GLint array_size = 1;     // elements in the whole array (1 if not an array)
    GLint first_element = 0;  // for "u_w[2]": 2; set() may write array_size - first_element
};

// "vec3", "mat4", "sampler2D"... for a uniform type; "0x8B52" if unknown.
std::string glsl_type_name(GLenum type);

class Program {
public:
    Program() = default;

    // Compiles every file (relative to shader_dir() or absolute; stage from
    // the extension) and links them. `label` defaults to the file names
    // joined: "00_pipeline/pipeline.vert + pipeline.frag". `feedback`: the
    // outputs of the last stage before the rasterizer that transform feedback
    // captures, in this order, interleaved into binding 0 of
    // GL_TRANSFORM_FEEDBACK_BUFFER (glTransformFeedbackVaryings before the
    // link, GL_INTERLEAVED_ATTRIBS); a name the stage does not write fails
    // the link with the linker's message.
    static Program from_files(const std::vector<std::string>& files, std::string label = {},
                              std::vector<std::string> feedback = {});
    static Program from_shaders(std::vector<Shader> shaders, std::string label = {},
                                std::vector<std::string> feedback = {});

    // A program that failed to build, kept so that only what draws with it
    // fails: id(), use() and every set() throw `error` again. ProgramLibrary
    // keeps such programs until a reload builds them.
    static Program failed(std::vector<std::string> files, const ShaderError& error,
                          std::vector<std::string> feedback = {});
    // Null when the program built; else why it did not.
    const ShaderError* build_error() const { return error_.get(); }

    GLuint id() const {
        if (error_) throw_build_error();
        return handle_.get();
    }
    // glUseProgram(id()).
    void use() const;
    const std::vector<std::string>& files() const { return files_; }
    // The outputs transform feedback captures (from_files), empty for most programs.
    const std::vector<std::string>& feedback() const { return feedback_; }
    const std::string& label() const { return label_; }

    // Scalars, vectors and matrices. bool uniforms take bool or int, sampler
    // and image uniforms take int (the texture unit).
    void set(const std::string& name, float v) const;
    void set(const std::string& name, double v) const;  // so set("x", 0.5) works
    void set(const std::string& name, int v) const;
    void set(const std::string& name, unsigned v) const;
    void set(const std::string& name, bool v) const;
    void set(const std::string& name, const glm::vec2& v) const;
    void set(const std::string& name, const glm::vec3& v) const;
    void set(const std::string& name, const glm::vec4& v) const;
    void set(const std::string& name, const glm::ivec2& v) const;
    void set(const std::string& name, const glm::ivec3& v) const;
    void set(const std::string& name, const glm::ivec4& v) const;
    void set(const std::string& name, const glm::uvec2& v) const;
    void set(const std::string& name, const glm::uvec3& v) const;
    void set(const std::string& name, const glm::uvec4& v) const;
    void set(const std::string& name, const glm::mat2& v) const;
    void set(const std::string& name, const glm::mat3& v) const;
    void set(const std::string& name, const glm::mat4& v) const;

    // Arrays, from element 0 ("u_w" or "u_w[0]") or from element i ("u_w[2]").
    // More values than the array holds from there is an error; fewer is fine.
    void set(const std::string& name, const std::vector<float>& v) const;
    void set(const std::string& name, const std::vector<int>& v) const;
    void set(const std::string& name, const std::vector<glm::vec2>& v) const;
    void set(const std::string& name, const std::vector<glm::vec3>& v) const;
    void set(const std::string& name, const std::vector<glm::vec4>& v) const;
    void set(const std::string& name, const std::vector<glm::ivec2>& v) const;
    void set(const std::string& name, const std::vector<glm::ivec3>& v) const;
    void set(const std::string& name, const std::vector<glm::ivec4>& v) const;
    void set(const std::string& name, const std::vector<glm::mat3>& v) const;
    void set(const std::string& name, const std::vector<glm::mat4>& v) const;

    // For a uniform that only a student's part reads. A GLSL compiler
    // removes a uniform that does not affect the output, and only uniforms
    // that "will actually be accessed when the executable code is executed"
    // are active (GL 4.3, 7.6 Uniform Variables), so until the student writes
    // the part that reads it, set() would refuse it. This sets the uniform
    // when it is active and returns whether it did; a name that appears in
    // none of the program's files is still an error (misspelt), as in set().
    template <class T>
    bool set_if_active(const std::string& name, const T& value) const {
        if (!has_uniform(name)) {
            require_declared(name);
            return false;
        }
        set(name, value);
        return true;
    }

    bool has_uniform(const std::string& name) const;
    // nullptr if `name` is not an active uniform.
    const UniformInfo* uniform(const std::string& name) const;
    // Active uniforms sorted by name: "u_color: vec3, u_lights[0]: vec3[4], u_mvp: mat4".
    std::string describe_uniforms() const;

private:
    // Looks `name` up, checks that a value of GLSL type `given` may be
    // stored there (`count`: -1 for a plain value, else the number of array
    // elements) and returns its location; throws fw::Error otherwise.
    GLint checked_location(const std::string& name, GLenum given, GLsizei count) const;
    [[noreturn]] void throw_unknown(const std::string& name) const;
    // Throws throw_unknown's error unless `name` appears in a source file.
    void require_declared(const std::string& name) const;
    // The file whose source holds the identifier at the front of `name`; "".
    std::string file_declaring(const std::string& name) const;
    std::string files_text() const;
    void load_uniforms();
    [[noreturn]] void throw_build_error() const;

    detail::Handle handle_;
    std::vector<std::string> files_;
    std::vector<std::string> feedback_;
    std::string label_;
    // Every active uniform, plus for arrays "name" and each "name[i]".
    // Looked up on every set(): hashed, not ordered (describe_uniforms sorts).
    std::unordered_map<std::string, UniformInfo> uniforms_;
    // (file, source) of each stage, to tell "optimised out" from "misspelt".
    std::vector<std::pair<std::string, std::string>> sources_;
    std::shared_ptr<const ShaderError> error_;
};

}  // namespace fw
