// Image files (PNG, PAM, PFM) and the fuzzy comparison behind the `image` check.
#include <stb/stb_image.h>
#include <stb/stb_image_write.h>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "framework/error.hpp"
#include "framework/image.hpp"
#include "tests/support/test_support.hpp"

using fw::Image;
using fw::Rgba8;

namespace {

const Rgba8 kBlack{0, 0, 0, 255};
const Rgba8 kRed{255, 0, 0, 255};
const Rgba8 kWhite{255, 255, 255, 255};

// A black w x h image with a filled rectangle [x0, x1) x [y0, y1).
Image rect_image(int w, int h, int x0, int y0, int x1, int y1, Rgba8 colour = kRed) {
    Image img(w, h, kBlack);
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x) img.at(x, y) = colour;
    return img;
}

void write_bytes(const std::string& path, const std::string& bytes) {
    std::ofstream(path, std::ios::binary) << bytes;
}

std::string read_bytes(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), {});
}

// The message of the fw::Error that `f` throws, or "" when it throws none.
template <class F>
std::string error_of(F f) {
    try {
        f();
    } catch (const fw::Error& e) {
        return e.what();
    }
    return "";
}

}  // namespace

TEST_CASE("PNG round trip is pixel exact and stores the bottom row last") {
    Image img(3, 2);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 3; ++x)
            img.at(x, y) = {std::uint8_t(40 * x), std::uint8_t(100 * y), 7, std::uint8_t(200 + x)};
    img.at(1, 0) = {11, 22, 33, 44};  // bottom row in GL terms
    std::string path = fw::test::out_dir() + "/round_trip.png";
    fw::write_png(path, img);

    Image back = fw::read_png(path);
    REQUIRE(back.width == 3);
    REQUIRE(back.height == 2);
    CHECK(back.pixels == img.pixels);

    // Decoded independently: PNG row H-1 (the last one) holds GL row 0.
    int w = 0, h = 0, n = 0;
    unsigned char* raw = stbi_load(path.c_str(), &w, &h, &n, 4);
    REQUIRE(raw != nullptr);
    const unsigned char* p = raw + ((h - 1) * w + 1) * 4;
    CHECK(p[0] == 11);
    CHECK(p[1] == 22);
    CHECK(p[2] == 33);
    CHECK(p[3] == 44);
    stbi_image_free(raw);
}

TEST_CASE("PNG: a whole frame of noise and gradients round trips exactly") {
    // Every filter and both of zlib's block kinds get used on such a frame.
    Image img(512, 384);
    unsigned seed = 12345;
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x) {
            seed = seed * 1103515245u + 12345u;
            const bool noisy = (x / 64 + y / 64) % 2 == 0;
            img.at(x, y) = {std::uint8_t(noisy ? seed >> 24 : x / 2), std::uint8_t(y / 2),
                            std::uint8_t(noisy ? seed >> 16 : 128), std::uint8_t(noisy ? 255 : x)};
        }
    const std::string bytes = fw::encode_png(img);
    int w = 0, h = 0;
    REQUIRE(fw::png_header_size(bytes, w, h));
    CHECK(w == 512);
    CHECK(h == 384);
    const Image back = fw::decode_png(bytes, "noise");
    CHECK(back.pixels == img.pixels);
}

TEST_CASE("PNG: a frame of pure noise spans several IDAT chunks and round trips exactly") {
    Image img(1024, 1024);
    unsigned seed = 987654321u;
    for (Rgba8& p : img.pixels) {
        seed = seed * 1664525u + 1013904223u;
        p = {std::uint8_t(seed >> 24), std::uint8_t(seed >> 16), std::uint8_t(seed >> 8),
             std::uint8_t(seed >> 1)};
    }
    const std::string png = fw::encode_png(img);
    int chunks = 0;
    for (size_t at = png.find("IDAT"); at != std::string::npos; at = png.find("IDAT", at + 4))
        ++chunks;
    CHECK(chunks >= 4);  // 4 MiB that do not compress, in chunks of at most 1 MiB
    CHECK(fw::decode_png(png, "noise").pixels == img.pixels);
}

TEST_CASE("PNG: the colour type is the smallest that keeps every pixel, and each round trips") {
    // IHDR's colour type is byte 25 of the file: 0 grey, 2 RGB, 6 RGBA.
    auto colour_type = [](const std::string& png) { return static_cast<int>(png.at(25)); };
    Image grey(40, 30);
    for (int y = 0; y < grey.height; ++y)
        for (int x = 0; x < grey.width; ++x) {
            const auto v = std::uint8_t(x * 6 + y);
            grey.at(x, y) = {v, v, v, 255};
        }
    Image rgb = grey;
    rgb.at(39, 29) = {1, 2, 3, 255};  // one pixel that is not grey
    Image rgba = rgb;
    rgba.at(0, 0).a = 254;  // one pixel that is not opaque
    Image grey_alpha = grey;
    grey_alpha.at(5, 5).a = 0;  // grey, but not opaque: RGBA keeps it
    const struct {
        const char* name;
        const Image& image;
        int type;
    } cases[] = {
        {"grey", grey, 0}, {"rgb", rgb, 2}, {"rgba", rgba, 6}, {"grey_alpha", grey_alpha, 6}};
    for (const auto& c : cases) {
        CAPTURE(c.name);
        const std::string png = fw::encode_png(c.image);
        CHECK(colour_type(png) == c.type);
        CHECK(fw::decode_png(png, c.name).pixels == c.image.pixels);
        // And by stb_image directly, top row first.
        int w = 0, h = 0, n = 0;
        unsigned char* raw =
            stbi_load_from_memory(reinterpret_cast<const unsigned char*>(png.data()),
                                  static_cast<int>(png.size()), &w, &h, &n, 4);
        REQUIRE(raw != nullptr);
        CHECK(std::memcmp(raw, &c.image.at(0, c.image.height - 1), 4) == 0);
        stbi_image_free(raw);
    }
}

TEST_CASE("PAM round trip is exact, top row first, with the header of docs/contract.md") {
    Image img(3, 2);
    for (int y = 0; y < 2; ++y)
        for (int x = 0; x < 3; ++x) img.at(x, y) = {std::uint8_t(x), std::uint8_t(y), 9, 255};
    img.at(2, 1) = {11, 22, 33, 44};  // the top row's last pixel
    const std::string bytes = fw::encode_pam(img);
    const std::string header =
        "P7\nWIDTH 3\nHEIGHT 2\nDEPTH 4\nMAXVAL 255\nTUPLTYPE RGB_ALPHA\nENDHDR\n";
    REQUIRE(bytes.size() == header.size() + 3 * 2 * 4);
    CHECK(bytes.compare(0, header.size(), header) == 0);
    // The first row in the file is the top one: its third pixel is (11, 22, 33, 44).
    CHECK(bytes.substr(header.size() + 8, 4) == "\x0b\x16\x21\x2c");
    CHECK(fw::decode_pam(bytes, "t.pam").pixels == img.pixels);
    int w = 0, h = 0;
    CHECK(fw::pam_header_size(bytes, w, h));
    CHECK(w == 3);
    CHECK(h == 2);
    const std::string path = fw::test::out_dir() + "/t.pam";
    fw::write_pam(path, img);
    CHECK(fw::test::read_text(path) == bytes);
}

TEST_CASE("write_pam writes encode_pam's bytes, row by row from a tall frame") {
    // 2500 rows, each of its own colour, so that a row out of place shows.
    Image img(3, 2500);
    for (int y = 0; y < img.height; ++y)
        for (int x = 0; x < img.width; ++x)
            img.at(x, y) = {std::uint8_t(x), std::uint8_t(y), std::uint8_t(y >> 8), 255};
    const std::string path = fw::test::out_dir() + "/tall.pam";
    fw::write_pam(path, img);
    const std::string bytes = fw::test::read_text(path);
    CHECK(bytes == fw::encode_pam(img));
    CHECK(fw::decode_pam(bytes, "tall.pam").pixels == img.pixels);
    // A path that cannot be written is named, with the reason.
    const std::string bad = fw::test::out_dir() + "/no-such-dir/t.pam";
    const std::string message = fw::test::thrown([&] { fw::write_pam(bad, img); });
    CHECK(message.find(bad) != std::string::npos);
    CHECK(message.find("No such file or directory") != std::string::npos);
}

TEST_CASE("decode_pam refuses anything but the exact header and size, naming the file") {
    const std::string good = fw::encode_pam(Image(2, 2, kRed));
    const std::string pixels = good.substr(good.size() - 16);
    auto header = [](const std::string& lines) { return "P7\n" + lines + "ENDHDR\n"; };
    const std::string fields = "DEPTH 4\nMAXVAL 255\nTUPLTYPE RGB_ALPHA\n";
    const struct {
        std::string bytes, why;
    } bad[] = {
        {"P6\n2 2\n255\n" + pixels, "not a PAM file"},
        {header("WIDTH 2\nHEIGHT 2\n" + fields) + pixels + "x",
         "needs 16 bytes of pixels; the file has 17"},
        {header("WIDTH 2\nHEIGHT 2\n" + fields) + pixels.substr(1), "the file has 15"},
        {header("WIDTH 2\nHEIGHT 2\nWIDTH 2\n" + fields) + pixels, "WIDTH given twice"},
        {header("WIDTH 2\n" + fields) + pixels, "needs WIDTH, HEIGHT"},
        {header("WIDTH 0\nHEIGHT 2\n" + fields), "WIDTH \"0\" is not a size"},
        {header("WIDTH 70000\nHEIGHT 2\n" + fields), "70000x2 is over the limit of 65536"},
        {header("WIDTH -2\nHEIGHT 2\n" + fields), "WIDTH \"-2\" is not a size"},
        {header("WIDTH 2\nHEIGHT 2\nDEPTH 3\nMAXVAL 255\nTUPLTYPE RGB\n") + pixels,
         "only 8-bit RGB_ALPHA"},
        {header("WIDTH 2\nHEIGHT 2\n# a comment\n" + fields) + pixels, "unexpected header line"},
        {"P7\nWIDTH 2\nHEIGHT 2\n" + fields + std::string(600, 'x'), "without an ENDHDR"},
    };
    for (const auto& b : bad) {
        CAPTURE(b.why);
        const std::string message = fw::test::thrown([&] { fw::decode_pam(b.bytes, "frame.pam"); });
        CHECK(message.find("'frame.pam'") != std::string::npos);
        CHECK(message.find(b.why) != std::string::npos);
    }
    int w = 0, h = 0;
    CHECK_FALSE(fw::pam_header_size("garbage", w, h));
    CHECK_FALSE(fw::pam_header_size(bad[5].bytes, w, h));
}

TEST_CASE("read_png converts grey and RGB files to RGBA") {
    // Written with stb directly, top row first: 1 and 3 channels per pixel.
    const unsigned char grey[] = {10, 20, 30, 40};   // 2 x 2
    const unsigned char rgb[] = {1, 2, 3, 4, 5, 6};  // 2 x 1
    std::string grey_path = fw::test::out_dir() + "/grey.png";
    std::string rgb_path = fw::test::out_dir() + "/rgb.png";
    REQUIRE(stbi_write_png(grey_path.c_str(), 2, 2, 1, grey, 2));
    REQUIRE(stbi_write_png(rgb_path.c_str(), 2, 1, 3, rgb, 6));

    Image g = fw::read_png(grey_path);
    REQUIRE(g.width == 2);
    CHECK(g.at(0, 1) == Rgba8{10, 10, 10, 255});  // the file's top row is GL row 1
    CHECK(g.at(1, 0) == Rgba8{40, 40, 40, 255});
    Image c = fw::read_png(rgb_path);
    CHECK(c.at(1, 0) == Rgba8{4, 5, 6, 255});
}

TEST_CASE("png_header_size reads the size without decoding, and refuses what is not a PNG") {
    const std::string path = fw::test::out_dir() + "/size.png";
    fw::write_png(path, fw::Image(37, 11, {1, 2, 3, 255}));
    const std::string bytes = fw::test::read_text(path);
    int w = 0, h = 0;
    REQUIRE(fw::png_header_size(bytes, w, h));
    CHECK(w == 37);
    CHECK(h == 11);
    CHECK_FALSE(fw::png_header_size(bytes.substr(0, 20), w, h));
    CHECK_FALSE(fw::png_header_size("GIF89a and then some more bytes", w, h));
    std::string huge = bytes;
    huge[16] = '\xff';  // a width of 2^32 - x: no PNG's
    CHECK_FALSE(fw::png_header_size(huge, w, h));
}

TEST_CASE("PNG reading: each filter, colour type and size reads as stb_image reads it") {
    // stb_image_write's files, one filter forced on every row (or its own
    // choice per row, -1), over noise and gradients in 1 to 4 channels.
    const int sizes[][2] = {{1, 1}, {37, 11}, {64, 48}};
    unsigned seed = 7;
    int files = 0;
    for (const auto& size : sizes)
        for (int channels = 1; channels <= 4; ++channels) {
            const int w = size[0], h = size[1];
            std::vector<unsigned char> top_first(size_t(w) * h * channels);
            for (size_t i = 0; i < top_first.size(); ++i) {
                seed = seed * 1103515245u + 12345u;
                top_first[i] = static_cast<unsigned char>(i % 3 ? (seed >> 16) : i * 7 / 5);
            }
            for (int filter = -1; filter <= 4; ++filter) {
                stbi_write_force_png_filter = filter;
                std::string bytes;
                REQUIRE(stbi_write_png_to_func(
                    [](void* to, void* data, int n) {
                        static_cast<std::string*>(to)->append(static_cast<char*>(data), size_t(n));
                    },
                    &bytes, w, h, channels, top_first.data(), w * channels));
                int sw = 0, sh = 0, sc = 0;
                stbi_uc* want =
                    stbi_load_from_memory(reinterpret_cast<const stbi_uc*>(bytes.data()),
                                          static_cast<int>(bytes.size()), &sw, &sh, &sc, 4);
                REQUIRE(want);
                Image direct;
                const bool taken = fw::decode_plain_png(bytes, direct);
                CHECK_MESSAGE(taken, channels << " channels, filter " << filter);
                const Image read = fw::decode_png(bytes, "noise.png");
                for (const Image* img : {static_cast<const Image*>(&direct), &read}) {
                    REQUIRE(img->width == w);
                    REQUIRE(img->height == h);
                    bool same = true;
                    for (int y = 0; y < h; ++y)  // stb's rows are top first, ours bottom first
                        same &= std::memcmp(&img->at(0, h - 1 - y), want + size_t(y) * w * 4,
                                            size_t(w) * 4) == 0;
                    CHECK_MESSAGE(
                        same, w << "x" << h << ", " << channels << " channels, filter " << filter);
                }
                stbi_image_free(want);
                ++files;
            }
        }
    stbi_write_force_png_filter = -1;
    CHECK(files == 72);
    // Course's own files take the same path.
    const Image frame = rect_image(40, 30, 5, 6, 20, 25, {10, 200, 30, 128});
    Image back;
    REQUIRE(fw::decode_plain_png(fw::encode_png(frame), back));
    CHECK(back.pixels == frame.pixels);
}

TEST_CASE("PNG reading: a damaged or unusual file goes to stb_image, whose words say why") {
    std::string bytes = fw::encode_png(rect_image(64, 64, 1, 2, 50, 60));
    Image img;
    REQUIRE(fw::decode_plain_png(bytes, img));
    // Interlaced (IHDR's last byte; its CRC is not checked by either reader):
    // the direct path leaves it to stb_image, which reads the stream as Adam7
    // and so finds it wrong.
    std::string interlaced = bytes;
    interlaced[8 + 8 + 12] = 1;
    CHECK_FALSE(fw::decode_plain_png(interlaced, img));
    CHECK_THROWS_AS(fw::decode_png(interlaced, "i.png"), fw::Error);
    // Cut short inside its pixels.
    const std::string cut = bytes.substr(0, bytes.size() / 2);
    CHECK_FALSE(fw::decode_plain_png(cut, img));
    const std::string why = error_of([&] { fw::decode_png(cut, "cut.png"); });
    CHECK(why.find("cannot read PNG 'cut.png': ") == 0);
    // A byte of the compressed pixels changed: the stream's checksum fails.
    std::string garbled = bytes;
    garbled[bytes.size() - 30] ^= 0x5a;
    CHECK_FALSE(fw::decode_plain_png(garbled, img));
}

TEST_CASE("PNG errors name the path") {
    std::string missing = fw::test::out_dir() + "/no_such.png";
    std::string msg = error_of([&] { fw::read_png(missing); });
    CHECK(msg.find(missing) != std::string::npos);
    CHECK(msg.find("not found") != std::string::npos);

    std::string bogus = fw::test::out_dir() + "/bogus.png";
    write_bytes(bogus, "this is not a png");
    CHECK(error_of([&] { fw::read_png(bogus); }).find(bogus) != std::string::npos);

    std::string nodir = fw::test::out_dir() + "/no_dir/x.png";
    msg = error_of([&] { fw::write_png(nodir, Image(1, 1)); });
    CHECK(msg.find(nodir) != std::string::npos);
    CHECK(msg.find("directory") != std::string::npos);
}

TEST_CASE("Image rejects negative sizes") {
    CHECK_THROWS_AS(Image(-1, 4), fw::UsageError);
    CHECK_THROWS_AS(fw::DepthImage(4, -1), fw::UsageError);
}

TEST_CASE("PFM round trip is exact and the header matches docs/contract.md") {
    fw::DepthImage d(3, 2);
    const float values[] = {0.0f, 1.0f, 0.5f, 1e-7f, 0.999999f, -3.25f};
    std::memcpy(d.values.data(), values, sizeof values);
    std::string path = fw::test::out_dir() + "/depth.pfm";
    fw::write_pfm(path, d);

    std::string bytes = read_bytes(path);
    const std::string header = "Pf\n3 2\n-1.0\n";
    CHECK(bytes.substr(0, header.size()) == header);
    CHECK(bytes.size() == header.size() + 6 * 4);
    // Little endian, bottom row first: the first float is value (0, 0).
    float first = 0;
    std::memcpy(&first, bytes.data() + header.size(), 4);
    CHECK(first == 0.0f);

    fw::DepthImage back = fw::read_pfm(path);
    REQUIRE(back.width == 3);
    REQUIRE(back.height == 2);
    CHECK(std::memcmp(back.values.data(), values, sizeof values) == 0);
}

TEST_CASE("read_pfm reads big-endian files (positive scale)") {
    // 0.5f is 0x3F000000; 2.0f is 0x40000000; big endian = most significant byte first.
    std::string bytes =
        std::string("Pf\n2 1\n1.0\n") + std::string("\x3F\0\0\0", 4) + std::string("\x40\0\0\0", 4);
    std::string path = fw::test::out_dir() + "/big.pfm";
    write_bytes(path, bytes);
    fw::DepthImage d = fw::read_pfm(path);
    REQUIRE(d.width == 2);
    CHECK(d.at(0, 0) == 0.5f);
    CHECK(d.at(1, 0) == 2.0f);
}

TEST_CASE("PFM errors name the path and the reason") {
    std::string dir = fw::test::out_dir();
    std::string missing = dir + "/no_such.pfm";
    std::string msg = error_of([&] { fw::read_pfm(missing); });
    CHECK(msg.find(missing) != std::string::npos);

    std::string truncated = dir + "/truncated.pfm";
    write_bytes(truncated, "Pf\n4 4\n-1.0\n" + std::string(20, '\0'));
    msg = error_of([&] { fw::read_pfm(truncated); });
    CHECK(msg.find(truncated) != std::string::npos);
    CHECK(msg.find("truncated") != std::string::npos);

    std::string colour = dir + "/colour.pfm";
    write_bytes(colour, "PF\n1 1\n-1.0\n" + std::string(12, '\0'));
    msg = error_of([&] { fw::read_pfm(colour); });
    CHECK(msg.find(colour) != std::string::npos);
    CHECK(msg.find("colour") != std::string::npos);
}

TEST_CASE("compare: identical images pass with no failed pixels") {
    Image a = rect_image(64, 48, 10, 10, 30, 40);
    fw::CompareResult r = fw::compare_images(a, a);
    MESSAGE(r.summary());
    CHECK(r.passed);
    CHECK(r.failed_pixels == 0);
    CHECK(r.total_pixels == 64 * 48);
    CHECK(r.max_channel_error == 0);
    CHECK(r.difference.width == 64);
}

TEST_CASE(
    "compare: a passed pixel's grey is a quarter of its luminance, rounded, for every colour") {
    // The difference image's grey is 0.25 * (0.2126 r + 0.7152 g + 0.0722 b)
    // + 0.5, truncated. Worked out in whole numbers it is exact but for the
    // colours that land half-way, and for those the rounding of the
    // floating-point form decides: every such colour, and every colour where
    // the whole-number form alone would round the other way, is checked here.
    auto grey_of = [](int r, int g, int b) {
        return static_cast<std::uint8_t>(0.25 * (0.2126 * r + 0.7152 * g + 0.0722 * b) + 0.5);
    };
    std::vector<Rgba8> hard;
    for (int r = 0; r < 256; ++r)
        for (int g = 0; g < 256; ++g)
            for (int b = 0; b < 256; ++b) {
                const unsigned n = 2126u * r + 7152u * g + 722u * b + 20000u;
                if (n % 40000u == 0 || n / 40000u != grey_of(r, g, b))
                    hard.push_back({std::uint8_t(r), std::uint8_t(g), std::uint8_t(b), 255});
            }
    CHECK(hard.size() > 800);  // 845 half-way colours on an IEEE double machine
    Image img(static_cast<int>(hard.size()), 1);
    img.pixels = hard;
    const fw::CompareResult c = fw::compare_images(img, img);
    REQUIRE(c.passed);
    for (size_t i = 0; i < hard.size(); ++i) {
        const Rgba8 p = hard[i], d = c.difference.pixels[i];
        CAPTURE(int(p.r));
        CAPTURE(int(p.g));
        CAPTURE(int(p.b));
        const std::uint8_t want = grey_of(p.r, p.g, p.b);
        REQUIRE((d.r == want && d.g == want && d.b == want && d.a == 255));
    }
}

TEST_CASE("compare: a one-pixel edge shift passes, a 10-pixel move fails") {
    Image expected = rect_image(64, 64, 20, 20, 40, 40);
    fw::CompareResult shifted = fw::compare_images(rect_image(64, 64, 21, 19, 41, 39), expected);
    MESSAGE(shifted.summary());
    CHECK(shifted.passed);
    CHECK(shifted.failed_pixels == 0);

    fw::CompareResult moved = fw::compare_images(rect_image(64, 64, 30, 20, 50, 40), expected);
    MESSAGE(moved.summary());
    CHECK_FALSE(moved.passed);
    // Each side of the rectangle fails 198 pixels. On the right the frame's
    // red over black reference fails at x 41..49 (x 40 sees the reference's
    // red at 39), 9 x 20, and the reference's black under the frame's red at
    // x 40..48 (x 49 sees the frame's black at 50), except rows 20 and 39,
    // which see the frame's black rows 19 and 40: of those, x 40 adds 18.
    // The left side is its mirror image: the frame's black over red
    // reference (x 21..29, rows 21..38) and the reference's red with no red
    // of the frame near (x 20..28, every row).
    CHECK(moved.failed_pixels == 2 * (9 * 20 + 18));
    CHECK(moved.difference.at(45, 30) != Rgba8{0, 0, 0, 255});
    CHECK(moved.difference.at(5, 5) == Rgba8{0, 0, 0, 255});
}

namespace {

// A black 64 x 64 image with a one-pixel line from (x0, y0) to (x1, y1)
// (exclusive), horizontal or vertical.
Image line_image(int x0, int y0, int x1, int y1, Rgba8 colour = kWhite) {
    Image img(64, 64, kBlack);
    for (int y = y0; y < std::max(y1, y0 + 1); ++y)
        for (int x = x0; x < std::max(x1, x0 + 1); ++x) img.at(x, y) = colour;
    return img;
}

long failed_in(const fw::CompareResult& r) {
    return std::count(r.failed.begin(), r.failed.end(), std::uint8_t{1});
}

}  // namespace

TEST_CASE("compare: a frame without the reference's one-pixel line fails, one with it added too") {
    // Every black pixel of the frame has a black reference pixel next to it:
    // only the reference's line, looked for among the frame's pixels, finds
    // nothing. 48 pixels of 4096 (1.2%) against the 0.1% limit.
    const Image reference = line_image(8, 32, 56, 32), blank(64, 64, kBlack);
    const fw::CompareResult missing = fw::compare_images(blank, reference);
    MESSAGE(missing.summary());
    CHECK_FALSE(missing.passed);
    CHECK(missing.failed_pixels == 48);
    CHECK(failed_in(missing) == 48);
    CHECK(missing.max_channel_error == 255);
    for (int x = 0; x < 64; ++x) {
        CAPTURE(x);
        CHECK(missing.failed[32 * 64 + x] == (x >= 8 && x < 56));
        CHECK(missing.failed[31 * 64 + x] == 0);
        CHECK(missing.failed[33 * 64 + x] == 0);
    }
    // The difference image marks the line at full error (yellow), the rest grey.
    CHECK(missing.difference.at(20, 32) == Rgba8{255, 255, 0, 255});
    CHECK(missing.difference.at(20, 33) == Rgba8{0, 0, 0, 255});

    // The frame's extra line fails as before, at the same pixels.
    const fw::CompareResult extra = fw::compare_images(reference, blank);
    MESSAGE(extra.summary());
    CHECK_FALSE(extra.passed);
    CHECK(extra.failed_pixels == 48);
    CHECK(extra.max_channel_error == 255);
    CHECK(extra.failed == missing.failed);
    CHECK(extra.difference.at(20, 32) == Rgba8{255, 255, 0, 255});

    // Vertical: the same.
    CHECK(fw::compare_images(blank, line_image(40, 4, 40, 60)).failed_pixels == 56);
    CHECK(fw::compare_images(line_image(40, 4, 40, 60), blank).failed_pixels == 56);
    // Without the difference image, the same verdict.
    fw::CompareOptions no_difference;
    no_difference.difference = false;
    const fw::CompareResult quick = fw::compare_images(blank, reference, no_difference);
    CHECK(quick.failed == missing.failed);
    CHECK(quick.max_channel_error == 255);
}

TEST_CASE("compare: a thin line a pixel off, or a pixel wider, still passes") {
    const Image reference = line_image(8, 32, 56, 32);
    for (const auto& [dx, dy] :
         std::vector<std::pair<int, int>>{{0, 1}, {0, -1}, {1, 1}, {-1, 0}}) {
        CAPTURE(dx);
        CAPTURE(dy);
        const Image shifted = line_image(8 + dx, 32 + dy, 56 + dx, 32 + dy);
        const fw::CompareResult r = fw::compare_images(shifted, reference);
        CHECK(r.passed);
        CHECK(r.failed_pixels == 0);
        CHECK(fw::compare_images(reference, shifted).failed_pixels == 0);
    }
    Image wider = reference;
    for (int x = 8; x < 56; ++x) wider.at(x, 33) = kWhite;
    CHECK(fw::compare_images(wider, reference).failed_pixels == 0);
    CHECK(fw::compare_images(reference, wider).failed_pixels == 0);
    // With radius 0 both fail on the row that differs.
    fw::CompareOptions exact;
    exact.radius = 0;
    CHECK(fw::compare_images(wider, reference, exact).failed_pixels == 48);
    CHECK(fw::compare_images(reference, wider, exact).failed_pixels == 48);
}

TEST_CASE("compare: a pixel failing both ways counts once; the heat is the larger error") {
    // Row 20: the reference's white line drawn red in the frame: each of its
    // pixels fails both ways (no red in the reference near it, no white in
    // the frame near its reference pixel): 48, not 96. Row 40: a line only
    // the frame has, x 8..31: 24 more, one way. Row 50: a line only the
    // reference has, x 8..15: 8 more, the other way.
    Image reference = line_image(8, 20, 56, 20), frame = line_image(8, 20, 56, 20, kRed);
    for (int x = 8; x < 32; ++x) frame.at(x, 40) = kWhite;
    for (int x = 8; x < 16; ++x) reference.at(x, 50) = kWhite;
    const fw::CompareResult r = fw::compare_images(frame, reference);
    MESSAGE(r.summary());
    CHECK(r.failed_pixels == 48 + 24 + 8);
    CHECK(failed_in(r) == r.failed_pixels);
    CHECK(r.failed[20 * 64 + 30] == 1);
    CHECK(r.failed[40 * 64 + 30] == 1);
    CHECK(r.failed[50 * 64 + 10] == 1);
    CHECK(r.failed[50 * 64 + 20] == 0);
    CHECK(r.failed_fraction == doctest::Approx(80.0 / 4096));
    // Swapped, the same positions fail.
    const fw::CompareResult swapped = fw::compare_images(reference, frame);
    CHECK(swapped.failed == r.failed);
    CHECK(swapped.max_channel_error == r.max_channel_error);

    // At (8, 8) the frame's grey 60 is 40 from the reference's grey 100 next
    // to it, but the reference's white there is 195 from every pixel of the
    // frame near it (60 and black): the larger error, 195, is the one shown.
    Image grey_frame(16, 16, kBlack), grey_reference(16, 16, Rgba8{100, 100, 100, 255});
    grey_frame.at(8, 8) = Rgba8{60, 60, 60, 255};
    grey_reference.at(8, 8) = Rgba8{255, 255, 255, 255};
    const fw::CompareResult both = fw::compare_images(grey_frame, grey_reference);
    CHECK(both.max_channel_error == 195);
    // A plain 195 everywhere (60 against 255) gives the heat of 195.
    const fw::CompareResult plain = fw::compare_images(Image(4, 4, Rgba8{60, 60, 60, 255}),
                                                       Image(4, 4, Rgba8{255, 255, 255, 255}));
    REQUIRE(plain.max_channel_error == 195);
    CHECK(both.difference.at(8, 8) == plain.difference.at(1, 1));
    // The frame's error alone (40) would be a dimmer red.
    const fw::CompareResult forty = fw::compare_images(Image(4, 4, Rgba8{60, 60, 60, 255}),
                                                       Image(4, 4, Rgba8{100, 100, 100, 255}));
    REQUIRE(forty.max_channel_error == 40);
    CHECK(both.difference.at(8, 8) != forty.difference.at(1, 1));
}

TEST_CASE("compare: without the difference image, the same verdict to the pixel") {
    // Rows equal to the reference (the memcmp path), rows that differ within
    // the tolerance, and a moved rectangle's rows that fail.
    const Image expected = rect_image(64, 64, 20, 20, 40, 40);
    Image actual = rect_image(64, 64, 30, 20, 50, 40);
    for (int x = 0; x < 64; ++x) actual.at(x, 5).g = 6;
    fw::CompareOptions no_difference;
    no_difference.difference = false;
    const fw::CompareResult with = fw::compare_images(actual, expected);
    const fw::CompareResult without = fw::compare_images(actual, expected, no_difference);
    CHECK(without.difference.pixels.empty());
    CHECK(with.difference.width == 64);
    CHECK(without.passed == with.passed);
    CHECK(without.failed_pixels == with.failed_pixels);
    CHECK(without.failed_pixels == 2 * (9 * 20 + 18));
    CHECK(without.max_channel_error == with.max_channel_error);
    CHECK(without.failed == with.failed);
    CHECK(without.summary() == with.summary());
    // One channel off in one pixel of an otherwise equal row is seen.
    Image one_off = expected;
    one_off.at(63, 63).a = 0;
    const fw::CompareResult single = fw::compare_images(one_off, expected, no_difference);
    CHECK(single.failed_pixels == 1);
    CHECK(single.max_channel_error == 255);
}

TEST_CASE("compare: a recoloured object fails") {
    Image expected = rect_image(64, 64, 20, 20, 40, 40);
    Image actual = rect_image(64, 64, 20, 20, 40, 40, {200, 0, 0, 255});
    fw::CompareResult r = fw::compare_images(actual, expected);
    MESSAGE(r.summary());
    CHECK_FALSE(r.passed);
    CHECK(r.max_channel_error == 55);
}

TEST_CASE("compare: 8/255 on any channel passes, 9/255 fails") {
    Image expected(16, 16, {100, 100, 100, 100});
    for (int channel = 0; channel < 4; ++channel)
        for (int delta : {8, -8, 9, -9}) {
            Image actual = expected;
            for (Rgba8& p : actual.pixels) {
                std::uint8_t* c[] = {&p.r, &p.g, &p.b, &p.a};
                *c[channel] = std::uint8_t(100 + delta);
            }
            fw::CompareResult r = fw::compare_images(actual, expected);
            INFO("channel " << channel << " delta " << delta << ": " << r.summary());
            CHECK(r.passed == (std::abs(delta) <= 8));
            CHECK(r.max_channel_error == std::abs(delta));
        }
}

TEST_CASE("compare: a size mismatch fails and says both sizes") {
    fw::CompareResult r = fw::compare_images(Image(32, 16), Image(16, 32));
    MESSAGE(r.summary());
    CHECK_FALSE(r.passed);
    CHECK(r.size_mismatch);
    CHECK(r.summary().find("32x16") != std::string::npos);
    CHECK(r.summary().find("16x32") != std::string::npos);
    CHECK(r.failed_pixels == 0);
    CHECK(r.failed.empty());
    CHECK(r.difference.pixels.empty());
    // Either way round.
    const fw::CompareResult swapped = fw::compare_images(Image(16, 32), Image(32, 16));
    CHECK(swapped.size_mismatch);
    CHECK_FALSE(swapped.passed);
    CHECK(swapped.summary() == "size mismatch: actual image is 16x32, expected 32x16");
}

TEST_CASE("compare: max_failed_fraction is an inclusive limit") {
    // 100 x 100 pixels at the default 0.1% limit: 10 isolated bad pixels pass, 11 fail.
    Image expected(100, 100, kBlack);
    Image actual = expected;
    for (int i = 0; i < 10; ++i) actual.at(5 + 9 * i, 50) = kRed;
    fw::CompareResult at_limit = fw::compare_images(actual, expected);
    MESSAGE(at_limit.summary());
    CHECK(at_limit.failed_pixels == 10);
    CHECK(at_limit.passed);

    actual.at(50, 90) = kRed;
    fw::CompareResult over = fw::compare_images(actual, expected);
    MESSAGE(over.summary());
    CHECK(over.failed_pixels == 11);
    CHECK_FALSE(over.passed);
    CHECK(over.summary().find("limit 0.1%") != std::string::npos);

    fw::CompareOptions loose;
    loose.max_failed_fraction = 0.0011;
    CHECK(fw::compare_images(actual, expected, loose).passed);
}
