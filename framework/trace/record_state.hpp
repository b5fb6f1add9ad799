// The record's queries (record.hpp): the live state of a draw, a dispatch, a
// clear or a read-back, asked of GL with glGet* (the caller holds
// gl_calls::Unobserved), and the names that stand for GL's object numbers.
// By part: record_state.cpp the calls' own (draw, dispatch, clear, read-back)
// and the shared queries, record_program.cpp the program's interface and its
// uniforms, samplers, images and blocks, record_texture.cpp a texture unit,
// record_vertex.cpp the vertex array and the buffers read back,
// record_fixed_function.cpp the fixed-function state and the framebuffer.
#pragma once

#include <glad/gl.h>

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "framework/gl/binding.hpp"
#include "framework/trace/record.hpp"

namespace fw::gl_record::detail {

using nlohmann::json;

// An object's name in a record: its label, else its creation order among the
// objects of its kind ("buffer #2"), else "unlabelled" for one created before
// the Recorder started; 0 is "none" ("default" for a framebuffer).
class Names {
public:
    void created(GLenum identifier, GLuint id);
    std::string of(GLenum identifier, GLuint id) const;

private:
    std::map<std::pair<GLenum, GLuint>, int> order_;
    std::map<GLenum, int> count_;
};

// A float at the record's precision: six significant digits.
json number(double v);

// The queries every part shares (an integer state is fw::get_integer,
// binding.hpp): an enum's name, an enum state's name, the first n values of a float or an
// integer state.
std::string name(GLenum v, EnumKind kind = EnumKind::Other);
std::string name_of(GLenum pname, EnumKind kind = EnumKind::Other);
json floats(GLenum pname, int n);
json ints(GLenum pname, int n);

// What a program declares, read once per link: its active uniforms (outside
// blocks), attributes, uniform and storage blocks and captured outputs.
struct ProgramInterface {
    struct Uniform {
        std::string name;  // "u_w" for "u_w[0]"
        GLenum type = 0;
        std::vector<GLint> locations;  // one per array element
        bool array = false;
    };
    std::vector<Uniform> uniforms;                          // sorted by name
    std::vector<std::pair<std::string, GLint>> attributes;  // name, location; sorted by location
    std::vector<std::pair<std::string, GLuint>> uniform_blocks, storage_blocks;  // name, index
    int feedback_buffers = 0;
};

class StateReader {
public:
    explicit StateReader(const Names& names) : names_(names) {}

    // The state of a draw whose primitives are `mode`; `elements`: it reads
    // the element buffer.
    void draw(json& event, GLenum mode, bool elements);
    void dispatch(json& event);
    // glClear's or glClearBuffer's: `color`, `depth`, `stencil` say what it clears.
    void clear(json& event, bool color, bool depth, bool stencil);
    void read_pixels(json& event);
    // glGetBufferSubData, glMapBuffer*: the buffer bound to `target`.
    void buffer_read(json& event, GLenum target);

    // A program linked again or deleted: its interface is read again.
    void forget(GLuint program) { programs_.erase(program); }

private:
    const ProgramInterface& interface_of(GLuint program);
    void program_state(json& event, GLuint program, bool draw);
    void uniform_state(json& event, GLuint program, const ProgramInterface& p);
    void vertex_state(json& event, const ProgramInterface& p, bool elements);
    void fragment_state(json& event, GLenum mode);
    json framebuffer(GLenum binding, GLenum target);
    json texture_unit(GLint unit, GLenum sampler_type);

    const Names& names_;
    std::map<GLuint, ProgramInterface> programs_;
};

}  // namespace fw::gl_record::detail
