// Lab 9 `buffers`: the course's references for the particles' motion, the
// subdivided sphere and the std140 rules, written from the lab sheet's
// closed forms and the GL specification (section 7.6.2.2), never from the
// lab's code, and the wrong answers the report names.
#include <cmath>
#include <glm/glm.hpp>

#include "block.hpp"
#include "framework/error.hpp"
#include "grading/units/buffer_reference.hpp"
#include "grading/units/reference.hpp"

namespace {

using buffers::GlslType;
using buffers::Std140Place;
using grading::BufferExpectation;

// The sheet's numbers (labs/09_buffers/README.md, The scenes).
constexpr double kDt = 0.02, kGravity = -4.0, kSourceY = -1.5, kSpeed = 3.0;

int param(const nlohmann::json& params, const char* name, int lo, int hi) {
    const nlohmann::json& v = params.at(name);
    if (!v.is_number_integer() || v.get<int>() < lo || v.get<int>() > hi)
        throw fw::Error(std::string("params.") + name + " must be an integer from " +
                        std::to_string(lo) + " to " + std::to_string(hi));
    return v.get<int>();
}

// How one wrong step rule moves a particle: its position after the step from
// (p, v), and its velocity.
enum class Rule { Exact, NoHalf, Twice, VelocityFirst, VelocityKept };

// Particle i of `count` after `steps` steps of `rule`, in double: the
// exact rule is the closed form at t = steps dt.
glm::dvec2 particle(int i, int count, int steps, Rule rule) {
    const double phi = (30.0 + 120.0 * (i + 0.5) / count) * std::acos(-1.0) / 180.0;
    glm::dvec2 p(0.0, kSourceY), v(kSpeed * std::cos(phi), kSpeed * std::sin(phi));
    const glm::dvec2 g(0.0, kGravity);
    if (rule == Rule::Exact) {
        const double t = steps * kDt;
        return p + v * t + 0.5 * g * t * t;
    }
    for (int n = 0; n < steps; ++n) {
        if (rule == Rule::VelocityFirst) v += g * kDt;
        const double half = rule == Rule::NoHalf ? 0.0 : rule == Rule::Twice ? 1.0 : 0.5;
        p += v * kDt + half * g * kDt * kDt;
        if (rule != Rule::VelocityFirst && rule != Rule::VelocityKept) v += g * kDt;
    }
    return p;
}

// Every particle after `steps` of `rule`, those from `first_still` on never moved.
BufferExpectation particles(const nlohmann::json& params, Rule rule, int steps_override = -1,
                            int first_still = -1) {
    const int count = param(params, "count", 1, 1000);
    const int steps = steps_override >= 0 ? steps_override : param(params, "steps", 0, 100);
    BufferExpectation e{3, {}};
    for (int i = 0; i < count; ++i) {
        const bool still = first_still >= 0 && i >= first_still;
        const glm::dvec2 p = particle(i, count, still ? 0 : steps, rule);
        e.values.insert(e.values.end(), {float(p.x), float(p.y), 0.0f});
    }
    return e;
}

BufferExpectation ref_motion(const nlohmann::json& params) {
    return particles(params, Rule::Exact);
}
BufferExpectation no_half(const nlohmann::json& params) { return particles(params, Rule::NoHalf); }
BufferExpectation twice(const nlohmann::json& params) { return particles(params, Rule::Twice); }
BufferExpectation velocity_first(const nlohmann::json& params) {
    return particles(params, Rule::VelocityFirst);
}
BufferExpectation velocity_kept(const nlohmann::json& params) {
    return particles(params, Rule::VelocityKept);
}
BufferExpectation never_moved(const nlohmann::json& params) {
    return particles(params, Rule::Exact, 0);
}
BufferExpectation one_step(const nlohmann::json& params) {
    return particles(params, Rule::Exact, param(params, "steps", 0, 100) > 0 ? 1 : 0);
}
// Work groups of 64 counted as count / 64 rounded down: the last, partial
// group never runs.
BufferExpectation groups_rounded_down(const nlohmann::json& params) {
    return particles(params, Rule::Exact, -1, param(params, "count", 1, 1000) / 64 * 64);
}

// The octahedron of the sheet, subdivided `passes` times in the sheet's
// order; `push` false leaves the midpoints inside the sphere.
BufferExpectation subdivided(const nlohmann::json& params, bool push) {
    const int passes = param(params, "passes", 0, 4);
    const glm::dvec3 ring[4] = {{1, 0, 0}, {0, 0, -1}, {-1, 0, 0}, {0, 0, 1}};
    std::vector<glm::dvec3> v;
    for (int i = 0; i < 4; ++i) v.insert(v.end(), {ring[i], ring[(i + 1) % 4], {0, 1, 0}});
    for (int i = 0; i < 4; ++i) v.insert(v.end(), {ring[(i + 1) % 4], ring[i], {0, -1, 0}});
    for (int k = 0; k < passes; ++k) {
        std::vector<glm::dvec3> next;
        for (std::size_t t = 0; t + 2 < v.size(); t += 3) {
            const glm::dvec3 a = v[t], b = v[t + 1], c = v[t + 2];
            const auto mid = [push](glm::dvec3 p, glm::dvec3 q) {
                return push ? glm::normalize(p + q) : 0.5 * (p + q);
            };
            const glm::dvec3 ab = mid(a, b), bc = mid(b, c), ca = mid(c, a);
            next.insert(next.end(), {a, ab, ca, ab, b, bc, ca, bc, c, ab, bc, ca});
        }
        v = std::move(next);
    }
    BufferExpectation e{3, {}};
    for (const glm::dvec3& p : v)
        e.values.insert(e.values.end(), {float(p.x), float(p.y), float(p.z)});
    return e;
}
BufferExpectation ref_sphere(const nlohmann::json& params) { return subdivided(params, true); }
BufferExpectation flat_midpoints(const nlohmann::json& params) { return subdivided(params, false); }

// Section 7.6.2.2, rules 1-5: a scalar's alignment and size is 4 bytes, a
// vecN's 2N or 4N (vec3 aligned as vec4, 12 bytes long), a column-major
// matrix is an array of its columns, each aligned and padded as a vec4.
Std140Place ref_std140_place(int offset, GlslType type) {
    struct TypeRule {
        GlslType type;
        int alignment, size;
    };
    constexpr TypeRule kRules[] = {{GlslType::Float, 4, 4},  {GlslType::Vec2, 8, 8},
                                   {GlslType::Vec3, 16, 12}, {GlslType::Vec4, 16, 16},
                                   {GlslType::Mat3, 16, 48}, {GlslType::Mat4, 16, 64}};
    for (const TypeRule& r : kRules)
        if (r.type == type) {
            const int pad = offset % r.alignment == 0 ? 0 : r.alignment - offset % r.alignment;
            return {offset + pad, offset + pad + r.size};
        }
    throw fw::Error("std140_place: a type with no std140 rule");
}

}  // namespace

COURSE_REFERENCE(std140_place, &ref_std140_place,
                 {grading::integer(0, 256), grading::choice<GlslType>()})
COURSE_BUFFER_REFERENCE(motion, &ref_motion, "particle", "is at", {"count", "steps"})
COURSE_BUFFER_MISTAKE(motion, "no-half-step", "each step moved by v dt only, without g dt^2 / 2",
                      &no_half)
COURSE_BUFFER_MISTAKE(motion, "gravity-twice", "gravity applied twice, g dt^2 for g dt^2 / 2",
                      &twice)
COURSE_BUFFER_MISTAKE(motion, "velocity-first", "the velocity changed before the position moved",
                      &velocity_first)
COURSE_BUFFER_MISTAKE(motion, "velocity-kept", "the velocity never changed by gravity",
                      &velocity_kept)
COURSE_BUFFER_MISTAKE(motion, "never-moved",
                      "the particles never moved: no step reached the buffer", &never_moved)
COURSE_BUFFER_MISTAKE(motion, "not-swapped", "one step only: the two buffers never swapped roles",
                      &one_step)
COURSE_BUFFER_MISTAKE(motion, "groups-rounded-down",
                      "the last, partial work group never ran (count / 64 rounded down)",
                      &groups_rounded_down)
COURSE_BUFFER_REFERENCE(sphere, &ref_sphere, "vertex", "is at", {"passes"})
COURSE_BUFFER_MISTAKE(sphere, "midpoints-not-pushed",
                      "the midpoints left on the edges, not pushed out to the sphere",
                      &flat_midpoints)
