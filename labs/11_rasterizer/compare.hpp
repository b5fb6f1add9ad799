// Lab 11's figures comparing the CPU image with GL's (README.md, Stats):
// coverage counts, the largest colour difference, and the lines' pixels per
// major-axis step.
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <vector>

#include "framework/image.hpp"
#include "raster.hpp"
#include "scenes.hpp"

namespace rasterizer {

// The CPU canvas as 8-bit RGBA, bottom row first: round(255 * c) per channel.
fw::Image canvas_image(const Canvas& canvas);

// Which pixels an image covers (any channel not 0).
std::vector<bool> coverage(const fw::Image& image);

// Of each line (their boxes are disjoint), the steps along its major axis,
// end to end, at which exactly one pixel of its box is covered; summed.
int one_per_major(const std::vector<bool>& covered, int width, const std::vector<Line>& lines);

// `lab_stats` (README.md, Stats): "cpu" and "gl" {filled, overdraw}, the
// CPU's "triangles", "differ" (pixels covered by one side only),
// "max_color_difference" (of pixels both cover, in 1/255), "color_differ"
// (pixels both cover whose colours differ by more than 2/255),
// "max_depth_difference" (window depth, every pixel) and, for lines,
// "cpu"/"gl" "one_per_major".
nlohmann::json compare_stats(const CpuScene& cpu, const fw::Image& gl, const fw::DepthImage& depth,
                             const fw::Image& counts, const std::vector<Line>* lines);

}  // namespace rasterizer
