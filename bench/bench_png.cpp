// PNG encoders and decoders on the course's own frames: every blessed
// reference image (labs/*/reference/*.png, the same scenes and sizes as the
// checkpoints), decoded once, then encoded by each candidate, the
// framework's own (fw::encode_png: libdeflate under a container written by
// hand, at several levels) among them. Prints milliseconds per image,
// megapixels per second, the mean size, and each encoder's time as a ratio of
// stb_image_write's (the encoder the framework used first). Every encoding is
// decoded again (by stb_image) and compared with its source, so a fast
// encoder that writes the wrong pixels cannot win. Then the decoders (stb_image
// and libspng) on the files fw::encode_png writes and on libpng's (level 1,
// the same filter and colour types).
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
    fw::Image image;                  // the same, bottom row first (the framework's order)
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

// The smallest colour type that keeps a frame's pixels: 0 grey, 2 RGB, 6 RGBA.
int smallest_colour_type(const Frame& f) {
    unsigned opaque = 1, grey = 1;
    for (size_t i = 0; i < f.rgba.size(); i += 4) {
        opaque &= f.rgba[i + 3] == 255;
        grey &= (f.rgba[i] == f.rgba[i + 1]) & (f.rgba[i + 1] == f.rgba[i + 2]);
    }
    return !opaque ? PNG_COLOR_TYPE_RGBA : grey ? PNG_COLOR_TYPE_GRAY : PNG_COLOR_TYPE_RGB;
}

// What libpng_write needs, set before its setjmp.
struct LibpngJob {
    const unsigned char* rows;  // top row first
    size_t row_bytes;
    int width, height, type, level, filters, strategy;
    std::string* out;
};

// libpng's calls for one image, in a frame of their own: libpng reports an
// error by a longjmp back to the setjmp here, and this frame writes none of
// its variables after it, so none can be clobbered.
bool libpng_write(const LibpngJob& job) {
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    if (setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return false;
    }
    png_set_write_fn(png, job.out, png_append, nullptr);
    png_set_compression_level(png, job.level);
    png_set_compression_strategy(png, job.strategy);
    png_set_filter(png, PNG_FILTER_TYPE_BASE, job.filters);
    png_set_IHDR(png, info, static_cast<png_uint_32>(job.width),
                 static_cast<png_uint_32>(job.height), 8, job.type, PNG_INTERLACE_NONE,
                 PNG_COMPRESSION_TYPE_BASE, PNG_FILTER_TYPE_BASE);
    png_write_info(png, info);
    for (int y = 0; y < job.height; ++y)
        png_write_row(png,
                      const_cast<png_bytep>(job.rows + static_cast<size_t>(y) * job.row_bytes));
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    return true;
}

// libpng writing `f` as colour type `type`; grey and RGB rows are first
// packed to that type's channels (the first 1 or 3 of each pixel).
std::string libpng_encode(const Frame& f, int level, int filters, int strategy = Z_FILTERED,
                          int type = PNG_COLOR_TYPE_RGBA) {
    const size_t channels = type == PNG_COLOR_TYPE_RGBA ? 4 : type == PNG_COLOR_TYPE_RGB ? 3 : 1;
    std::vector<unsigned char> packed;
    if (channels != 4) {
        packed.resize(static_cast<size_t>(f.width) * f.height * channels);
        for (size_t i = 0; i < packed.size() / channels; ++i)
            for (size_t c = 0; c < channels; ++c) packed[i * channels + c] = f.rgba[4 * i + c];
    }
    std::string out;
    const LibpngJob job{channels == 4 ? f.rgba.data() : packed.data(),
                        static_cast<size_t>(f.width) * channels,
                        f.width,
                        f.height,
                        type,
                        level,
                        filters,
                        strategy,
                        &out};
    return libpng_write(job) ? out : std::string();
}

// libspng's decoder, to 8-bit RGBA, top row first.
bool spng_decode(const std::string& png, std::vector<unsigned char>& rgba) {
    spng_ctx* ctx = spng_ctx_new(0);
    size_t size = 0;
    bool ok = spng_set_png_buffer(ctx, png.data(), png.size()) == 0 &&
              spng_decoded_image_size(ctx, SPNG_FMT_RGBA8, &size) == 0;
    if (ok) {
        rgba.resize(size);
        ok = spng_decode_image(ctx, rgba.data(), size, SPNG_FMT_RGBA8, 0) == 0;
    }
    spng_ctx_free(ctx);
    return ok;
}

bool stb_decode(const std::string& png, std::vector<unsigned char>& rgba) {
    int w = 0, h = 0, n = 0;
    unsigned char* data = stbi_load_from_memory(reinterpret_cast<const unsigned char*>(png.data()),
                                                static_cast<int>(png.size()), &w, &h, &n, 4);
    if (!data) return false;
    rgba.assign(data, data + static_cast<size_t>(w) * h * 4);
    stbi_image_free(data);
    return true;
}

// The framework's own reader (decode_png: libdeflate for these files), its
// bottom-first rows copied back top first for the comparison (a memcpy a
// row, in the time measured).
bool fw_decode(const std::string& png, std::vector<unsigned char>& rgba) {
    const fw::Image img = fw::decode_png(png, "frame.png");
    const size_t row = static_cast<size_t>(img.width) * 4;
    rgba.resize(row * img.height);
    for (int y = 0; y < img.height; ++y)
        std::memcpy(&rgba[row * (img.height - 1 - y)], &img.at(0, y), row);
    return true;
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
            Frame frame{file.path().string(),
                        w,
                        h,
                        {data, data + static_cast<size_t>(w) * h * 4},
                        fw::Image(w, h)};
            stbi_image_free(data);
            for (int y = 0; y < h; ++y)
                std::memcpy(&frame.image.at(0, h - 1 - y),
                            frame.rgba.data() + static_cast<size_t>(y) * w * 4,
                            static_cast<size_t>(w) * 4);
            frames.push_back(std::move(frame));
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
        {"libpng + zlib level 1, filter up, smallest colour type",
         [=](const Frame& f) {
             return libpng_encode(f, 1, up, Z_FILTERED, smallest_colour_type(f));
         }},
        {"libpng + zlib level 1, filter up, RLE",
         [=](const Frame& f) { return libpng_encode(f, 1, up, Z_RLE); }},
        {"libspng + zlib level 1, filter up",
         [](const Frame& f) { return spng_encode(f, 1, SPNG_FILTER_CHOICE_UP); }},
        {"libspng + zlib level 1, no filter",
         [](const Frame& f) { return spng_encode(f, 1, SPNG_FILTER_CHOICE_NONE); }},
        {"libspng + zlib level 6, all filters",
         [](const Frame& f) { return spng_encode(f, 6, SPNG_FILTER_CHOICE_ALL); }},
    };
    std::vector<Encoder> all_encoders = encoders;
    for (int level : {1, 2, 3, 4, 6})
        all_encoders.push_back(
            {"fw::encode_png, libdeflate level " + std::to_string(level) +
                 (level == fw::kPngLevel ? " (used)" : ""),
             [level](const Frame& f) { return fw::encode_png(f.image, level); }});

    std::printf("PNG encoders on %zu reference frames (%.1f megapixels), best of %d rounds\n",
                frames.size(), megapixels, rounds);
    std::printf("%-42s %10s %10s %12s %10s\n", "encoder", "ms/image", "MP/s", "mean bytes",
                "vs stb");
    double stb_seconds = 0;
    int failures = 0;
    for (const Encoder& e : all_encoders) {
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

    // The decoders, on the files fw::encode_png writes and on libpng's.
    std::printf("\nPNG decoders (to 8-bit RGBA), best of %d rounds\n", rounds);
    std::printf("%-42s %10s %10s\n", "decoder, files", "ms/image", "MP/s");
    struct Decoder {
        const char* name;
        bool (*decode)(const std::string&, std::vector<unsigned char>&);
    };
    const Decoder decoders[] = {
        {"stb_image", stb_decode}, {"libspng", spng_decode}, {"fw::decode_png", fw_decode}};
    for (const bool ours : {true, false}) {
        std::vector<std::string> files;
        for (const Frame& f : frames)
            files.push_back(
                ours ? fw::encode_png(f.image)
                     : libpng_encode(f, 1, PNG_FILTER_UP, Z_FILTERED, smallest_colour_type(f)));
        for (const Decoder& d : decoders) {
            double best = 1e30;
            std::vector<unsigned char> rgba;
            for (int r = 0; r < rounds; ++r) {
                const auto start = std::chrono::steady_clock::now();
                for (const std::string& png : files) d.decode(png, rgba);
                best = std::min(best, seconds_since(start));
            }
            for (size_t i = 0; i < frames.size(); ++i)
                if (!d.decode(files[i], rgba) || rgba != frames[i].rgba) {
                    std::fprintf(stderr, "bench_png: %s does not decode %s\n", d.name,
                                 frames[i].name.c_str());
                    ++failures;
                    break;
                }
            const std::string name =
                std::string(d.name) + (ours ? ", fw::encode_png's" : ", libpng level 1's");
            std::printf("%-42s %10.2f %10.1f\n", name.c_str(), 1000 * best / frames.size(),
                        megapixels / best);
        }
    }
    return failures ? 1 : 0;
}
