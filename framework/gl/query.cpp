#include "framework/gl/query.hpp"

#include <algorithm>

#include "framework/error.hpp"
#include "framework/gl/debug.hpp"
#include "framework/text.hpp"

namespace fw {

namespace {

// The targets a Query takes; their names come from gl_enum_name.
constexpr GLenum kTargets[] = {
    GL_PRIMITIVES_GENERATED,
    GL_SAMPLES_PASSED,
    GL_ANY_SAMPLES_PASSED,
    GL_ANY_SAMPLES_PASSED_CONSERVATIVE,
    GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN,
    GL_TIME_ELAPSED,
};

}  // namespace

Query::Query(GLenum target, std::string label) : target_(target), label_(std::move(label)) {
    if (std::find(std::begin(kTargets), std::end(kTargets), target) == std::end(kTargets))
        throw UsageError("Query target " + gl_enum_name(target) + " is not supported; use one of " +
                         join(kTargets, ", ", [](GLenum t) { return gl_enum_name(t); }) +
                         (label_.empty() ? "" : " (query '" + label_ + "')"));
    GLuint id = 0;
    glGenQueries(1, &id);
    handle_ = detail::Handle(id, [](GLuint n) { glDeleteQueries(1, &n); });
}

void Query::begin() {
    if (id() == 0) throw UsageError("Query::begin on an empty Query");
    if (active_) throw UsageError("Query '" + label_ + "': begin() twice without end()");
    glBeginQuery(target_, id());
    active_ = true;
    // A name from glGenQueries becomes a query object only at its first
    // glBeginQuery; before that, glObjectLabel would fail on it.
    if (!labelled_) {
        set_object_label(GL_QUERY, id(), label_);
        labelled_ = true;
    }
}

void Query::end() {
    if (!active_) throw UsageError("Query '" + label_ + "': end() without begin()");
    glEndQuery(target_);
    active_ = false;
    ended_ = true;
}

bool Query::available() const {
    if (!ended_) return false;
    GLuint ready = GL_FALSE;
    glGetQueryObjectuiv(id(), GL_QUERY_RESULT_AVAILABLE, &ready);
    return ready == GL_TRUE;
}

std::uint64_t Query::result() const {
    if (active_) throw UsageError("Query '" + label_ + "': result() before end()");
    if (!ended_) throw UsageError("Query '" + label_ + "': result() before begin() and end()");
    GLuint64 value = 0;
    glGetQueryObjectui64v(id(), GL_QUERY_RESULT, &value);
    return value;
}

}  // namespace fw
