// Lab 11 `rasterizer`: the course's references for the student parts, in the
// forms the grader calls (labs/11_rasterizer/unit_calls.hpp), written from
// the sheet's rules (README.md, What you implement) in exact integer or
// double arithmetic where it can be, never from the lab's code.
#include <glm/glm.hpp>
#include <map>
#include <utility>
#include <vector>

#include "grading/units/reference.hpp"

namespace {

constexpr int kCanvas = 32;  // the canvas the line forms draw on

// floor(num / den) for den > 0.
long floor_div(long num, long den) {
    const long q = num / den;
    return (num % den != 0 && num < 0) ? q - 1 : q;
}

// The pixels written, row by row from the bottom: (x, y, writes).
std::vector<glm::vec3> rows(const std::map<std::pair<int, int>, int>& hits) {
    std::vector<glm::vec3> out;
    for (int y = 0; y < kCanvas; ++y)
        for (int x = 0; x < kCanvas; ++x) {
            const auto it = hits.find({x, y});
            if (it != hits.end()) out.emplace_back(x, y, it->second);
        }
    return out;
}

// Step i of n along the segment: a + i d / n rounded to the nearest integer;
// a tie goes up (DDA, floor(x + 0.5)) or towards b (Bresenham's error term
// steps the minor axis when it reaches the half).
int nearest(int a, int d, int i, int n, bool tie_towards_b) {
    const long twice = 2L * (long(a) * n + long(i) * d);  // 2 n times the exact value
    if (tie_towards_b && d < 0) return int(-floor_div(-(twice - n), 2L * n));  // tie down
    return int(floor_div(twice + n, 2L * n));                                  // tie up
}

std::vector<glm::vec3> ref_line(int ax, int ay, int bx, int by, bool bresenham) {
    const int dx = bx - ax, dy = by - ay;
    const int n = glm::max(glm::abs(dx), glm::abs(dy));
    std::map<std::pair<int, int>, int> hits;
    if (n == 0) ++hits[{ax, ay}];
    for (int i = 0; n > 0 && i <= n; ++i)
        ++hits[{nearest(ax, dx, i, n, bresenham), nearest(ay, dy, i, n, bresenham)}];
    return rows(hits);
}
std::vector<glm::vec3> ref_line_dda(int ax, int ay, int bx, int by) {
    return ref_line(ax, ay, bx, by, false);
}
std::vector<glm::vec3> ref_line_bresenham(int ax, int ay, int bx, int by) {
    return ref_line(ax, ay, bx, by, true);
}

// A left edge goes down (y up); a top edge is horizontal and goes to -x.
bool ref_top_left(glm::vec2 a, glm::vec2 b) { return b.y < a.y || (b.y == a.y && b.x < a.x); }

double cross(glm::dvec2 a, glm::dvec2 b, glm::dvec2 p) {
    return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

// Inside every edge of the counter-clockwise order; on an edge only when it
// is a top or a left one.
bool ref_covers(glm::vec2 a, glm::vec2 b, glm::vec2 c, glm::vec2 p) {
    const double area = cross(a, b, c);
    if (area == 0.0) return false;
    const glm::vec2 ccw[3] = {a, area > 0.0 ? b : c, area > 0.0 ? c : b};
    for (int i = 0; i < 3; ++i) {
        const glm::vec2 from = ccw[i], to = ccw[(i + 1) % 3];
        const double e = cross(from, to, p);
        if (e < 0.0 || (e == 0.0 && !ref_top_left(from, to))) return false;
    }
    return true;
}

// An edge and its reverse: one of the two is top-left (a point on an edge
// shared by two triangles belongs to one of them), neither when a == b.
glm::vec2 ref_top_left_both(glm::vec2 a, glm::vec2 b) {
    return {ref_top_left(a, b) ? 1.0f : 0.0f, ref_top_left(b, a) ? 1.0f : 0.0f};
}

// The centres of the 8 x 8 canvas the triangle covers, row by row.
std::vector<glm::vec2> ref_covers_centres(glm::vec2 a, glm::vec2 b, glm::vec2 c) {
    std::vector<glm::vec2> out;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x)
            if (ref_covers(a, b, c, {x + 0.5f, y + 0.5f})) out.emplace_back(x + 0.5f, y + 0.5f);
    return out;
}

// The scanline fill writes the covered centres once each.
std::vector<glm::vec3> ref_scanline_centres(glm::vec2 a, glm::vec2 b, glm::vec2 c) {
    std::vector<glm::vec3> out;
    for (const glm::vec2 centre : ref_covers_centres(a, b, c)) out.emplace_back(centre, 1.0f);
    return out;
}

// Areas of the triangles p makes with each opposite edge, over the whole.
glm::vec3 ref_barycentric(glm::vec2 a, glm::vec2 b, glm::vec2 c, glm::vec2 p) {
    const double area = cross(a, b, c);
    return glm::vec3(glm::dvec3(cross(b, c, p), cross(c, a, p), cross(a, b, p)) / area);
}

glm::vec4 ref_interpolate(glm::vec3 c0, glm::vec3 c1, glm::vec3 c2, glm::vec3 z, glm::vec3 w,
                          glm::vec3 weights, bool perspective) {
    const glm::vec3 lambda = weights / (weights[0] + weights[1] + weights[2]);
    const glm::dvec3 colors[3] = {c0, c1, c2};
    glm::dvec3 sum(0.0);
    double norm = 0.0;
    for (int i = 0; i < 3; ++i) {
        const double k = perspective ? double(lambda[i]) / w[i] : double(lambda[i]);
        sum += k * colors[i];
        norm += k;
    }
    const double depth = glm::dot(glm::dvec3(lambda), glm::dvec3(z));
    return glm::vec4(glm::vec3(sum / norm), float(depth));
}

// The mistake of interpolating the depth as the colour is: weighted by 1/w
// where `perspective` is on (grading::perspective_depth).
glm::vec4 ref_interpolate_depth_by_w(glm::vec3 c0, glm::vec3 c1, glm::vec3 c2, glm::vec3 z,
                                     glm::vec3 w, glm::vec3 weights, bool perspective) {
    glm::vec4 out = ref_interpolate(c0, c1, c2, z, w, weights, perspective);
    if (!perspective) return out;
    const glm::vec3 lambda = weights / (weights[0] + weights[1] + weights[2]);
    double sum = 0.0, norm = 0.0;
    for (int i = 0; i < 3; ++i) {
        sum += double(lambda[i]) / w[i] * z[i];
        norm += double(lambda[i]) / w[i];
    }
    out.w = float(sum / norm);
    return out;
}

// No area: the weights are not defined.
bool degenerate(glm::vec2 a, glm::vec2 b, glm::vec2 c, glm::vec2) { return cross(a, b, c) == 0.0; }

// Window positions in [0, size]^2 on a 1/16-pixel grid, as GL snaps them
// (GL_SUBPIXEL_BITS is at least 4). On it a float edge function is exact, and
// a row's crossing by the sheet's formula lands on the right side of every
// pixel centre, so the exact reference and a right float answer agree.
grading::ArgDomain on_subpixels(double size) {
    return grading::on_grid(grading::vec(2, 0, size), 1.0 / 16.0);
}

// GL_LESS: nearer passes and is stored.
glm::vec2 ref_depth_test(float stored, float z) {
    return z < stored ? glm::vec2(1.0f, z) : glm::vec2(0.0f, stored);
}

// Sutherland-Hodgman against z >= -w, edges 0 -> 1, 1 -> 2, 2 -> 0.
std::vector<glm::vec4> ref_clip_near(glm::vec4 p0, glm::vec4 p1, glm::vec4 p2) {
    const glm::dvec4 p[3] = {p0, p1, p2};
    std::vector<glm::vec4> out;
    for (int i = 0; i < 3; ++i) {
        const glm::dvec4 cur = p[i], next = p[(i + 1) % 3];
        const double d_cur = cur.z + cur.w, d_next = next.z + next.w;
        if (d_cur >= 0.0) out.emplace_back(cur);
        if ((d_cur >= 0.0) != (d_next >= 0.0))
            out.emplace_back(cur + (next - cur) * (d_cur / (d_cur - d_next)));
    }
    return out;
}

// The divide, then the viewport [0, width] x [0, height], depth [0, 1].
glm::vec4 ref_to_window(glm::vec4 clip, int width, int height) {
    const glm::dvec3 ndc = glm::dvec3(clip) / double(clip.w);
    return glm::vec4(float((ndc.x + 1.0) * width / 2.0), float((ndc.y + 1.0) * height / 2.0),
                     float((ndc.z + 1.0) / 2.0), clip.w);
}

}  // namespace

COURSE_REFERENCE(line_dda, &ref_line_dda,
                 {grading::integer(0, 31), grading::integer(0, 31), grading::integer(0, 31),
                  grading::integer(0, 31)})
COURSE_REFERENCE(line_bresenham, &ref_line_bresenham,
                 {grading::integer(0, 31), grading::integer(0, 31), grading::integer(0, 31),
                  grading::integer(0, 31)})
COURSE_REFERENCE(top_left, &ref_top_left_both, {grading::vec(2, -4, 4), grading::vec(2, -4, 4)},
                 grading::component_names({"a -> b top-left", "b -> a top-left"}))
COURSE_REFERENCE(covers, &ref_covers_centres, {on_subpixels(8), on_subpixels(8), on_subpixels(8)})
COURSE_REFERENCE(fill_triangle_scanline, &ref_scanline_centres,
                 {on_subpixels(8), on_subpixels(8), on_subpixels(8)})
COURSE_REFERENCE(barycentric, &ref_barycentric,
                 {on_subpixels(32), on_subpixels(32), on_subpixels(32), on_subpixels(32)}, 1e-3,
                 grading::redraw_when(&degenerate),
                 grading::component_names({"lambda_a", "lambda_b", "lambda_c"}))
COURSE_REFERENCE(interpolate, &ref_interpolate,
                 {grading::vec(3, 0, 1), grading::vec(3, 0, 1), grading::vec(3, 0, 1),
                  grading::vec(3, 0, 1), grading::vec(3, 0.1, 10), grading::vec(3, 0.05, 1),
                  grading::boolean()},
                 grading::component_names({"r", "g", "b", "depth"}),
                 grading::perspective_depth(&ref_interpolate_depth_by_w))
COURSE_REFERENCE(depth_test, &ref_depth_test, {grading::scalar(0, 1), grading::scalar(0, 1)},
                 grading::component_names({"passes", "depth stored"}))
COURSE_REFERENCE(clip_near, &ref_clip_near,
                 {grading::vec(4, -2, 2), grading::vec(4, -2, 2), grading::vec(4, -2, 2)}, 1e-4)
COURSE_REFERENCE(to_window, &ref_to_window,
                 {grading::vec(4, -2, 2), grading::integer(1, 64), grading::integer(1, 64)},
                 grading::component_names({"x_w", "y_w", "z_w", "w"}))
