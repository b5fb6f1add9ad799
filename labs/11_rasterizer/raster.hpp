// Lab 11's CPU rasterizer: the canvas it draws into and the steps GL performs
// between the vertex shader and the fragment shader, written out in
// raster.cpp (the student parts) for the lab in rasterizer_lab.cpp.
#pragma once

#include <glm/glm.hpp>
#include <vector>

namespace rasterizer {

// A width x height image, row 0 at the bottom as in GL's window coordinates:
// pixel (x, y) covers [x, x + 1) x [y, y + 1), its centre is (x + 0.5, y + 0.5).
struct Canvas {
    Canvas(int w, int h);
    int width, height;
    std::vector<glm::vec3> color;  // black at first
    std::vector<float> depth;      // 1 (the far plane) at first
    std::vector<int> writes;       // how many times plot() wrote each pixel
    int index(int x, int y) const { return y * width + x; }
    bool inside(int x, int y) const { return x >= 0 && y >= 0 && x < width && y < height; }
};

// Writes `color` at pixel (x, y) and counts the write; a pixel outside the
// canvas is skipped.
void plot(Canvas& canvas, int x, int y, glm::vec3 color);

// A vertex after the viewport mapping: window x, y in pixels, window z in
// [0, 1], the clip-space w it had (for perspective-correct interpolation),
// and its colour.
struct WindowVertex {
    glm::vec3 window;
    float w;
    glm::vec3 color;
};

// A vertex in clip space, as the vertex shader writes gl_Position.
struct ClipVertex {
    glm::vec4 clip;
    glm::vec3 color;
};

// What interpolation gives a fragment.
struct Fragment {
    glm::vec3 color;
    float depth;
};

// Part 1: the pixels of the line from pixel a to pixel b, both included, by
// DDA. Part 2: the same by Bresenham, integers only.
void line_dda(Canvas& canvas, glm::ivec2 a, glm::ivec2 b, glm::vec3 color);
void line_bresenham(Canvas& canvas, glm::ivec2 a, glm::ivec2 b, glm::vec3 color);

// (b - a) x (p - a): positive when p is left of the directed edge a -> b.
float edge_function(glm::vec2 a, glm::vec2 b, glm::vec2 p);

// Part 3: whether a point on the edge a -> b of a counter-clockwise triangle
// belongs to it (a left or a top edge); whether the triangle a b c (either winding) covers the
// point p, with the top-left rule for a p on an edge.
bool top_left(glm::vec2 a, glm::vec2 b);
bool covers(glm::vec2 a, glm::vec2 b, glm::vec2 c, glm::vec2 p);

// Part 4: p's barycentric coordinates in the triangle a b c; the colour and
// depth at those coordinates, affine or perspective-correct; the depth test.
glm::vec3 barycentric(glm::vec2 a, glm::vec2 b, glm::vec2 c, glm::vec2 p);
Fragment interpolate(const WindowVertex v[3], glm::vec3 bary, bool perspective);
bool depth_test(Canvas& canvas, int x, int y, float z);

// Part 5: the triangle clipped against the near plane z = -w (0, 3 or 4
// vertices, in order); a clip-space vertex mapped to the window.
std::vector<ClipVertex> clip_near(const ClipVertex tri[3]);
WindowVertex to_window(const ClipVertex& v, int width, int height);

// Pixel (x, y) of the triangle: its centre's barycentric coordinates,
// interpolate(), depth_test() when `depth` is on, then plot().
void shade_pixel(Canvas& canvas, const WindowVertex v[3], int x, int y, bool perspective,
                 bool depth);
// Every pixel whose centre the triangle covers, by shade_pixel().
void fill_triangle(Canvas& canvas, const WindowVertex v[3], bool perspective, bool depth);
// Part 6: the same pixels, colours and depths, row by row: each row's span
// between the left and the right edges.
void fill_triangle_scanline(Canvas& canvas, const WindowVertex v[3], bool perspective, bool depth);
// clip_near(), then each triangle of the fan (0, i, i + 1) through
// to_window() and fill_triangle(); returns the number of triangles filled.
int draw_clip_triangle(Canvas& canvas, const ClipVertex tri[3], bool perspective, bool depth);

}  // namespace rasterizer
