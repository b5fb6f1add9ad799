// The checks the PrairieLearn tests share (prairielearn_support.hpp).
#include "tests/grading/prairielearn_support.hpp"

#include <set>

#include "tests/grading/report_fixture.hpp"
#include "tests/support/test_support.hpp"

namespace prairielearn_test {

namespace {

unsigned byte(const std::string& bytes, size_t i) {
    return i < bytes.size() ? static_cast<unsigned char>(bytes[i]) : 0u;
}

unsigned big_endian16(const std::string& bytes, size_t i) {
    return byte(bytes, i) << 8 | byte(bytes, i + 1);
}

// JPEG: markers FF xx, each segment but SOI and EOI with a 16-bit length;
// the size is in the start-of-frame segment (SOF0..SOF15 less DHT, JPG, DAC).
bool jpeg_size(const std::string& bytes, int& width, int& height) {
    if (byte(bytes, 0) != 0xFF || byte(bytes, 1) != 0xD8) return false;
    for (size_t at = 2; at + 9 < bytes.size();) {
        if (byte(bytes, at) != 0xFF) return false;
        const unsigned marker = byte(bytes, at + 1);
        if (marker >= 0xC0 && marker <= 0xCF && marker != 0xC4 && marker != 0xC8 &&
            marker != 0xCC) {
            height = static_cast<int>(big_endian16(bytes, at + 5));
            width = static_cast<int>(big_endian16(bytes, at + 7));
            return true;
        }
        at += 2 + big_endian16(bytes, at + 2);
    }
    return false;
}

bool png_size(const std::string& bytes, int& width, int& height) {
    const std::string signature = "\x89PNG\r\n\x1a\n";
    if (bytes.size() < 24 || bytes.compare(0, signature.size(), signature) != 0 ||
        bytes.compare(12, 4, "IHDR") != 0)
        return false;
    width = static_cast<int>(big_endian16(bytes, 16) << 16 | big_endian16(bytes, 18));
    height = static_cast<int>(big_endian16(bytes, 20) << 16 | big_endian16(bytes, 22));
    return true;
}

// The names of an object's fields, in any order.
using Keys = std::set<std::string>;
Keys keys(const json& object) {
    Keys out;
    for (auto it = object.begin(); it != object.end(); ++it) out.insert(it.key());
    return out;
}

std::vector<Picture> check_images(const json& images, const std::string& test) {
    std::vector<Picture> pictures;
    REQUIRE_MESSAGE(images.is_array(), test << ": images is not an array");
    const std::set<std::string> labels{"rendered", "expected", "difference"};
    for (const json& image : images) {
        REQUIRE_MESSAGE(image.is_object(), test << ": an image is not an object");
        CHECK(keys(image) == Keys{"label", "url"});
        Picture p;
        p.label = image.value("label", "");
        CHECK_MESSAGE(labels.count(p.label) == 1, test << ": image label " << p.label);
        const std::string url = image.value("url", "");
        for (const char* type : {"png", "jpeg"}) {
            const std::string prefix = std::string("data:image/") + type + ";base64,";
            if (url.rfind(prefix, 0) == 0) {
                p.type = type;
                p.bytes = report_fixture::base64_decode(url.substr(prefix.size()));
            }
        }
        REQUIRE_MESSAGE(!p.type.empty(),
                        test << ": not a PNG or JPEG data URL: " << url.substr(0, 40));
        int w = 0, h = 0;
        CHECK_MESSAGE(image_size(p.bytes, w, h), test << ": the " << p.type << " does not decode");
        CHECK_MESSAGE((w >= 1 && h >= 1 && w <= 160 && h <= 160),
                      test << ": " << p.label << " is " << w << " x " << h);
        pictures.push_back(std::move(p));
    }
    return pictures;
}

}  // namespace

bool image_size(const std::string& bytes, int& width, int& height) {
    return png_size(bytes, width, height) || jpeg_size(bytes, width, height);
}

std::vector<Picture> check_schema(const json& results) {
    REQUIRE_MESSAGE(results.is_object(), "results.json is not a JSON object");
    REQUIRE(results.contains("gradable"));
    REQUIRE(results["gradable"].is_boolean());
    const bool gradable = results["gradable"].get<bool>();
    CHECK(keys(results) ==
          (gradable ? Keys{"gradable", "score", "message", "output", "tests"}
                    : Keys{"gradable", "score", "message", "output", "format_errors", "tests"}));
    REQUIRE(results["score"].is_number());
    REQUIRE(results["message"].is_string());
    REQUIRE(results["output"].is_string());
    REQUIRE(results["tests"].is_array());
    const double score = results["score"].get<double>();
    CHECK(score >= 0.0);
    CHECK(score <= 1.0);
    if (!gradable) {
        CHECK(score == 0.0);
        REQUIRE(results["format_errors"].is_array());
        CHECK(!results["format_errors"].empty());
        for (const json& e : results["format_errors"]) CHECK((e.is_string() && !e.empty()));
        CHECK(results["tests"].empty());
        return {};
    }
    std::vector<Picture> pictures;
    double points = 0, max_points = 0;
    for (const json& t : results["tests"]) {
        REQUIRE(t.is_object());
        CHECK(keys(t) ==
              Keys{"name", "description", "points", "max_points", "message", "output", "images"});
        const std::string name = t.value("name", "");
        CHECK(!name.empty());
        for (const char* field : {"name", "description", "message", "output"})
            CHECK_MESSAGE(t[field].is_string(), name << ": " << field << " is not a string");
        REQUIRE_MESSAGE((t["points"].is_number() && t["max_points"].is_number()),
                        name << ": points and max_points are not numbers");
        const double p = t["points"].get<double>(), max = t["max_points"].get<double>();
        CHECK_MESSAGE((p >= 0 && p <= max), name << ": " << p << " of " << max << " points");
        points += p;
        max_points += max;
        for (Picture& picture : check_images(t["images"], name)) pictures.push_back(picture);
    }
    if (max_points > 0) CHECK(score == doctest::Approx(points / max_points));
    return pictures;
}

}  // namespace prairielearn_test
