// Lab 11's scanline fill, the student part (marked TODO)
// fill_triangle_scanline(): the pixels of fill_triangle(), found row by row.
#include <algorithm>
#include <cmath>

#include "raster.hpp"

namespace rasterizer {

// Part 6. The triangle made counter-clockwise as in covers() (degenerate:
// nothing). For the row y, centre height y_c = y + 0.5, each edge a -> b
// bounds the span: a horizontal edge keeps the whole row (E_ab > 0, or 0 on a
// top edge) or drops it; any other crosses the row at x = a.x + (y_c - a.y)
// (b.x - a.x) / (b.y - a.y), computed from the edge itself, not by adding
// the slope row after row. An edge going down (a left edge) keeps the centres
// at or right of its crossing, one going up those strictly left of it. Each
// pixel of the span goes through shade_pixel(), rows from the bottom, x
// increasing: the same pixels, colours and depths as fill_triangle().
void fill_triangle_scanline(Canvas& canvas, const WindowVertex v[3], bool perspective, bool depth) {
    // BEGIN SOLUTION
    // STUDENT: (void)canvas, (void)v, (void)perspective, (void)depth;  // TODO: each row's span
    glm::vec2 p[3] = {glm::vec2(v[0].window), glm::vec2(v[1].window), glm::vec2(v[2].window)};
    const float area = edge_function(p[0], p[1], p[2]);
    if (area == 0.0f) return;
    if (area < 0.0f) std::swap(p[1], p[2]);
    const float lo = std::min({p[0].y, p[1].y, p[2].y}), hi = std::max({p[0].y, p[1].y, p[2].y});
    const int y0 = std::max(0, static_cast<int>(std::floor(lo)));
    const int y1 = std::min(canvas.height - 1, static_cast<int>(std::ceil(hi)));
    for (int y = y0; y <= y1; ++y) {
        const float yc = static_cast<float>(y) + 0.5f;
        float left = 0.0f, right = static_cast<float>(canvas.width);  // left <= centre < right
        bool row_in = true;
        for (int i = 0; i < 3; ++i) {
            const glm::vec2 a = p[i], b = p[(i + 1) % 3];
            if (a.y == b.y) {
                const float e = (b.x - a.x) * (yc - a.y);
                row_in = row_in && (e > 0.0f || (e == 0.0f && b.x < a.x));
                continue;
            }
            const float x = a.x + (yc - a.y) * (b.x - a.x) / (b.y - a.y);
            if (b.y < a.y)
                left = std::max(left, x);
            else
                right = std::min(right, x);
        }
        if (!row_in || left >= right) continue;
        const int x0 = static_cast<int>(std::ceil(left - 0.5f));
        const int x1 = static_cast<int>(std::ceil(right - 0.5f));
        for (int x = x0; x < x1; ++x) shade_pixel(canvas, v, x, y, perspective, depth);
    }
    // END SOLUTION
}

}  // namespace rasterizer
