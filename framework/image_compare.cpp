// The fuzzy image comparison behind the `image` check, and its difference
// image (docs/contract.md).
#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "framework/image.hpp"

namespace fw {

namespace {

int channel_error(Rgba8 a, Rgba8 b) {
    const int dr = std::abs(a.r - b.r), dg = std::abs(a.g - b.g);
    const int db = std::abs(a.b - b.b), da = std::abs(a.a - b.a);
    return std::max(std::max(dr, dg), std::max(db, da));
}

// A quarter of the pixel's luminance, rounded, so that a difference image
// still shows the shape: 0.25 * (0.2126 r + 0.7152 g + 0.0722 b) + 0.5,
// truncated. In whole numbers that is n / 40000 with n below; only where n
// is a multiple of 40000 (exactly half-way before rounding) can the
// floating-point form land on the other side, so that case takes it.
std::uint8_t quarter_luminance(Rgba8 p) {
    const unsigned n = 2126u * p.r + 7152u * p.g + 722u * p.b + 20000u;
    if (n % 40000u != 0) return static_cast<std::uint8_t>(n / 40000u);
    return static_cast<std::uint8_t>(0.25 * (0.2126 * p.r + 0.7152 * p.g + 0.0722 * p.b) + 0.5);
}

// Failed pixels: dim red just over the tolerance, brightening to yellow at 255.
Rgba8 heat(int error, int tolerance) {
    double t = tolerance >= 255 ? 1.0 : double(error - tolerance) / (255 - tolerance);
    t = std::clamp(t, 0.0, 1.0);
    auto u8 = [](double v) { return static_cast<std::uint8_t>(std::clamp(v, 0.0, 255.0) + 0.5); };
    return {u8(96 + 159 * std::min(1.0, 2 * t)), u8(255 * std::max(0.0, 2 * t - 1)), 0, 255};
}

// The smallest channel error between `p` and a pixel of `other` within `r`
// of (x, y), starting from `here` (the error against other's pixel at (x, y))
// and stopping at the first row that finds one within `enough`: exact only
// above it.
int nearest_error(Rgba8 p, const Image& other, int x, int y, int r, int enough, int here) {
    int best = here;
    const int x0 = std::max(0, x - r), x1 = std::min(other.width - 1, x + r);
    for (int ny = std::max(0, y - r); best > enough && ny <= std::min(other.height - 1, y + r);
         ++ny) {
        const Rgba8* row = &other.at(0, ny);
        for (int nx = x0; nx <= x1; ++nx) best = std::min(best, channel_error(p, row[nx]));
    }
    return best;
}

// The error of the pixel at (x, y), which differs in place by `here` (over
// `tolerance`), both ways: the larger of the frame's pixel's nearest error
// among the reference's and the reference's among the frame's; exact above
// `tolerance`. The second search stops at an error no larger than the
// first's, and is not needed when the first found none below `here` (its
// start).
int pixel_error(const Image& actual, const Image& expected, int x, int y, int r, int tolerance,
                int here) {
    const int error = nearest_error(actual.at(x, y), expected, x, y, r, tolerance, here);
    const int enough = std::max(tolerance, error);
    if (here <= enough) return error;
    return std::max(error, nearest_error(expected.at(x, y), actual, x, y, r, enough, here));
}

}  // namespace

CompareResult compare_images(const Image& actual, const Image& expected,
                             const CompareOptions& opt) {
    CompareResult res;
    res.options = opt;
    res.actual_width = actual.width;
    res.actual_height = actual.height;
    res.expected_width = expected.width;
    res.expected_height = expected.height;
    if (actual.width != expected.width || actual.height != expected.height) {
        res.size_mismatch = true;
        return res;
    }
    const int w = actual.width, h = actual.height, r = std::max(0, opt.radius);
    res.total_pixels = static_cast<long>(w) * h;
    if (opt.difference) res.difference = Image(w, h);
    res.failed.assign(static_cast<size_t>(w) * h, 0);
    auto grey = [](Rgba8 a) {
        const std::uint8_t g = quarter_luminance(a);
        return Rgba8{g, g, g, 255};
    };
    for (int y = 0; y < h; ++y) {
        const Rgba8* a_row = &actual.at(0, y);
        const Rgba8* e_row = &expected.at(0, y);
        Rgba8* d_row = opt.difference ? &res.difference.at(0, y) : nullptr;
        if (std::memcmp(a_row, e_row, static_cast<size_t>(w) * sizeof(Rgba8)) == 0) {
            // Every pixel equals its reference in place: an error of 0 both ways.
            if (d_row)
                for (int x = 0; x < w; ++x) d_row[x] = grey(a_row[x]);
            continue;
        }
        for (int x = 0; x < w; ++x) {
            // Only pixels that differ in place need the neighbourhood searches.
            const int here = channel_error(a_row[x], e_row[x]);
            const int error = here <= opt.tolerance
                                  ? here
                                  : pixel_error(actual, expected, x, y, r, opt.tolerance, here);
            res.max_channel_error = std::max(res.max_channel_error, error);
            if (error > opt.tolerance) {
                ++res.failed_pixels;
                res.failed[static_cast<size_t>(y) * w + x] = 1;
                if (d_row) d_row[x] = heat(error, opt.tolerance);
            } else if (d_row) {
                d_row[x] = grey(a_row[x]);
            }
        }
    }
    res.failed_fraction = res.total_pixels ? double(res.failed_pixels) / res.total_pixels : 0.0;
    // The epsilon keeps "exactly at the limit" passing despite rounding in the division.
    res.passed = res.failed_fraction <= opt.max_failed_fraction + 1e-12;
    return res;
}

std::string CompareResult::summary() const {
    char line[320];
    if (size_mismatch) {
        std::snprintf(line, sizeof line, "size mismatch: actual image is %dx%d, expected %dx%d",
                      actual_width, actual_height, expected_width, expected_height);
        return line;
    }
    const int n = 2 * std::max(0, options.radius) + 1;
    std::snprintf(line, sizeof line,
                  "%ld of %ld pixels (%.3g%%) differ by more than %d/255 (%dx%d neighbourhood, "
                  "largest error %d/255); limit %.3g%%: %s",
                  failed_pixels, total_pixels, 100.0 * failed_fraction, options.tolerance, n, n,
                  max_channel_error, 100.0 * options.max_failed_fraction, passed ? "pass" : "FAIL");
    return line;
}

}  // namespace fw
