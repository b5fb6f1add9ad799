// Lab 11's clipping and viewport mapping, the student parts (marked TODO)
// clip_near() and to_window(), and the loops that drive the CPU rasterizer
// over a triangle (shade_pixel(), fill_triangle(), draw_clip_triangle()).
#include <algorithm>
#include <cmath>

#include "raster.hpp"

namespace rasterizer {

// Part 5. Sutherland-Hodgman against the near plane: a point is in front
// when d = z + w >= 0. For each edge cur -> next: keep cur when it is in
// front; when d changes sign along the edge, add the point at
// t = d_cur / (d_cur - d_next), clip position and colour both mixed by t.
// One corner behind gives 4 vertices, two give 3, three give none. A corner
// on the plane (d = 0) is in front, and an edge from it to a corner behind
// (or back) still changes sign: the point added is that corner again.
std::vector<ClipVertex> clip_near(const ClipVertex tri[3]) {
    // BEGIN SOLUTION
    // STUDENT: return {tri[0], tri[1], tri[2]};  // TODO: keep, cut or drop each edge
    std::vector<ClipVertex> out;
    for (int i = 0; i < 3; ++i) {
        const ClipVertex& cur = tri[i];
        const ClipVertex& next = tri[(i + 1) % 3];
        const float d_cur = cur.clip.z + cur.clip.w;
        const float d_next = next.clip.z + next.clip.w;
        if (d_cur >= 0.0f) out.push_back(cur);
        if ((d_cur >= 0.0f) != (d_next >= 0.0f)) {
            const float t = d_cur / (d_cur - d_next);
            out.push_back({glm::mix(cur.clip, next.clip, t), glm::mix(cur.color, next.color, t)});
        }
    }
    return out;
    // END SOLUTION
}

// Part 5. The perspective divide (NDC = xyz / w), then the viewport mapping
// of a width x height window at the origin with depth range [0, 1]:
// x_w = (x_d + 1) * width / 2, y_w = (y_d + 1) * height / 2, z_w = (z_d + 1) / 2.
// The clip w is kept for perspective-correct interpolation.
WindowVertex to_window(const ClipVertex& v, int width, int height) {
    // BEGIN SOLUTION
    // STUDENT: (void)width, (void)height;
    // STUDENT: return {glm::vec3(0.0f), v.clip.w, v.color};  // TODO: divide, then map
    const glm::vec3 ndc = glm::vec3(v.clip) / v.clip.w;
    const glm::vec3 window{(ndc.x + 1.0f) * 0.5f * static_cast<float>(width),
                           (ndc.y + 1.0f) * 0.5f * static_cast<float>(height),
                           (ndc.z + 1.0f) * 0.5f};
    return {window, v.clip.w, v.color};
    // END SOLUTION
}

void shade_pixel(Canvas& canvas, const WindowVertex v[3], int x, int y, bool perspective,
                 bool depth) {
    const glm::vec2 centre(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
    const Fragment f = interpolate(
        v,
        barycentric(glm::vec2(v[0].window), glm::vec2(v[1].window), glm::vec2(v[2].window), centre),
        perspective);
    if (depth && !depth_test(canvas, x, y, f.depth)) return;
    plot(canvas, x, y, f.color);
}

void fill_triangle(Canvas& canvas, const WindowVertex v[3], bool perspective, bool depth) {
    const glm::vec2 a(v[0].window), b(v[1].window), c(v[2].window);
    const glm::vec2 lo = glm::min(a, glm::min(b, c)), hi = glm::max(a, glm::max(b, c));
    // The pixels whose centres can lie in the bounding box.
    const int x0 = std::max(0, static_cast<int>(std::floor(lo.x)));
    const int y0 = std::max(0, static_cast<int>(std::floor(lo.y)));
    const int x1 = std::min(canvas.width - 1, static_cast<int>(std::ceil(hi.x)));
    const int y1 = std::min(canvas.height - 1, static_cast<int>(std::ceil(hi.y)));
    for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
            const glm::vec2 centre(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
            if (covers(a, b, c, centre)) shade_pixel(canvas, v, x, y, perspective, depth);
        }
}

int draw_clip_triangle(Canvas& canvas, const ClipVertex tri[3], bool perspective, bool depth) {
    const std::vector<ClipVertex> polygon = clip_near(tri);
    int filled = 0;
    for (size_t i = 1; i + 1 < polygon.size(); ++i) {
        const WindowVertex v[3] = {to_window(polygon[0], canvas.width, canvas.height),
                                   to_window(polygon[i], canvas.width, canvas.height),
                                   to_window(polygon[i + 1], canvas.width, canvas.height)};
        fill_triangle(canvas, v, perspective, depth);
        ++filled;
    }
    return filled;
}

}  // namespace rasterizer
