// Images read back from GL and written to disk: RGBA8 colour (PNG) and float
// depth (PFM), plus the fuzzy comparison of the `image` check (docs/contract.md, Checks).
//
// Storage follows GL: row 0 is the BOTTOM row (window y = 0), so pixel
// (x, y) of an Image is the pixel at GL window coordinates (x + 0.5, y + 0.5).
// PNG files are written top row first (flipped on write and on read); PFM
// files are bottom row first, like GL, so they are written as stored.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace fw {

struct Rgba8 {
    std::uint8_t r = 0, g = 0, b = 0, a = 0;
    bool operator==(const Rgba8& o) const { return r == o.r && g == o.g && b == o.b && a == o.a; }
    bool operator!=(const Rgba8& o) const { return !(*this == o); }
};

struct Image {
    int width = 0, height = 0;
    std::vector<Rgba8> pixels;  // width * height, bottom row first

    Image() = default;
    Image(int w, int h, Rgba8 fill = {});
    Rgba8& at(int x, int y) { return pixels[static_cast<size_t>(y) * width + x]; }
    const Rgba8& at(int x, int y) const { return pixels[static_cast<size_t>(y) * width + x]; }
};

struct DepthImage {
    int width = 0, height = 0;
    std::vector<float> values;  // width * height, bottom row first

    DepthImage() = default;
    DepthImage(int w, int h, float fill = 0.0f);
    float& at(int x, int y) { return values[static_cast<size_t>(y) * width + x]; }
    float at(int x, int y) const { return values[static_cast<size_t>(y) * width + x]; }
};

// PNG, 8 bits per channel, in the smallest colour type that keeps every
// pixel (grey, RGB, or RGBA where a pixel is not opaque). Throw fw::Error
// naming the path on failure.
void write_png(const std::string& path, const Image& img);
// The PNG file's bytes, in memory.
std::string encode_png(const Image& img);
// The same at libdeflate's compression `level` (1 to 12; bench_png
// compares them); the one-argument form uses kPngLevel.
std::string encode_png(const Image& img, int level);
inline constexpr int kPngLevel = 2;
// A baseline JPEG's bytes (quality 1-100; alpha is dropped), for pictures
// that must stay small.
std::string encode_jpeg(const Image& img, int quality);
// `img` made at most `max_side` pixels wide and high, keeping its shape: each
// pixel the mean of the block it covers, so that a one-pixel line stays
// visible as a fainter one, or with `brightest` each channel's largest value
// in the block, so that a single marked pixel (a difference image's) stays as
// bright. An image already that small is returned as it is.
Image shrink(const Image& img, int max_side, bool brightest = false);
Image read_png(const std::string& path);
// The same from a PNG file's bytes already in memory; `name` is for messages.
Image decode_png(const std::string& bytes, const std::string& name);
// decode_png's own path, for the PNGs course reads by the hundred (8 bits a
// channel, grey, grey and alpha, RGB or RGBA, not interlaced, no palette or
// transparency chunk): false, and `img` unspecified, for any other file or a
// damaged one, which decode_png then gives to stb_image.
bool decode_plain_png(const std::string& bytes, Image& img);
// The width and height a PNG's header (its IHDR chunk) states, read without
// decoding anything; false when `bytes` does not start like a PNG.
bool png_header_size(const std::string& bytes, int& width, int& height);

// PAM (netpbm's P7, 8-bit RGB_ALPHA, top row first): raw pixels, for frames
// handed from one process to another (a grading child to course) with
// nothing to compress or decompress. decode_pam is strict: the exact header
// (image_pam.cpp), sizes 1..65536 and exactly the bytes they call for; it
// throws fw::Error naming `name` and what is wrong.
std::string encode_pam(const Image& img);
// encode_pam's header alone: its pixels follow, the top row first.
std::string pam_header(const Image& img);
void write_pam(const std::string& path, const Image& img);
Image decode_pam(std::string_view bytes, const std::string& name);
// The width and height a PAM's header states, read without the pixels; false
// when `bytes` does not start with such a header.
bool pam_header_size(std::string_view bytes, int& width, int& height);

// PFM, single channel ("Pf"), little-endian float32, rows bottom first:
// header "Pf\n<width> <height>\n-1.0\n". read_pfm accepts either byte order
// (the sign of the scale) and rejects colour ("PF") files with a clear error.
std::string encode_pfm(const DepthImage& img);
void write_pfm(const std::string& path, const DepthImage& img);
DepthImage read_pfm(const std::string& path);
// The same from bytes already read; `name` is for messages.
DepthImage decode_pfm(std::string bytes, const std::string& name);

// docs/contract.md, Checks, `image`: the comparison runs both ways. A pixel
// position fails when the pixel of `actual` there has no pixel of `expected`
// in its (2r+1)x(2r+1) neighbourhood (r = `radius`, default 1: 3x3) within
// `tolerance` (0-255) on every channel (RGBA), or when the pixel of `expected`
// there has none of `actual` in its neighbourhood: a frame that lacks a thin
// line of the reference fails as one that adds it does. The image passes when
// failed_fraction <= max_failed_fraction.
struct CompareOptions {
    int tolerance = 8;
    int radius = 1;
    double max_failed_fraction = 0.001;
    // Whether to fill CompareResult::difference; without it, a frame equal to
    // its reference row by row costs a memcmp per row.
    bool difference = true;
};

struct CompareResult {
    bool passed = false;
    bool size_mismatch = false;  // then nothing else is meaningful
    long failed_pixels = 0;      // positions failing either way, each counted once
    long total_pixels = 0;
    double failed_fraction = 0.0;
    int max_channel_error = 0;  // over all pixels and both ways, to the nearest neighbour match
    Image difference;  // failed pixels dim red -> yellow by the larger error of the two ways;
                       // passing ones dark grey (empty without CompareOptions::difference)
    std::vector<std::uint8_t> failed;  // width * height, bottom row first: 1 where a pixel failed
    CompareOptions options;            // the thresholds used, for summary()
    int actual_width = 0, actual_height = 0, expected_width = 0, expected_height = 0;
    std::string summary()
        const;  // one line: "12 of 262144 pixels (0.0046%) differ by more than 8/255; limit 0.1%"
};

CompareResult compare_images(const Image& actual, const Image& expected,
                             const CompareOptions& opt = {});

}  // namespace fw
