// The parts of fw::gl_usage's Checker (usage.hpp) that its files share:
// what a program's sources and GL say about it, and the completeness of the
// texture a sampler reads. Every query here runs under
// gl_calls::Unobserved and leaves GL's state and errors as they were.
#pragma once

#include <glad/gl.h>

#include <cstdarg>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "framework/gl/binding.hpp"

namespace fw::gl_usage::detail {

// A sampler or image uniform, one per array element.
struct Opaque {
    std::string name;  // "u_texture", "u_maps[1]"
    GLint location = -1;
    GLenum type = 0;  // GL_SAMPLER_2D, GL_IMAGE_2D, ...
};

// A shader storage block: its index, name and whether the source declares it readonly.
struct StorageBlock {
    GLuint index = 0;
    std::string name;
    bool readonly = false;
};

// What the checks need of a program, read once.
struct ProgramInfo {
    // From the sources at link time (glGetAttachedShaders: the framework
    // detaches them after the link): the clip distances the last
    // vertex-processing stage writes, and that stage's name.
    bool sources_seen = false;
    std::vector<int> clip;
    std::string clip_stage;
    std::set<std::string> readonly_blocks;
    // From GL's interface queries, on the first draw or dispatch.
    bool resources = false;
    std::vector<Opaque> samplers, images;
    std::vector<GLint> inputs;  // attribute locations the program reads
    GLint uniform_blocks = 0;
    std::vector<StorageBlock> storage;
    GLint feedback_buffers = 0;  // buffers transform feedback captures into
};

// Reads the program's attached shaders (after a link): fills the
// sources_seen part of `info`.
void read_sources(GLuint program, ProgramInfo& info);
// Fills the resources part of `info`.
void read_resources(GLuint program, ProgramInfo& info);

// The names of the storage blocks a source declares readonly.
std::set<std::string> readonly_blocks(const std::string& source);

bool is_sampler(GLenum type);
bool is_image(GLenum type);

// The texture target a sampler type reads (GL_TEXTURE_2D for sampler2D,
// isampler2D, sampler2DShadow...), 0 for one this does not know.
GLenum sampler_target(GLenum type);
// "GL_TEXTURE_2D", ...
std::string target_name(GLenum target);

// The texture bound on `unit` for `target`, and why it is incomplete under
// GL 4.3 section 8.17 ("" when complete); the filters of a sampler object
// bound on the unit replace the texture's.
struct UnitTexture {
    GLuint texture = 0;
    std::string incomplete;
};
UnitTexture texture_on_unit(GLuint unit, GLenum target);

// A buffer or a texture (images): the names are two name spaces.
enum class Object { Buffer, Texture };
using Key = std::pair<Object, GLuint>;
std::string object_name(const Key& k);

// What a call reads: the object, the barrier bit that makes a shader's
// earlier writes visible to that read, and how ("vertex attributes (location 0)").
struct Source {
    Key object;
    GLbitfield bit = 0;
    std::string where;
};
// "GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT" for the bit.
std::string barrier_bit_name(GLbitfield bit);
// The binding point of a storage block of `program`.
GLuint storage_binding(GLuint program, const StorageBlock& s);

// What a draw (`draw`) or a dispatch named `call` of `program` reads: its
// inputs' vertex buffers, the index and indirect buffers, its uniform and
// storage blocks, its images. The samplers' textures are the caller's.
std::vector<Source> call_sources(GLuint program, const ProgramInfo& p, bool draw, const char* call);
// What a read-back (glGetBufferSubData, glMapBuffer, glMapBufferRange,
// glCopyBufferSubData, glReadPixels, glGetTexImage) reads, from its arguments.
std::vector<Source> read_back_sources(const char* call, va_list args);

// "the buffer 'compute particles'" (its label) or "buffer 5".
std::string buffer_name(GLuint buffer);
std::string texture_name(GLuint texture);
std::string program_name(GLuint program);

}  // namespace fw::gl_usage::detail
