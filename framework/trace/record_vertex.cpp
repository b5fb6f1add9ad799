// The record's vertex part: the vertex array's attributes that the program
// reads and the element buffer of an indexed draw; the buffer a read-back
// reads (record_state.hpp).
#include "framework/gl/binding.hpp"
#include "framework/trace/record_state.hpp"

namespace fw::gl_record::detail {

namespace {

// Attribute `attr` at `location` as vertex array `vao` feeds it: a disabled
// array's current value, else its format and its buffer binding.
json attribute(const Names& names, GLuint vao, const std::string& attr, GLint location) {
    const GLuint i = static_cast<GLuint>(location);
    auto get = [&](GLenum pname) {
        GLint v = 0;
        glGetVertexAttribiv(i, pname, &v);
        return v;
    };
    json a = {{"name", attr}};
    if (vao == 0 || !get(GL_VERTEX_ATTRIB_ARRAY_ENABLED)) {
        // A disabled array: every vertex reads the current value.
        GLfloat v[4] = {};
        glGetVertexAttribfv(i, GL_CURRENT_VERTEX_ATTRIB, v);
        a["enabled"] = false;
        a["current"] = {number(v[0]), number(v[1]), number(v[2]), number(v[3])};
        return a;
    }
    // Through the attribute's vertex buffer binding, which
    // glVertexAttribPointer and glVertexAttribFormat both set: one
    // record for either formulation, the stride as GL takes it.
    const GLuint b = static_cast<GLuint>(get(GL_VERTEX_ATTRIB_BINDING));
    a["enabled"] = true;
    a["size"] = get(GL_VERTEX_ATTRIB_ARRAY_SIZE);
    a["type"] = name(static_cast<GLenum>(get(GL_VERTEX_ATTRIB_ARRAY_TYPE)));
    a["normalized"] = get(GL_VERTEX_ATTRIB_ARRAY_NORMALIZED) != 0;
    a["integer"] = get(GL_VERTEX_ATTRIB_ARRAY_INTEGER) != 0;
    a["stride"] = get_integer(GL_VERTEX_BINDING_STRIDE, b);
    a["offset"] = get_integer(GL_VERTEX_BINDING_OFFSET, b) + get(GL_VERTEX_ATTRIB_RELATIVE_OFFSET);
    a["divisor"] = get_integer(GL_VERTEX_BINDING_DIVISOR, b);
    a["buffer"] =
        names.of(GL_BUFFER, static_cast<GLuint>(get_integer(GL_VERTEX_BINDING_BUFFER, b)));
    return a;
}

}  // namespace

void StateReader::vertex_state(json& event, const ProgramInterface& p, bool elements) {
    const GLuint vao = static_cast<GLuint>(get_integer(GL_VERTEX_ARRAY_BINDING));
    json va = {{"label", names_.of(GL_VERTEX_ARRAY, vao)}};
    json attributes = json::object();
    for (const auto& [attr, location] : p.attributes)
        attributes[std::to_string(location)] = attribute(names_, vao, attr, location);
    va["attributes"] = attributes;
    if (elements)
        va["elements"] =
            names_.of(GL_BUFFER, static_cast<GLuint>(get_integer(GL_ELEMENT_ARRAY_BUFFER_BINDING)));
    event["vertex_array"] = va;
}

void StateReader::buffer_read(json& event, GLenum target) {
    const GLenum binding = buffer_binding_query(target);
    if (binding) event["buffer"] = names_.of(GL_BUFFER, static_cast<GLuint>(get_integer(binding)));
}

}  // namespace fw::gl_record::detail
