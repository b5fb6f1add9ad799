#include "framework/gl/vertex_array.hpp"

#include "framework/error.hpp"
#include "framework/gl/binding.hpp"
#include "framework/gl/debug.hpp"
#include "framework/text.hpp"

namespace fw {

namespace {

std::size_t index_size_of(GLenum type) {
    switch (type) {
        case GL_UNSIGNED_BYTE:
            return 1;
        case GL_UNSIGNED_SHORT:
            return 2;
        case GL_UNSIGNED_INT:
            return 4;
        default:
            return 0;
    }
}

// The vertex array bound in this thread's current context, as far as the
// wrapper knows it: set by the wrapper's own binds, and forgotten by any
// other glBindVertexArray or glDeleteVertexArrays (a lab's raw call, a scoped
// binding's restore), which track_vertex_array_binding() routes through
// forget_binding(). kUnknown until GL is loaded, and after a context is made.
constexpr GLuint kUnknown = ~GLuint{0};
thread_local GLuint known_binding = kUnknown;
PFNGLBINDVERTEXARRAYPROC driver_bind = nullptr;
PFNGLDELETEVERTEXARRAYSPROC driver_delete = nullptr;

void GLAD_API_PTR bind_and_forget(GLuint id) {
    known_binding = kUnknown;
    driver_bind(id);
}

void GLAD_API_PTR delete_and_forget(GLsizei n, const GLuint* ids) {
    known_binding = kUnknown;
    driver_delete(n, ids);
}

}  // namespace

namespace detail {

void track_vertex_array_binding() {
    known_binding = kUnknown;
    // gladLoadGL has just set both pointers to the driver's functions.
    if (glad_glBindVertexArray == nullptr || glad_glDeleteVertexArrays == nullptr) return;
    if (glad_glBindVertexArray != &bind_and_forget) {
        driver_bind = glad_glBindVertexArray;
        glad_glBindVertexArray = &bind_and_forget;
    }
    if (glad_glDeleteVertexArrays != &delete_and_forget) {
        driver_delete = glad_glDeleteVertexArrays;
        glad_glDeleteVertexArrays = &delete_and_forget;
    }
}

bool vertex_array_binding_known() { return known_binding != kUnknown; }

}  // namespace detail

VertexLayout& VertexLayout::add(const VertexAttribute& a) {
    for (const VertexAttribute& b : attributes_)
        if (b.location == a.location)
            throw UsageError("VertexLayout: location " + std::to_string(a.location) +
                             " is given two attributes; each shader input needs its own");
    if (a.components < 1 || a.components > 4)
        throw UsageError("VertexAttribute.components must be 1 to 4 (location " +
                         std::to_string(a.location) + " has " + std::to_string(a.components) + ")");
    attributes_.push_back(a);
    return *this;
}

namespace {

// Throws UsageError naming the field of `desc` that is wrong.
void check_desc(const VertexArrayDesc& desc, const std::string& where) {
    if (!desc.vertices || desc.vertices->id() == 0)
        throw UsageError("VertexArrayDesc.vertices must point to a created Buffer" + where);
    const VertexLayout& layout = desc.layout;
    if (layout.attributes().empty())
        throw UsageError("VertexArrayDesc.layout has no attributes; add them with .attr()" + where);
    if (layout.stride() == 0)
        throw UsageError("VertexArrayDesc.layout has stride 0; use VertexLayout::of<Vertex>()" +
                         where);
    if (index_size_of(desc.index_type) == 0)
        throw UsageError(
            "VertexArrayDesc.index_type must be GL_UNSIGNED_BYTE, "
            "GL_UNSIGNED_SHORT or GL_UNSIGNED_INT, not " +
            gl_enum_name(desc.index_type) + where);
    if (desc.indices && desc.indices->id() == 0)
        throw UsageError("VertexArrayDesc.indices points to an empty Buffer" + where);
    GLint max_attribs = 0;
    glGetIntegerv(GL_MAX_VERTEX_ATTRIBS, &max_attribs);
    for (const VertexAttribute& a : layout.attributes())
        if (a.location >= static_cast<GLuint>(max_attribs))
            throw UsageError("VertexAttribute.location " + std::to_string(a.location) +
                             " is not below GL_MAX_VERTEX_ATTRIBS (" + std::to_string(max_attribs) +
                             ")" + where);
}

// Describes every attribute of desc.layout to vertex array `id` and attaches
// the buffers.
void attach(GLuint id, const VertexArrayDesc& desc) {
    const ScopedBinding bound = bind_vertex_array_scoped(id);
    // Binding point 0 holds the vertex buffer; every attribute reads from it.
    constexpr GLuint kBinding = 0;
    for (const VertexAttribute& a : desc.layout.attributes()) {
        glEnableVertexAttribArray(a.location);
        auto offset = static_cast<GLuint>(a.offset);
        if (a.integer)
            glVertexAttribIFormat(a.location, a.components, a.type, offset);
        else
            glVertexAttribFormat(a.location, a.components, a.type,
                                 a.normalized ? GL_TRUE : GL_FALSE, offset);
        glVertexAttribBinding(a.location, kBinding);
    }
    glBindVertexBuffer(kBinding, desc.vertices->id(), 0,
                       static_cast<GLsizei>(desc.layout.stride()));
    // The element array binding is part of the vertex array's state: binding
    // it here, while the vertex array is bound, is what attaches the indices.
    if (desc.indices) glBindBuffer(GL_ELEMENT_ARRAY_BUFFER, desc.indices->id());
}

}  // namespace

VertexArray::VertexArray(const VertexArrayDesc& desc) : label_(desc.label) {
    check_desc(desc, " (vertex array " + quoted_label(label_) + ")");
    GLuint id = 0;
    glGenVertexArrays(1, &id);
    handle_ = detail::Handle(id, [](GLuint name) { glDeleteVertexArrays(1, &name); });
    attach(id, desc);

    index_size_ = index_size_of(desc.index_type);
    vertex_count_ = desc.vertices->size() / desc.layout.stride();
    has_indices_ = desc.indices != nullptr;
    index_count_ = has_indices_ ? desc.indices->size() / index_size_ : 0;
    index_type_ = desc.index_type;
    set_object_label(GL_VERTEX_ARRAY, id, label_);
}

VertexArray VertexArray::blank(std::string label) {
    VertexArray vao;
    vao.label_ = std::move(label);
    GLuint id = 0;
    glGenVertexArrays(1, &id);
    vao.handle_ = detail::Handle(id, [](GLuint name) { glDeleteVertexArrays(1, &name); });
    // A name from glGenVertexArrays becomes a vertex array object when it is
    // first bound; only then may it be labelled.
    const ScopedBinding bound = bind_vertex_array_scoped(id);
    set_object_label(GL_VERTEX_ARRAY, id, vao.label_);
    return vao;
}

void VertexArray::bind() const {
    if (glad_glBindVertexArray != &bind_and_forget) {  // not tracked: GL loaded elsewhere
        glBindVertexArray(id());
        return;
    }
    driver_bind(id());
    known_binding = id();
}

void VertexArray::bind_for_draw() const {
    // Raw GL binds a vertex array once for many draws; the wrapper does the
    // same unless something else may have bound another since its last bind.
    if (known_binding != id()) bind();
}

void VertexArray::draw(GLenum mode, GLsizei count, GLint first) const {
    if (id() == 0) throw UsageError("VertexArray::draw on an empty VertexArray");
    if (first < 0 || count < 0 ||
        static_cast<std::size_t>(first) + static_cast<std::size_t>(count) > vertex_count_)
        throw UsageError("VertexArray " + quoted_label(label_) + ": draw of vertices [" +
                         std::to_string(first) + ", " + std::to_string(first + count) +
                         ") but its vertex buffer holds " + std::to_string(vertex_count_));
    bind_for_draw();
    glDrawArrays(mode, first, count);
}

void VertexArray::draw_indexed(GLenum mode, GLsizei count, std::size_t first_index) const {
    if (id() == 0) throw UsageError("VertexArray::draw_indexed on an empty VertexArray");
    if (!has_indices_)
        throw UsageError("VertexArray " + quoted_label(label_) +
                         " has no index buffer: set VertexArrayDesc.indices, or use draw()");
    if (count < 0 || first_index + static_cast<std::size_t>(count) > index_count_)
        throw UsageError("VertexArray " + quoted_label(label_) + ": draw_indexed of indices [" +
                         std::to_string(first_index) + ", " +
                         std::to_string(first_index + static_cast<std::size_t>(count)) +
                         ") but its index buffer holds " + std::to_string(index_count_));
    bind_for_draw();
    // With an element array buffer bound, the "indices" pointer argument is
    // a byte offset into that buffer.
    const void* offset = reinterpret_cast<const void*>(first_index * index_size_);
    glDrawElements(mode, count, index_type_, offset);
}

}  // namespace fw
