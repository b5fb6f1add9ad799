// Lab 13 `surface-detail`: the course's references for the student's normal
// map, tangent frame, pixel rays and ray-triangle test, written from the
// sheet's formulas (README.md, What you implement) in double precision,
// never from the lab's code.
#include <cmath>
#include <glm/glm.hpp>

#include "grading/units/reference.hpp"

namespace {

// The sheet's height map: a dome of radius 6 texels in each 16 x 16 cell.
double height(int i, int j) {
    const double x = ((i % 64 + 64) % 64) % 16 - 7.5, y = ((j % 64 + 64) % 64) % 16 - 7.5;
    return std::fmax(0.0, 1.0 - (x * x + y * y) / 36.0);
}

glm::vec3 ref_normal_map(int i, int j, float scale) {
    const double du = (height(i + 1, j) - height(i - 1, j)) / 2.0;
    const double dv = (height(i, j + 1) - height(i, j - 1)) / 2.0;
    return glm::vec3(glm::normalize(glm::dvec3(-scale * du, -scale * dv, 1.0)));
}

glm::mat3 ref_tangent_frame(glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec2 uv0, glm::vec2 uv1,
                            glm::vec2 uv2, glm::vec3 n) {
    const glm::dvec3 e1 = glm::dvec3(p1) - glm::dvec3(p0), e2 = glm::dvec3(p2) - glm::dvec3(p0);
    const glm::dvec2 d1 = glm::dvec2(uv1) - glm::dvec2(uv0), d2 = glm::dvec2(uv2) - glm::dvec2(uv0);
    const double det = d1.x * d2.y - d2.x * d1.y;
    const glm::dvec3 t = (e1 * d2.y - e2 * d1.y) / det, b = (e2 * d1.x - e1 * d2.x) / det;
    const glm::dvec3 nn(n);
    const glm::dvec3 to = glm::normalize(t - glm::dot(nn, t) * nn);
    const glm::dvec3 bo = glm::normalize(b - glm::dot(nn, b) * nn - glm::dot(to, b) * to);
    return glm::mat3(glm::vec3(to), glm::vec3(bo), n);
}

// UVs so nearly on a line, or edges so nearly along n, that the frame is not
// defined to float precision.
bool degenerate_frame(glm::vec3 p0, glm::vec3 p1, glm::vec3 p2, glm::vec2 uv0, glm::vec2 uv1,
                      glm::vec2 uv2, glm::vec3 n) {
    const glm::dvec2 d1 = glm::dvec2(uv1 - uv0), d2 = glm::dvec2(uv2 - uv0);
    if (std::fabs(d1.x * d2.y - d2.x * d1.y) < 0.05) return true;
    const glm::dvec3 e1(p1 - p0), e2(p2 - p0);
    const glm::dvec3 t = (e1 * d2.y - e2 * d1.y), b = (e2 * d1.x - e1 * d2.x);
    const glm::dvec3 nn(n);
    const glm::dvec3 to = t - glm::dot(nn, t) * nn;
    if (glm::length(to) < 0.1 * glm::length(t) + 1e-9) return true;
    const glm::dvec3 bo =
        b - glm::dot(nn, b) * nn - glm::dot(glm::normalize(to), b) * glm::normalize(to);
    return glm::length(bo) < 0.1 * glm::length(b) + 1e-9;
}

// The sheet's camera: eye (0, 4.5, 4.5), u = (1, 0, 0), v = (0, 1, -1) / sqrt 2,
// w = (0, 1, 1) / sqrt 2, tan(22.5 degrees); a 64 x 64 image.
glm::vec3 ref_pixel_direction(int i, int j) {
    const double s = std::sqrt(0.5), k = std::tan(M_PI / 8.0);
    const double x = 2.0 * (i + 0.5) / 64.0 - 1.0, y = 2.0 * (j + 0.5) / 64.0 - 1.0;
    const glm::dvec3 d =
        x * k * glm::dvec3(1, 0, 0) + y * k * glm::dvec3(0, s, -s) - glm::dvec3(0, s, s);
    return glm::vec3(glm::normalize(d));
}

// Where o + t d meets the plane of a b c: t and the barycentric (u, v).
struct Crossing {
    double t, u, v;
    bool parallel;
};
Crossing crossing(glm::vec3 o, glm::vec3 d, glm::vec3 a, glm::vec3 b, glm::vec3 c) {
    const glm::dvec3 e1(b - a), e2(c - a), dd(d), s = glm::dvec3(o) - glm::dvec3(a);
    const glm::dvec3 p = glm::cross(dd, e2), q = glm::cross(s, e1);
    const double det = glm::dot(e1, p);
    if (std::fabs(det) < 1e-12) return {0, 0, 0, true};
    return {glm::dot(e2, q) / det, glm::dot(s, p) / det, glm::dot(dd, q) / det, false};
}

float ref_intersect(glm::vec3 o, glm::vec3 d, glm::vec3 a, glm::vec3 b, glm::vec3 c) {
    const Crossing x = crossing(o, d, a, b, c);
    if (x.parallel || x.u < 0 || x.v < 0 || x.u + x.v > 1 || x.t <= 0) return -1.0f;
    return static_cast<float>(x.t);
}

// Within float rounding of an edge, of the origin, or of parallel: either
// answer is right there.
bool borderline(glm::vec3 o, glm::vec3 d, glm::vec3 a, glm::vec3 b, glm::vec3 c) {
    const Crossing x = crossing(o, d, a, b, c);
    const double m = 1e-3;
    if (x.parallel) return true;
    const double det = glm::dot(glm::dvec3(b - a), glm::cross(glm::dvec3(d), glm::dvec3(c - a)));
    return std::fabs(det) < 1e-3 || std::fabs(x.u) < m || std::fabs(x.v) < m ||
           std::fabs(x.u + x.v - 1) < m || std::fabs(x.t) < m;
}

}  // namespace

COURSE_REFERENCE(normal_map, &ref_normal_map,
                 {grading::integer(0, 63), grading::integer(0, 63), grading::scalar(0, 8)})
COURSE_REFERENCE(tangent_frame, &ref_tangent_frame,
                 {grading::vec(3, -2, 2), grading::vec(3, -2, 2), grading::vec(3, -2, 2),
                  grading::vec(2, 0, 1), grading::vec(2, 0, 1), grading::vec(2, 0, 1),
                  grading::unit_vec(3)},
                 1e-3, grading::redraw_when(&degenerate_frame))
COURSE_REFERENCE(pixel_direction, &ref_pixel_direction,
                 {grading::integer(0, 63), grading::integer(0, 63)})
COURSE_REFERENCE(intersect_triangle, &ref_intersect,
                 {grading::vec(3, -2, 2), grading::vec(3, -1, 1), grading::vec(3, -2, 2),
                  grading::vec(3, -2, 2), grading::vec(3, -2, 2)},
                 1e-3, grading::redraw_when(&borderline))
