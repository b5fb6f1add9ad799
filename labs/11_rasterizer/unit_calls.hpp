// The forms in which the grader calls lab 11's student parts (the unit checks
// of checkpoints.json, named after the parts): plain numbers and vectors in,
// plain numbers and vectors out. Course's references for them are in
// labs/11_rasterizer/grading/references.cpp.
#pragma once

#include <glm/glm.hpp>
#include <vector>

namespace rasterizer {

// line_dda() and line_bresenham() of the segment (ax, ay) - (bx, by) on an
// empty 32 x 32 canvas: every pixel written, row by row from the bottom, each
// as (x, y, how many times it was written).
std::vector<glm::vec3> line_dda_pixels(int ax, int ay, int bx, int by);
std::vector<glm::vec3> line_bresenham_pixels(int ax, int ay, int bx, int by);

// top_left() of the edge a -> b and of its reverse b -> a, 1 for true.
glm::vec2 top_left_both(glm::vec2 a, glm::vec2 b);

// The centres (x + 0.5, y + 0.5) of an 8 x 8 canvas that covers() puts in
// the triangle a b c, row by row from the bottom.
std::vector<glm::vec2> covers_centres(glm::vec2 a, glm::vec2 b, glm::vec2 c);

// fill_triangle_scanline() of the triangle a b c on an empty 8 x 8 canvas:
// every pixel written, row by row from the bottom, as (centre x, centre y,
// how many times it was written).
std::vector<glm::vec3> scanline_centres(glm::vec2 a, glm::vec2 b, glm::vec2 c);

// interpolate() for corners of colours c0, c1, c2, window depths z and clip
// w, at the weights `weights` divided by their sum: (r, g, b, depth).
glm::vec4 interpolate_at(glm::vec3 c0, glm::vec3 c1, glm::vec3 c2, glm::vec3 z, glm::vec3 w,
                         glm::vec3 weights, bool perspective);

// depth_test() of a fragment at depth z on a pixel that holds `stored`:
// (1 when it passes, else 0; the depth the pixel holds afterwards).
glm::vec2 depth_test_at(float stored, float z);

// clip_near() of the triangle p0 p1 p2 (coloured red, green, blue): the clip
// positions of the vertices it returns, in order.
std::vector<glm::vec4> clip_near_at(glm::vec4 p0, glm::vec4 p1, glm::vec4 p2);

// to_window() of a vertex at `clip` in a width x height window: (x_w, y_w,
// z_w, the w kept).
glm::vec4 to_window_at(glm::vec4 clip, int width, int height);

}  // namespace rasterizer
