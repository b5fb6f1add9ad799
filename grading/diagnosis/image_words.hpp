// A failed image check said in words: where the rendered frame differs from
// the reference and which colours are expected and found there, so that a
// student reads "expected orange (1, 0.6, 0.1), found black (0, 0, 0) at 1,204
// pixels in x 380-420, y 150-210" instead of only a count of pixels.
#pragma once

#include <string>

#include "framework/image.hpp"

namespace grading {

// A plain name for a colour: black, white, grey, red, orange, yellow, green,
// cyan, blue, purple, magenta, pink, brown, with "dark" or "light" where it
// helps; alpha is ignored.
std::string colour_name(const fw::Rgba8& colour);

// "orange (1, 0.6, 0.1)": the name and the channels in 0..1, two decimals.
std::string colour_words(const fw::Rgba8& colour);

// The failed pixels of `result` (compare_images(actual, expected)) in words:
// their bounding box, then up to `groups` kinds of difference (each pair of
// colour names expected and found), most pixels first, with their count,
// the pair of colours (expected, found) most common at its pixels and its
// own bounding box. Coordinates
// are pixels from the bottom-left corner, as a probe's "at". Empty when no
// pixel failed or the sizes differ.
std::string describe_difference(const fw::Image& actual, const fw::Image& expected,
                                const fw::CompareResult& result, size_t groups = 3);

}  // namespace grading
