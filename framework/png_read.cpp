// Reading PNG. The files course reads by the hundred (references, frames of
// the report) are 8 bits a channel, not interlaced, in grey, RGB or RGBA:
// those are inflated by libdeflate and unfiltered here, straight into the
// image's bottom-first rows. Every other PNG (palettes, 16 bits, Adam7, a
// transparency chunk), and any file this path finds damaged, goes to
// stb_image, whose words then explain what is wrong with it.
#include <libdeflate.h>
#include <stb/stb_image.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "framework/error.hpp"
#include "framework/image.hpp"

namespace fw {

namespace {

std::uint32_t be32(const unsigned char* p) {
    return std::uint32_t(p[0]) << 24 | std::uint32_t(p[1]) << 16 | std::uint32_t(p[2]) << 8 | p[3];
}

// libdeflate's decompressor of this thread, kept between images.
libdeflate_decompressor* decompressor() {
    struct Held {
        libdeflate_decompressor* d = libdeflate_alloc_decompressor();
        ~Held() { libdeflate_free_decompressor(d); }
    };
    thread_local Held held;
    return held.d;
}

// What the direct path needs of a file: its size, its channels and its
// compressed pixels (the IDAT chunks joined). False for anything else.
struct Plain {
    std::uint32_t width = 0, height = 0;
    int channels = 0;
    std::string idat;
};

bool plain_png(const std::string& bytes, Plain& png) {
    const auto* p = reinterpret_cast<const unsigned char*>(bytes.data());
    size_t at = 8;
    bool header = false;
    while (at + 12 <= bytes.size()) {
        const std::uint32_t length = be32(p + at);
        if (length > bytes.size() - at - 12) return false;
        const char* type = bytes.data() + at + 4;
        const unsigned char* data = p + at + 8;
        if (std::memcmp(type, "IHDR", 4) == 0) {
            if (header || length != 13) return false;
            header = true;
            png.width = be32(data);
            png.height = be32(data + 4);
            // 8 bits, deflate, PNG's filters, no interlace.
            if (data[8] != 8 || data[10] != 0 || data[11] != 0 || data[12] != 0) return false;
            const int channels[] = {1, 0, 3, 0, 2, 0, 4};  // by colour type; 0: not here
            png.channels = data[9] <= 6 ? channels[data[9]] : 0;
            // The sizes stb_image accepts, and no more than 1 GiB inflated.
            if (!png.channels || png.width == 0 || png.height == 0 || png.width > (1u << 24) ||
                png.height > (1u << 24) ||
                (std::uint64_t(png.width) * png.channels + 1) * png.height > (1ull << 30))
                return false;
        } else if (!header || std::memcmp(type, "PLTE", 4) == 0 ||
                   std::memcmp(type, "tRNS", 4) == 0) {
            return false;
        } else if (std::memcmp(type, "IDAT", 4) == 0) {
            png.idat.append(bytes, at + 8, length);
        } else if (std::memcmp(type, "IEND", 4) == 0) {
            return !png.idat.empty();
        } else if (!(type[0] & 0x20)) {
            return false;  // a critical chunk PNG does not define
        }
        at += 12 + size_t(length);
    }
    return false;
}

// `n` bytes of `row` plus those of `above`, byte by byte without carries:
// the "up" filter undone, the common one, eight bytes at a time.
void add_above(unsigned char* row, const unsigned char* above, size_t n) {
    constexpr std::uint64_t kLow7 = 0x7f7f7f7f7f7f7f7full;
    size_t i = 0;
    for (; i + 8 <= n; i += 8) {
        std::uint64_t a, b;
        std::memcpy(&a, row + i, 8);
        std::memcpy(&b, above + i, 8);
        const std::uint64_t sum = ((a & kLow7) + (b & kLow7)) ^ ((a ^ b) & ~kLow7);
        std::memcpy(row + i, &sum, 8);
    }
    for (; i < n; ++i) row[i] = static_cast<unsigned char>(row[i] + above[i]);
}

// PNG's five row filters undone in `rows` (each a filter byte, then
// `stride` bytes), `bpp` bytes a pixel. False on a filter that does not exist.
bool unfilter(std::vector<unsigned char>& rows, size_t stride, size_t height, size_t bpp) {
    const std::vector<unsigned char> zeros(stride, 0);
    const unsigned char* above = zeros.data();
    for (size_t y = 0; y < height; ++y) {
        unsigned char* row = &rows[y * (stride + 1)];
        const unsigned filter = row[0];
        unsigned char* cur = row + 1;
        switch (filter) {
            case 0:
                break;
            case 1:
                for (size_t i = bpp; i < stride; ++i) cur[i] += cur[i - bpp];
                break;
            case 2:
                add_above(cur, above, stride);
                break;
            case 3:
                for (size_t i = 0; i < stride; ++i)
                    cur[i] +=
                        static_cast<unsigned char>(((i >= bpp ? cur[i - bpp] : 0) + above[i]) / 2);
                break;
            case 4:
                for (size_t i = 0; i < stride; ++i) {
                    const int a = i >= bpp ? cur[i - bpp] : 0, b = above[i];
                    const int c = i >= bpp ? above[i - bpp] : 0;
                    const int pa = std::abs(b - c), pb = std::abs(a - c),
                              pc = std::abs(a + b - 2 * c);
                    cur[i] += static_cast<unsigned char>(pa <= pb && pa <= pc ? a
                                                         : pb <= pc           ? b
                                                                              : c);
                }
                break;
            default:
                return false;
        }
        above = cur;
    }
    return true;
}

}  // namespace

bool decode_plain_png(const std::string& bytes, Image& img) {
    Plain png;
    if (!plain_png(bytes, png)) return false;
    const size_t stride = size_t(png.width) * png.channels, height = png.height;
    std::vector<unsigned char> rows((stride + 1) * height);
    size_t inflated = 0;
    if (libdeflate_zlib_decompress(decompressor(), png.idat.data(), png.idat.size(), rows.data(),
                                   rows.size(), &inflated) != LIBDEFLATE_SUCCESS ||
        inflated != rows.size() || !unfilter(rows, stride, height, png.channels))
        return false;
    img = Image(static_cast<int>(png.width), static_cast<int>(png.height));
    for (size_t y = 0; y < height; ++y) {
        const unsigned char* src = &rows[y * (stride + 1) + 1];
        // PNG's top row is GL's last.
        auto* out = reinterpret_cast<unsigned char*>(&img.pixels[(height - 1 - y) * png.width]);
        const size_t w = png.width;
        if (png.channels == 4) {
            std::memcpy(out, src, stride);
        } else if (png.channels == 3) {
            // Four bytes read for each pixel but the last (whose fourth would
            // lie past the buffer's end on the last row), its alpha then set.
            for (size_t x = 0; x + 1 < w; ++x, out += 4, src += 3) {
                std::uint32_t p;
                std::memcpy(&p, src, 4);
                std::memcpy(out, &p, 4);
                out[3] = 255;
            }
            out[0] = src[0], out[1] = src[1], out[2] = src[2], out[3] = 255;
        } else if (png.channels == 2) {
            for (size_t x = 0; x < w; ++x, out += 4, src += 2)
                out[0] = out[1] = out[2] = src[0], out[3] = src[1];
        } else {
            for (size_t x = 0; x < w; ++x, out += 4, ++src)
                out[0] = out[1] = out[2] = src[0], out[3] = 255;
        }
    }
    return true;
}

Image decode_png(const std::string& bytes, const std::string& name) {
    static const char signature[] = "\x89PNG\r\n\x1a\n";
    if (bytes.compare(0, 8, signature, 8) != 0)
        throw Error("cannot read PNG '" + name + "': not a PNG file");
    Image img;
    if (decode_plain_png(bytes, img)) return img;
    int w = 0, h = 0, channels = 0;
    // Asking for 4 components converts grey, grey+alpha and RGB to RGBA8.
    stbi_uc* data = stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()),
                                          static_cast<int>(bytes.size()), &w, &h, &channels, 4);
    if (!data) throw Error("cannot read PNG '" + name + "': " + stbi_failure_reason());
    img = Image(w, h);
    for (int y = 0; y < h; ++y)  // PNG's top row first, GL's bottom row first
        std::memcpy(&img.pixels[size_t(h - 1 - y) * w], data + size_t(y) * w * 4, size_t(w) * 4);
    stbi_image_free(data);
    return img;
}

}  // namespace fw
