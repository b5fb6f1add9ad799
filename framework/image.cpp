// PNG written here over libdeflate, JPEG by libjpeg-turbo, PFM by hand. PNG
// read: png_read.cpp; PAM: image_pam.cpp; the comparison: image_compare.cpp.
#include "framework/image.hpp"

#include <libdeflate.h>
#include <turbojpeg.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>

#include "framework/error.hpp"

namespace fw {

namespace {

void check_size(const char* what, int w, int h) {
    if (w < 0 || h < 0)
        throw UsageError(std::string(what) + " size " + std::to_string(w) + "x" +
                         std::to_string(h) + " is negative");
}

// The whole file as bytes; throws naming the path and what went wrong.
std::string read_file(const std::string& path, const char* kind) {
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
        throw Error("cannot read " + std::string(kind) + " '" + path + "': file not found");
    errno = 0;
    std::ifstream in(path, std::ios::binary);
    if (!in)
        throw Error("cannot read " + std::string(kind) + " '" + path +
                    "': " + (errno ? std::strerror(errno) : "cannot open it"));
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

}  // namespace

Image::Image(int w, int h, Rgba8 fill) : width(w), height(h) {
    check_size("Image", w, h);
    pixels.assign(static_cast<size_t>(w) * h, fill);
}

DepthImage::DepthImage(int w, int h, float fill) : width(w), height(h) {
    check_size("DepthImage", w, h);
    values.assign(static_cast<size_t>(w) * h, fill);
}

// ---- PNG -------------------------------------------------------------------

void write_png(const std::string& path, const Image& img) {
    if (img.width <= 0 || img.height <= 0 ||
        img.pixels.size() != static_cast<size_t>(img.width) * img.height)
        throw Error("cannot write PNG '" + path + "': image is " + std::to_string(img.width) + "x" +
                    std::to_string(img.height) + " with " + std::to_string(img.pixels.size()) +
                    " pixels");
    const std::string bytes = encode_png(img);
    std::ofstream out(path, std::ios::binary);
    if (!out)
        throw Error("cannot write PNG '" + path +
                    "': check that its directory exists and is writable");
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out) throw Error("cannot write PNG '" + path + "': write failed (disk full?)");
}

namespace {

void check_encodable(const Image& img, const char* format) {
    if (img.width <= 0 || img.height <= 0 ||
        img.pixels.size() != static_cast<size_t>(img.width) * img.height)
        throw Error(std::string("cannot encode a ") + format + " of an image " +
                    std::to_string(img.width) + "x" + std::to_string(img.height) + " with " +
                    std::to_string(img.pixels.size()) + " pixels");
}

}  // namespace

namespace {

void put_be32(std::string& out, std::uint32_t v) {
    for (int shift = 24; shift >= 0; shift -= 8) out.push_back(static_cast<char>(v >> shift));
}

// A PNG chunk: length, type, data and the CRC of type and data.
void put_chunk(std::string& out, const char* type, const std::string& data) {
    put_be32(out, static_cast<std::uint32_t>(data.size()));
    const size_t from = out.size();
    out.append(type, 4);
    out += data;
    put_be32(out,
             static_cast<std::uint32_t>(libdeflate_crc32(0, out.data() + from, out.size() - from)));
}

// The compressor of this thread at `level`, kept between images.
libdeflate_compressor* compressor(int level) {
    struct Held {
        libdeflate_compressor* c = nullptr;
        int level = -1;
        ~Held() { libdeflate_free_compressor(c); }
    };
    thread_local Held held;
    if (held.level != level) {
        libdeflate_free_compressor(held.c);
        held.c = libdeflate_alloc_compressor(level);
        held.level = held.c ? level : -1;
    }
    return held.c;
}

// The rows of `img` as PNG filters them, top row first (PNG's order; the
// image is stored bottom first), each with the "up" filter, in `channels`
// (4: RGBA, 3: RGB, 1: grey). RGBA rows are filtered where they lie; grey and
// RGB ones are packed first, into two buffers that take turns.
std::vector<std::uint8_t> up_filtered_rows(const Image& img, int channels) {
    const int w = img.width, h = img.height;
    const size_t row = static_cast<size_t>(w) * channels;
    std::vector<std::uint8_t> filtered((row + 1) * h);
    const std::vector<std::uint8_t> zeros(row, 0);
    std::vector<std::uint8_t> packed[2];
    if (channels != 4) packed[0].resize(row), packed[1].resize(row);
    const std::uint8_t* above = zeros.data();
    for (int y = 0; y < h; ++y) {
        const Rgba8* src = &img.at(0, h - 1 - y);
        const std::uint8_t* here = reinterpret_cast<const std::uint8_t*>(src);
        if (channels != 4) {
            std::uint8_t* out = packed[y % 2].data();
            for (int x = 0; x < w; ++x)
                if (channels == 3) {
                    out[3 * x] = src[x].r;
                    out[3 * x + 1] = src[x].g;
                    out[3 * x + 2] = src[x].b;
                } else {
                    out[x] = src[x].r;
                }
            here = out;
        }
        std::uint8_t* out = &filtered[(row + 1) * y];
        out[0] = 2;  // "up": each byte less the one above it
        for (size_t i = 0; i < row; ++i) out[1 + i] = static_cast<std::uint8_t>(here[i] - above[i]);
        above = here;
    }
    return filtered;
}

// `data` as one zlib stream, by libdeflate at `level`.
std::string zlib_stream(const std::vector<std::uint8_t>& data, int level) {
    libdeflate_compressor* c = compressor(level);
    if (!c) throw Error("cannot encode a PNG: out of memory for the compressor");
    std::string stream(libdeflate_zlib_compress_bound(c, data.size()), '\0');
    const size_t size =
        libdeflate_zlib_compress(c, data.data(), data.size(), stream.data(), stream.size());
    if (size == 0) throw Error("cannot encode a PNG: the compressed pixels did not fit");
    stream.resize(size);
    return stream;
}

}  // namespace

// The PNG container written here, its pixels compressed by libdeflate, in
// the smallest colour type that holds every pixel exactly (grey, RGB or
// RGBA), each row with the "up" filter: on the course's frames the fastest
// of the encoders bench/bench_png compares, and the smallest files of the
// fast ones (a difference image is grey, most frames are opaque).
std::string encode_png(const Image& img, int level) {
    check_encodable(img, "PNG");
    unsigned opaque = 1, grey = 1;
    for (const Rgba8& p : img.pixels) {
        opaque &= p.a == 255;
        grey &= (p.r == p.g) & (p.g == p.b);
    }
    const int channels = !opaque ? 4 : grey ? 1 : 3;
    const std::uint8_t color_type = !opaque ? 6 : grey ? 0 : 2;
    const std::string idat = zlib_stream(up_filtered_rows(img, channels), level);
    std::string ihdr;
    put_be32(ihdr, static_cast<std::uint32_t>(img.width));
    put_be32(ihdr, static_cast<std::uint32_t>(img.height));
    // 8 bits a channel, the colour type, deflate, filters per row, no interlace.
    ihdr += {8, static_cast<char>(color_type), 0, 0, 0};
    std::string bytes("\x89PNG\r\n\x1a\n", 8);
    // The stream goes in IDAT chunks of at most 1 MiB: a chunk's length must
    // stay below 2^31, and readers take any split.
    constexpr size_t kIdat = size_t(1) << 20;
    bytes.reserve(8 + 25 + idat.size() + 12 * (idat.size() / kIdat + 2));
    put_chunk(bytes, "IHDR", ihdr);
    for (size_t at = 0; at < idat.size(); at += kIdat)
        put_chunk(bytes, "IDAT", idat.substr(at, kIdat));
    put_chunk(bytes, "IEND", "");
    return bytes;
}

std::string encode_png(const Image& img) { return encode_png(img, kPngLevel); }

// libjpeg-turbo: several times stb_image_write's speed, which `lab serve`
// needs for every frame it sends.
std::string encode_jpeg(const Image& img, int quality) {
    check_encodable(img, "JPEG");
    const std::unique_ptr<void, int (*)(tjhandle)> tj(tjInitCompress(), tjDestroy);
    if (!tj) throw Error("cannot encode a JPEG: libjpeg-turbo did not start");
    unsigned char* data = nullptr;
    unsigned long size = 0;
    // Rows are stored bottom first (GL's order): TJFLAG_BOTTOMUP reads them so.
    const int failed =
        tjCompress2(tj.get(), reinterpret_cast<const unsigned char*>(img.pixels.data()), img.width,
                    0, img.height, TJPF_RGBA, &data, &size, TJSAMP_420, std::clamp(quality, 1, 100),
                    TJFLAG_BOTTOMUP);
    const std::unique_ptr<unsigned char, void (*)(unsigned char*)> owned(data, tjFree);
    if (failed)
        throw Error("cannot encode a JPEG of " + std::to_string(img.width) + "x" +
                    std::to_string(img.height) + " pixels: " + tjGetErrorStr2(tj.get()));
    return std::string(reinterpret_cast<const char*>(data), size);
}

Image shrink(const Image& img, int max_side, bool brightest) {
    const int longest = std::max(img.width, img.height);
    if (max_side <= 0 || longest <= max_side) return img;
    const int w = std::max(1, img.width * max_side / longest);
    const int h = std::max(1, img.height * max_side / longest);
    Image out(w, h);
    // Output pixel (x, y) covers source pixels x * width / w up to (x + 1) *
    // width / w; every source pixel that part of it falls in counts.
    for (int y = 0; y < h; ++y) {
        const int y0 = y * img.height / h, y1 = ((y + 1) * img.height + h - 1) / h;
        for (int x = 0; x < w; ++x) {
            const int x0 = x * img.width / w, x1 = ((x + 1) * img.width + w - 1) / w;
            unsigned sum[4] = {0, 0, 0, 0};
            for (int sy = y0; sy < y1; ++sy)
                for (int sx = x0; sx < x1; ++sx) {
                    const Rgba8 p = img.at(sx, sy);
                    const unsigned v[4] = {p.r, p.g, p.b, p.a};
                    for (int c = 0; c < 4; ++c)
                        sum[c] = brightest ? std::max(sum[c], v[c]) : sum[c] + v[c];
                }
            const unsigned n = brightest ? 1u : static_cast<unsigned>((y1 - y0) * (x1 - x0));
            out.at(x, y) = {static_cast<std::uint8_t>((sum[0] + n / 2) / n),
                            static_cast<std::uint8_t>((sum[1] + n / 2) / n),
                            static_cast<std::uint8_t>((sum[2] + n / 2) / n),
                            static_cast<std::uint8_t>((sum[3] + n / 2) / n)};
        }
    }
    return out;
}

Image read_png(const std::string& path) { return decode_png(read_file(path, "PNG"), path); }

bool png_header_size(const std::string& bytes, int& width, int& height) {
    static const char signature[] = "\x89PNG\r\n\x1a\n";
    if (bytes.size() < 24 || bytes.compare(0, 8, signature, 8) != 0) return false;
    auto be32 = [&](size_t at) {
        std::uint32_t v = 0;
        for (size_t i = 0; i < 4; ++i) v = (v << 8) | static_cast<unsigned char>(bytes[at + i]);
        return v;
    };
    // A PNG's sizes are below 2^31; larger values are not a PNG's.
    const std::uint32_t w = be32(16), h = be32(20);
    if (w > 0x7fffffffu || h > 0x7fffffffu) return false;
    width = static_cast<int>(w);
    height = static_cast<int>(h);
    return true;
}

// ---- PFM -------------------------------------------------------------------

std::string encode_pfm(const DepthImage& img) {
    if (img.values.size() != static_cast<size_t>(img.width) * img.height)
        throw Error("cannot encode a PFM of " + std::to_string(img.width) + "x" +
                    std::to_string(img.height) + " depth values: the image has " +
                    std::to_string(img.values.size()));
    // Scale -1.0: the minus sign means little endian (x86 and ARM order, as stored).
    std::string bytes =
        "Pf\n" + std::to_string(img.width) + " " + std::to_string(img.height) + "\n-1.0\n";
    const size_t header = bytes.size(), size = img.values.size() * sizeof(float);
    bytes.resize(header + size);
    std::memcpy(&bytes[header], img.values.data(), size);
    return bytes;
}

void write_pfm(const std::string& path, const DepthImage& img) {
    if (img.values.size() != static_cast<size_t>(img.width) * img.height)
        throw Error("cannot write PFM '" + path + "': image has the wrong number of values");
    std::ofstream out(path, std::ios::binary);
    if (!out)
        throw Error("cannot write PFM '" + path +
                    "': check that its directory exists and is writable");
    const std::string bytes = encode_pfm(img);
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    if (!out) throw Error("cannot write PFM '" + path + "': write failed (disk full?)");
}

DepthImage read_pfm(const std::string& path) { return decode_pfm(read_file(path, "PFM"), path); }

DepthImage decode_pfm(std::string bytes, const std::string& name) {
    auto fail = [&](const std::string& why) {
        return Error("cannot read PFM '" + name + "': " + why);
    };
    if (bytes.compare(0, 2, "PF") == 0)
        throw fail("it is a colour (PF) file; only single-channel depth (Pf) is supported");
    if (bytes.compare(0, 2, "Pf") != 0) throw fail("not a PFM file (no 'Pf' header)");

    // Three whitespace-separated tokens after "Pf", then exactly one whitespace byte.
    size_t pos = 2;
    auto token = [&]() {
        while (pos < bytes.size() && std::isspace(static_cast<unsigned char>(bytes[pos]))) ++pos;
        size_t start = pos;
        while (pos < bytes.size() && !std::isspace(static_cast<unsigned char>(bytes[pos]))) ++pos;
        return bytes.substr(start, pos - start);
    };
    std::string ws = token(), hs = token(), ss = token();
    char* end = nullptr;
    long w = std::strtol(ws.c_str(), &end, 10);
    bool ok = !ws.empty() && *end == '\0';
    long h = std::strtol(hs.c_str(), &end, 10);
    ok = ok && !hs.empty() && *end == '\0';
    double scale = std::strtod(ss.c_str(), &end);
    ok = ok && !ss.empty() && *end == '\0' && scale != 0.0 && pos < bytes.size();
    if (!ok || w < 0 || h < 0 || w > 65536 || h > 65536)
        throw fail("malformed header; expected \"Pf\\n<width> <height>\\n-1.0\\n\"");
    ++pos;  // the single whitespace byte that ends the header

    size_t need = static_cast<size_t>(w) * h * sizeof(float);
    if (bytes.size() - pos < need)
        throw fail("truncated: " + std::to_string(w) + "x" + std::to_string(h) + " needs " +
                   std::to_string(need) + " bytes of data, file has " +
                   std::to_string(bytes.size() - pos));
    // A positive scale means big-endian floats: reverse each 4-byte group.
    if (scale > 0)
        for (size_t i = pos; i < pos + need; i += 4) {
            std::swap(bytes[i], bytes[i + 3]);
            std::swap(bytes[i + 1], bytes[i + 2]);
        }
    DepthImage img(static_cast<int>(w), static_cast<int>(h));
    std::memcpy(img.values.data(), bytes.data() + pos, need);
    return img;
}

}  // namespace fw
