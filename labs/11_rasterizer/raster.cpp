// Lab 11's CPU rasterizer, the student parts (marked TODO): line_dda(),
// line_bresenham(), top_left(), covers(), barycentric(), interpolate(), depth_test(),
// clip_near() and to_window(). labs/11_rasterizer/README.md gives each rule.
#include "raster.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace rasterizer {

Canvas::Canvas(int w, int h)
    : width(w),
      height(h),
      color(static_cast<size_t>(w * h), glm::vec3(0.0f)),
      depth(static_cast<size_t>(w * h), 1.0f),
      writes(static_cast<size_t>(w * h), 0) {}

void plot(Canvas& canvas, int x, int y, glm::vec3 color) {
    if (!canvas.inside(x, y)) return;
    canvas.color[static_cast<size_t>(canvas.index(x, y))] = color;
    ++canvas.writes[static_cast<size_t>(canvas.index(x, y))];
}

// Part 1. DDA: n = max(|dx|, |dy|) steps; step i is at a + i * (dx, dy) / n,
// rounded to the nearest pixel, a tie (x.5) up; both ends plotted (a single
// pixel when a == b). i * dx / n as one division is exact at a tie.
void line_dda(Canvas& canvas, glm::ivec2 a, glm::ivec2 b, glm::vec3 color) {
    // BEGIN SOLUTION
    // STUDENT: (void)canvas, (void)a, (void)b, (void)color;  // TODO: n + 1 plots, a + i * d / n
    const glm::ivec2 d = b - a;
    const int n = std::max(std::abs(d.x), std::abs(d.y));
    if (n == 0) {
        plot(canvas, a.x, a.y, color);
        return;
    }
    for (int i = 0; i <= n; ++i) {
        const float x =
            static_cast<float>(a.x) + static_cast<float>(i * d.x) / static_cast<float>(n);
        const float y =
            static_cast<float>(a.y) + static_cast<float>(i * d.y) / static_cast<float>(n);
        plot(canvas, static_cast<int>(std::floor(x + 0.5f)), static_cast<int>(std::floor(y + 0.5f)),
             color);
    }
    // END SOLUTION
}

// Part 2. Bresenham in every octant and both directions, with integers
// only: step the major axis each time; an error term says when the minor
// axis steps too (README.md, What you implement). Same pixels as line_dda().
void line_bresenham(Canvas& canvas, glm::ivec2 a, glm::ivec2 b, glm::vec3 color) {
    // BEGIN SOLUTION
    // STUDENT: (void)canvas, (void)a, (void)b, (void)color;  // TODO: integer error term
    const int dx = std::abs(b.x - a.x), sx = a.x < b.x ? 1 : -1;
    const int dy = -std::abs(b.y - a.y), sy = a.y < b.y ? 1 : -1;
    int error = dx + dy;
    glm::ivec2 p = a;
    for (;;) {
        plot(canvas, p.x, p.y, color);
        if (p == b) break;
        const int twice = 2 * error;
        if (twice >= dy) {
            error += dy;
            p.x += sx;
        }
        if (twice <= dx) {
            error += dx;
            p.y += sy;
        }
    }
    // END SOLUTION
}

float edge_function(glm::vec2 a, glm::vec2 b, glm::vec2 p) {
    return (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
}

// Part 3. The top-left rule for an edge a -> b of a counter-clockwise triangle in
// window coordinates (y up): a left edge goes down, a top edge is horizontal
// and goes towards -x. A point exactly on such an edge is inside.
bool top_left(glm::vec2 a, glm::vec2 b) {
    // BEGIN SOLUTION
    // STUDENT: (void)a, (void)b;
    // STUDENT: return false;  // TODO: left edge (dy < 0) or top edge (dy == 0, dx < 0)
    const glm::vec2 d = b - a;
    return d.y < 0.0f || (d.y == 0.0f && d.x < 0.0f);
    // END SOLUTION
}

// Part 3. Inside when each edge function of the counter-clockwise order is
// positive, or zero on a top or left edge. A clockwise triangle (negative
// area) is made counter-clockwise first; a degenerate one covers nothing.
bool covers(glm::vec2 a, glm::vec2 b, glm::vec2 c, glm::vec2 p) {
    // BEGIN SOLUTION
    // STUDENT: (void)a, (void)b, (void)c, (void)p;
    // STUDENT: return false;  // TODO: three edge functions and top_left() for the zeros
    const float area = edge_function(a, b, c);
    if (area == 0.0f) return false;
    if (area < 0.0f) std::swap(b, c);
    const glm::vec2 edges[3][2] = {{a, b}, {b, c}, {c, a}};
    for (const auto& e : edges) {
        const float f = edge_function(e[0], e[1], p);
        if (f < 0.0f || (f == 0.0f && !top_left(e[0], e[1]))) return false;
    }
    return true;
    // END SOLUTION
}

// Part 4. The weight of each vertex is the area of the triangle that p forms
// with the opposite edge, over the whole area: (E_bc(p), E_ca(p), E_ab(p)) / E_ab(c).
glm::vec3 barycentric(glm::vec2 a, glm::vec2 b, glm::vec2 c, glm::vec2 p) {
    // BEGIN SOLUTION
    // STUDENT: (void)a, (void)b, (void)c, (void)p;
    // STUDENT: return glm::vec3(1.0f, 0.0f, 0.0f);  // TODO: three edge functions over the area
    const float area = edge_function(a, b, c);
    return glm::vec3(edge_function(b, c, p), edge_function(c, a, p), edge_function(a, b, p)) / area;
    // END SOLUTION
}

// Part 4. Window depth is affine in window x, y: sum of bary_i * z_i. The
// colour is affine (noperspective) or perspective-correct (smooth):
// sum(bary_i * c_i / w_i) / sum(bary_i / w_i).
Fragment interpolate(const WindowVertex v[3], glm::vec3 bary, bool perspective) {
    // BEGIN SOLUTION
    // STUDENT: (void)bary, (void)perspective;
    // STUDENT: return {v[0].color, v[0].window.z};  // TODO: weighted sums, / w when perspective
    Fragment f{glm::vec3(0.0f), 0.0f};
    float weight_sum = 0.0f;
    for (int i = 0; i < 3; ++i) {
        const float weight = perspective ? bary[i] / v[i].w : bary[i];
        f.color += weight * v[i].color;
        weight_sum += weight;
        f.depth += bary[i] * v[i].window.z;
    }
    f.color /= weight_sum;
    return f;
    // END SOLUTION
}

// Part 4. GL_LESS: a fragment nearer than what the pixel holds passes and
// its depth is stored; otherwise it is dropped and the depth kept.
bool depth_test(Canvas& canvas, int x, int y, float z) {
    // BEGIN SOLUTION
    // STUDENT: (void)canvas, (void)x, (void)y, (void)z;
    // STUDENT: return true;  // TODO: compare with canvas.depth, store when nearer
    float& stored = canvas.depth[static_cast<size_t>(canvas.index(x, y))];
    if (!(z < stored)) return false;
    stored = z;
    return true;
    // END SOLUTION
}

}  // namespace rasterizer
