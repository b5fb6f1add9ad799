// The forms in which the grader calls lab 11's student parts (unit_calls.hpp).
#include "unit_calls.hpp"

#include "raster.hpp"
#include "scenes.hpp"

namespace rasterizer {

namespace {

// Every pixel of `canvas` written at least once, row by row from the bottom.
std::vector<glm::vec3> written(const Canvas& canvas) {
    std::vector<glm::vec3> out;
    for (int y = 0; y < canvas.height; ++y)
        for (int x = 0; x < canvas.width; ++x) {
            const int n = canvas.writes[static_cast<size_t>(canvas.index(x, y))];
            if (n > 0) out.emplace_back(x, y, n);
        }
    return out;
}

}  // namespace

std::vector<glm::vec3> line_dda_pixels(int ax, int ay, int bx, int by) {
    Canvas canvas(kGrid, kGrid);
    line_dda(canvas, {ax, ay}, {bx, by}, glm::vec3(1.0f));
    return written(canvas);
}

std::vector<glm::vec3> line_bresenham_pixels(int ax, int ay, int bx, int by) {
    Canvas canvas(kGrid, kGrid);
    line_bresenham(canvas, {ax, ay}, {bx, by}, glm::vec3(1.0f));
    return written(canvas);
}

glm::vec2 top_left_both(glm::vec2 a, glm::vec2 b) {
    return {top_left(a, b) ? 1.0f : 0.0f, top_left(b, a) ? 1.0f : 0.0f};
}

std::vector<glm::vec2> covers_centres(glm::vec2 a, glm::vec2 b, glm::vec2 c) {
    std::vector<glm::vec2> out;
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            const glm::vec2 centre(static_cast<float>(x) + 0.5f, static_cast<float>(y) + 0.5f);
            if (covers(a, b, c, centre)) out.push_back(centre);
        }
    return out;
}

std::vector<glm::vec3> scanline_centres(glm::vec2 a, glm::vec2 b, glm::vec2 c) {
    Canvas canvas(8, 8);
    const WindowVertex v[3] = {{glm::vec3(a, 0.5f), 1.0f, glm::vec3(1.0f)},
                               {glm::vec3(b, 0.5f), 1.0f, glm::vec3(1.0f)},
                               {glm::vec3(c, 0.5f), 1.0f, glm::vec3(1.0f)}};
    fill_triangle_scanline(canvas, v, true, false);
    std::vector<glm::vec3> out;
    for (const glm::vec3& pixel : written(canvas))
        out.push_back(pixel + glm::vec3(0.5f, 0.5f, 0.0f));
    return out;
}

glm::vec4 interpolate_at(glm::vec3 c0, glm::vec3 c1, glm::vec3 c2, glm::vec3 z, glm::vec3 w,
                         glm::vec3 weights, bool perspective) {
    const WindowVertex v[3] = {{{0.0f, 0.0f, z[0]}, w[0], c0},
                               {{0.0f, 0.0f, z[1]}, w[1], c1},
                               {{0.0f, 0.0f, z[2]}, w[2], c2}};
    const Fragment f =
        interpolate(v, weights / (weights[0] + weights[1] + weights[2]), perspective);
    return glm::vec4(f.color, f.depth);
}

glm::vec2 depth_test_at(float stored, float z) {
    Canvas canvas(1, 1);
    canvas.depth[0] = stored;
    const bool passes = depth_test(canvas, 0, 0, z);
    return {passes ? 1.0f : 0.0f, canvas.depth[0]};
}

std::vector<glm::vec4> clip_near_at(glm::vec4 p0, glm::vec4 p1, glm::vec4 p2) {
    const ClipVertex tri[3] = {{p0, {1, 0, 0}}, {p1, {0, 1, 0}}, {p2, {0, 0, 1}}};
    std::vector<glm::vec4> out;
    for (const ClipVertex& v : clip_near(tri)) out.push_back(v.clip);
    return out;
}

glm::vec4 to_window_at(glm::vec4 clip, int width, int height) {
    const WindowVertex v = to_window({clip, glm::vec3(1.0f)}, width, height);
    return glm::vec4(v.window, v.w);
}

}  // namespace rasterizer
