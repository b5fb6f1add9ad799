// PNG encoders on the course's own frames: every blessed reference image
// (labs/*/reference/*.png, the same scenes and sizes as the checkpoints),
// decoded once, then encoded by each candidate. Prints milliseconds per
// image, megapixels per second, the mean size, and each encoder's time as a
// ratio of stb_image_write's (the encoder the framework used first). Every
// encoding is decoded again (by stb_image) and compared with its source, so a
// fast encoder that writes the wrong pixels cannot win.
//
//   build/bin/bench_png [ROUNDS=3]
#include <png.h>
#include <spng.h>
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>
#include <zlib.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <functional>
#include <string>
#include <vector>

#include "framework/image.hpp"

namespace {

struct Frame {
    std::string name;
    int width = 0, height = 0;
    std::vector<unsigned char> rgba;  // top row first, as PNG stores it
};

void append(void* context, void* data, int size) {
    static_cast<std::string*>(context)->append(static_cast<const char*>(data),
                                               static_cast<size_t>(size));
}

std::string stb_encode(const Frame& f, int level) {
    stbi_write_png_compression_level = level;
    std::string out;
    stbi_write_png_to_func(append, &out, f.width, f.height, 4, f.rgba.data(), f.width * 4);
    return out;
}

void png_append(png_structp png, png_bytep data, png_size_t size) {
    static_cast<std::string*>(png_get_io_ptr(png))->append(reinterpret_cast<char*>(data), size);
}

std::string libpng_encode(const Frame& f, int level, int filters, int strategy = Z_FILTERED) {
    std::string out;
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return {};
    }
    png_set_write_fn(png, &out, png_append, nullptr);
    png_set_compression_level(png, level);
    png_set_compression_strategy(png, strategy);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, filters);
    png_set_IHDR(png, info, static_cast<png_uint_32>(f.width), static_cast<png_uint_32>(f.height),
                 8, PNG_COLOR_TYPE_RGBA, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_BASE,
                 PNG_FILTER_TYPE_BASE);
    png_write_info(png, info);
    for (int y = 0; y < f.height; ++y)
        png_write_row(png,
                      const_cast<png_bytep>(f.rgba.data() + static_cast<size_t>(y) * f.width * 4));
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return out;
}

std::string spng_encode(const Frame& f, int level, int filters) {
    spng_ctx* ctx = spng_ctx_new(SPNG_CTX_ENCODER);
    spng_set_option(ctx, SPNG_ENCODE_TO_BUFFER, 1);
    spng_set_option(ctx, SPNG_IMG_COMPRESSION_LEVEL, level);
    spng_set_option(ctx, SPNG_FILTER_CHOICE, filters);
    spng_ihdr ihdr{};
    ihdr.width = static_cast<uint32_t>(f.width);
    ihdr.height = static_cast<uint32_t>(f.height);
    ihdr.bit_depth = 8;
    ihdr.color_type = SPNG_COLOR_TYPE_TRUECOLOR_ALPHA;
    spng_set_ihdr(ctx, &ihdr);
    std::string out;
    if (spng_encode_image(ctx, f.rgba.data(), f.rgba.size(), SPNG_FMT_PNG, SPNG_ENCODE_FINALIZE) ==
        0) {
        size_t size = 0;
        int error = 0;
        void* data = spng_get_png_buffer(ctx, &size, &error);
        if (data) {
            out.assign(static_cast<char*>(data), size);
            std::free(data);
        }
    }
    spng_ctx_free(ctx);
    return out;
}

struct Encoder {
    std::string name;
    std::function<std::string(const Frame&)> encode;
};

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

int main(int argc, char** argv) {
    const int rounds = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
    std::vector<Frame> frames;
    const std::filesystem::path labs = std::filesystem::path(LAB_SOURCE_DIR) / "labs";
    for (const auto& lab : std::filesystem::directory_iterator(labs)) {
        if (!std::filesystem::is_directory(lab.path() / "reference")) continue;
        for (const auto& file : std::filesystem::directory_iterator(lab.path() / "reference")) {
            if (file.path().extension() != ".png") continue;
            int w = 0, h = 0, n = 0;
            unsigned char* data = stbi_load(file.path().c_str(), &w, &h, &n, 4);
            if (!data) continue;
            frames.push_back(
                {file.path().string(), w, h, {data, data + static_cast<size_t>(w) * h * 4}});
            stbi_image_free(data);
        }
    }
    if (frames.empty()) {
        std::fprintf(stderr, "bench_png: no reference images under %s\n", labs.c_str());
        return 2;
    }
    double megapixels = 0;
    for (const Frame& f : frames) megapixels += f.width * f.height / 1e6;

    const int up = PNG_FILTER_UP, none = PNG_FILTER_NONE, all = PNG_ALL_FILTERS;
    const std::vector<Encoder> encoders = {
        {"stb_image_write (level 8, its default)", [](const Frame& f) { return stb_encode(f, 8); }},
        {"stb_image_write level 1", [](const Frame& f) { return stb_encode(f, 1); }},
        {"libpng + zlib level 6, all filters",
         [=](const Frame& f) { return libpng_encode(f, 6, all); }},
        {"libpng + zlib level 1, filter up",
         [=](const Frame& f) { return libpng_encode(f, 1, up); }},
        {"libpng + zlib level 1, no filter",
         [=](const Frame& f) { return libpng_encode(f, 1, none); }},
        {"libpng + zlib level 1, filter up, RLE",
         [=](const Frame& f) { return libpng_encode(f, 1, up, Z_RLE); }},
        {"libspng + zlib level 1, filter up",
         [](const Frame& f) { return spng_encode(f, 1, SPNG_FILTER_CHOICE_UP); }},
        {"libspng + zlib level 1, no filter",
         [](const Frame& f) { return spng_encode(f, 1, SPNG_FILTER_CHOICE_NONE); }},
        {"libspng + zlib level 6, all filters",
         [](const Frame& f) { return spng_encode(f, 6, SPNG_FILTER_CHOICE_ALL); }},
    };

    std::printf("PNG encoders on %zu reference frames (%.1f megapixels), best of %d rounds\n",
                frames.size(), megapixels, rounds);
    std::printf("%-42s %10s %10s %12s %10s\n", "encoder", "ms/image", "MP/s", "mean bytes",
                "vs stb");
    double stb_seconds = 0;
    int failures = 0;
    for (const Encoder& e : encoders) {
        double best = 1e30;
        size_t bytes = 0;
        for (int r = 0; r < rounds; ++r) {
            bytes = 0;
            const auto start = std::chrono::steady_clock::now();
            for (const Frame& f : frames) bytes += e.encode(f).size();
            best = std::min(best, seconds_since(start));
        }
        // Each encoding decodes back to its source.
        for (const Frame& f : frames) {
            const std::string png = e.encode(f);
            int w = 0, h = 0, n = 0;
            unsigned char* back =
                stbi_load_from_memory(reinterpret_cast<const unsigned char*>(png.data()),
                                      static_cast<int>(png.size()), &w, &h, &n, 4);
            const bool same = back && w == f.width && h == f.height &&
                              std::memcmp(back, f.rgba.data(), f.rgba.size()) == 0;
            stbi_image_free(back);
            if (!same) {
                std::fprintf(stderr, "bench_png: %s does not decode back to %s\n", e.name.c_str(),
                             f.name.c_str());
                ++failures;
                break;
            }
        }
        if (stb_seconds == 0) stb_seconds = best;
        std::printf("%-42s %10.2f %10.1f %12zu %10.2f\n", e.name.c_str(),
                    1000 * best / frames.size(), megapixels / best, bytes / frames.size(),
                    best / stb_seconds);
    }
    return failures ? 1 : 0;
}
