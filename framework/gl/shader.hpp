// fw::Shader: one compiled GLSL stage. Programs are usually made straight
// from files (fw::Program::from_files); a Shader on its own is for tests and
// for sharing a stage between programs.
//
// A compile error throws fw::Error with the file, the stage, the compiler's
// log and the offending source lines:
//   shaders/tests/broken.frag:12: fragment shader failed to compile:
//     0:12(13): error: `foo' undeclared
//     12 |     color = foo;
#pragma once

#include <glad/gl.h>

#include <map>
#include <string>
#include <vector>

#include "framework/gl/handle.hpp"

namespace fw {

enum class Stage { Vertex, TessControl, TessEvaluation, Geometry, Fragment, Compute };

// GL_VERTEX_SHADER ... and "vertex", "tessellation control", ... for messages.
GLenum gl_shader_type(Stage stage);
const char* stage_name(Stage stage);
// From the file extension: .vert .tesc .tese .geom .frag .comp. Anything else
// throws UsageError listing them.
Stage stage_from_path(const std::string& path);

// The directory shaders are read from: $LAB_SHADER_DIR if set, else the
// source tree's shaders/ (LAB_SOURCE_DIR "/shaders").
std::string shader_dir();
// `relative` resolved against shader_dir(); an absolute path is returned as is.
std::string shader_path(const std::string& relative);

// Texts that stand in for shader files, by the path relative to shader_dir()
// that a program names ("07_framebuffer_ops/cutout.frag"): Shader::from_file
// compiles the text instead of reading the file, and takes its includes from
// the file's own folder. For `lab grade-child`, which renders a job with one
// of the course's files in place of the student's (its "shader_overrides").
// Replaces the texts set before; an empty map ends them.
void set_shader_overrides(std::map<std::string, std::string> texts);

// A file pasted into a shader by `#include "name"` (see Shader::from_file).
struct IncludedFile {
    std::string path;  // as messages show it
    std::string text;
};

// The compile error text shown above, from a raw info log. Understands
// Mesa's "0:12(5): error: ..." and NVIDIA's "0(12) : error C1008: ..." line
// numbers; other lines are passed through. `path` is what the message shows.
// A log line of source string k >= 1 refers to line n of included[k - 1].
std::string format_compile_error(const std::string& path, Stage stage, const std::string& log,
                                 const std::string& source,
                                 const std::vector<IncludedFile>& included = {});
// The source line number a log line refers to, or 0 if it names none;
// `source_string` (if given) gets the source string number (0: the file itself).
int log_line_number(const std::string& log_line, int* source_string = nullptr);

// Replaces each line `#include "name"` of `text` (the file at `path`) by the
// file `name` in the same folder, between #line directives that tell each
// file's lines apart: included file k is source string k, from line
// k * 100000 + 1; the shader's own lines keep their numbers.
// format_compile_error maps them back. Included files may not include others. Throws fw::Error
// naming the line and the path of a file it cannot read.
std::string expand_includes(const std::string& text, const std::string& path,
                            std::vector<IncludedFile>& included);

class Shader {
public:
    Shader() = default;

    // Reads and compiles `path` (absolute, or relative to shader_dir()); the
    // stage comes from its extension. `#include "shared.glsl"` lines paste a
    // file from the same folder: a lab's header of names that its C++
    // includes too (attribute locations, enum values). A text set by
    // set_shader_overrides for `path` is compiled instead of the file.
    // Throws fw::Error naming the path if a file cannot be read or does not
    // compile.
    static Shader from_file(const std::string& path);
    // Compiles `source`; `name` stands for the file in messages and labels.
    static Shader from_source(Stage stage, const std::string& source, const std::string& name);

    GLuint id() const { return handle_.get(); }
    Stage stage() const { return stage_; }
    // The resolved path (or the name given to from_source).
    const std::string& path() const { return path_; }
    const std::string& source() const { return source_; }

private:
    // Compiles `expanded` (the file's `text` with its includes pasted in).
    static Shader compile(Stage stage, const std::string& expanded, const std::string& name,
                          const std::string& text, const std::vector<IncludedFile>& included);

    detail::Handle handle_;
    Stage stage_ = Stage::Vertex;
    std::string path_;
    std::string source_;
};

// How a path is shown in messages: relative to the source tree when inside
// it ("shaders/tests/broken.frag"), else as given.
std::string display_path(const std::string& path);

}  // namespace fw
