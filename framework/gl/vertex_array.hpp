// fw::VertexArray: which buffer feeds which vertex attribute, in what format.
//
//   struct Vertex { glm::vec3 position; glm::vec3 color; };
//   // A_POSITION, A_COLOR: the locations in shaders/NN_name/shared.glsl
//   fw::VertexArray vao(fw::VertexArrayDesc{
//       .vertices = &vbo,
//       .layout = fw::VertexLayout::of<Vertex>()
//                     .attr(A_POSITION, &Vertex::position)
//                     .attr(A_COLOR, &Vertex::color),
//       .label = "quad",
//   });
//   glBindVertexArray(vao.id());  // a lab shows its binds and draws
//   glDrawArrays(GL_TRIANGLES, 0, 6);
//
// The format of each attribute (components, type, offset, stride) is deduced
// from the member it names, so it cannot disagree with the struct. Underneath
// are GL 4.3's separate attribute formats: glVertexAttribFormat says what one
// vertex looks like, glBindVertexBuffer says where the vertices are.
#pragma once

#include <glad/gl.h>

#include <cstddef>
#include <cstdint>
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "framework/gl/buffer.hpp"
#include "framework/gl/handle.hpp"

namespace fw {

// One attribute: `components` values of `type` at `offset` bytes into a vertex.
struct VertexAttribute {
    GLuint location = 0;
    GLint components = 4;
    GLenum type = GL_FLOAT;
    std::size_t offset = 0;
    // The shader reads ints (`in ivec2 x;`): glVertexAttribIFormat, no conversion.
    bool integer = false;
    // Fixed-point data read as float in [0, 1] (unsigned) or [-1, 1] (signed).
    bool normalized = false;
};

namespace detail {
// `M Vertex::*`, spelled as an alias so that clang-format 14 and 19 agree on it
// (docs/conventions.md, Formatting).
template <class Vertex, class M>
using MemberPointer = M Vertex::*;

// Format of one C++ member type: float, int, unsigned and their glm vectors,
// plus glm::u8vec as normalised colours.
template <GLint N, GLenum Type, bool Integer, bool Normalized>
struct Format {
    static constexpr GLint n = N;
    static constexpr GLenum type = Type;
    static constexpr bool integer = Integer;
    static constexpr bool normalized = Normalized;
};

template <class M>
struct AttribFormat {
    static_assert(sizeof(M) == 0,
                  "VertexLayout::attr: unsupported member type; use float, int, unsigned, "
                  "glm::vec2-4, glm::ivec2-4, glm::uvec2-4 or glm::u8vec2-4");
};
template <>
struct AttribFormat<float> : Format<1, GL_FLOAT, false, false> {};
template <>
struct AttribFormat<int> : Format<1, GL_INT, true, false> {};
template <>
struct AttribFormat<unsigned> : Format<1, GL_UNSIGNED_INT, true, false> {};
template <glm::length_t N, glm::qualifier Q>
struct AttribFormat<glm::vec<N, float, Q>> : Format<N, GL_FLOAT, false, false> {};
template <glm::length_t N, glm::qualifier Q>
struct AttribFormat<glm::vec<N, int, Q>> : Format<N, GL_INT, true, false> {};
template <glm::length_t N, glm::qualifier Q>
struct AttribFormat<glm::vec<N, unsigned, Q>> : Format<N, GL_UNSIGNED_INT, true, false> {};
// Bytes read as floats in [0, 1]: compact colours.
template <glm::length_t N, glm::qualifier Q>
struct AttribFormat<glm::vec<N, std::uint8_t, Q>> : Format<N, GL_UNSIGNED_BYTE, false, true> {};

// Routes glBindVertexArray and glDeleteVertexArrays through the wrapper, so
// that a draw binds its vertex array only when another may be bound: after
// the lab's own glBindVertexArray, a deletion, or a new context. Called by
// load_gl_and_check() right after gladLoadGL, for each context made.
void track_vertex_array_binding();
// Whether the wrapper knows which vertex array is bound in this thread (what
// the tests of the routing above read).
bool vertex_array_binding_known();
}  // namespace detail

class VertexLayout {
public:
    VertexLayout() = default;
    // Raw layout for data that is not a struct: `stride` bytes per vertex,
    // attributes added with add().
    explicit VertexLayout(std::size_t stride) : stride_(stride) {}

    // A layout whose vertices are `Vertex` structs (stride sizeof(Vertex)).
    template <class Vertex>
    static VertexLayout of() {
        return VertexLayout(sizeof(Vertex));
    }

    // Feeds shader input `location` from `member` of every vertex. `Vertex`
    // must be default-constructible (a plain struct is).
    template <class Vertex, class M>
    VertexLayout& attr(GLuint location, detail::MemberPointer<Vertex, M> member) {
        using F = detail::AttribFormat<M>;
        const Vertex probe{};
        const auto* base = reinterpret_cast<const unsigned char*>(&probe);
        const auto* field = reinterpret_cast<const unsigned char*>(&(probe.*member));
        return add({location, F::n, F::type, static_cast<std::size_t>(field - base), F::integer,
                    F::normalized});
    }

    VertexLayout& add(const VertexAttribute& a);

    std::size_t stride() const { return stride_; }
    const std::vector<VertexAttribute>& attributes() const { return attributes_; }

private:
    std::size_t stride_ = 0;
    std::vector<VertexAttribute> attributes_;
};

struct VertexArrayDesc {
    const Buffer* vertices = nullptr;     // required; read through `layout`
    VertexLayout layout;                  // at least one attribute
    const Buffer* indices = nullptr;      // optional; needed by draw_indexed()
    GLenum index_type = GL_UNSIGNED_INT;  // or GL_UNSIGNED_SHORT, GL_UNSIGNED_BYTE
    std::string label;
};

class VertexArray {
public:
    VertexArray() = default;
    explicit VertexArray(const VertexArrayDesc& desc);
    // A labelled vertex array with nothing attached, for a lab that shows the
    // calls: it binds the vertex array and describes the attributes itself
    // (glBindBuffer, glVertexAttribPointer, glEnableVertexAttribArray), as
    // labs/00_pipeline does. vertex_count() and index_count() are then 0.
    static VertexArray blank(std::string label);

    GLuint id() const { return handle_.get(); }
    const std::string& label() const { return label_; }
    // Vertices in the vertex buffer and indices in the index buffer (0 if
    // none), as they were when the vertex array was created.
    std::size_t vertex_count() const { return vertex_count_; }
    std::size_t index_count() const { return index_count_; }
    bool indexed() const { return has_indices_; }

    // glBindVertexArray(id()).
    void bind() const;

    // Binds (unless the wrapper itself bound this vertex array last and
    // nothing has bound another since), then glDrawArrays(mode, first, count). Throws UsageError if
    // [first, first + count) is not inside the vertex buffer.
    void draw(GLenum mode, GLsizei count, GLint first = 0) const;

    // Binds as draw() does, then glDrawElements(mode, count, index_type, offset of
    // first_index). Throws UsageError without an index buffer or if the
    // indices are out of range.
    void draw_indexed(GLenum mode, GLsizei count, std::size_t first_index = 0) const;

private:
    void bind_for_draw() const;

    detail::Handle handle_;
    std::string label_;
    std::size_t vertex_count_ = 0;
    std::size_t index_count_ = 0;
    std::size_t index_size_ = 4;
    GLenum index_type_ = GL_UNSIGNED_INT;
    bool has_indices_ = false;
};

}  // namespace fw
