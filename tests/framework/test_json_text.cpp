// fw::append_json (framework/json_glm.hpp): the unit results' JSON text,
// read back as the value dump() would have given, number for number and
// type for type. No GL.
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>

#include "framework/json_glm.hpp"
#include "tests/support/test_support.hpp"

namespace {

using nlohmann::json;

std::string text_of(const json& value) {
    std::string out = "<";
    fw::append_json(out, value);
    return out.substr(1);  // appended, not assigned
}

// Read back, `value` is the same JSON as dump()'s text reads back as: the
// same numbers to the bit, floats still floats, integers still integers.
void check_same(const json& value) {
    const std::string text = text_of(value);
    CAPTURE(text);
    const json ours = json::parse(text), theirs = json::parse(value.dump());
    CHECK(ours == theirs);
    CHECK(ours.dump() == theirs.dump());  // the types too: 1.0 is not 1
}

}  // namespace

TEST_CASE("append_json: numbers read back bit for bit, floats as floats") {
    const double values[] = {0.0,
                             -0.0,
                             1.0,
                             -3.0,
                             100000.0,
                             1e15,
                             1e16,
                             1e300,
                             -1e-300,
                             0.1,
                             static_cast<double>(0.1f),
                             static_cast<double>(1.0f / 3.0f),
                             5e-324,
                             std::numeric_limits<double>::max(),
                             std::numeric_limits<double>::lowest(),
                             123456.789e-20};
    for (const double v : values) {
        const json j = v;
        check_same(j);
        const json back = json::parse(text_of(j));
        CHECK(back.is_number_float());
        CHECK(std::signbit(back.get<double>()) == std::signbit(v));
    }
    // Random floats as a lab's unit results hold them (float, then double).
    std::mt19937 rng(7);
    std::uniform_real_distribution<float> spread(-1000.0f, 1000.0f);
    std::uniform_int_distribution<int> exponent(-30, 30);
    for (int i = 0; i < 2000; ++i) {
        const float f = std::ldexp(spread(rng), exponent(rng));
        const json j = static_cast<double>(f);
        CAPTURE(f);
        CHECK(json::parse(text_of(j)).get<double>() == static_cast<double>(f));
    }
}

TEST_CASE("append_json: what is not a finite float is written as dump() writes it") {
    CHECK(text_of(std::numeric_limits<double>::infinity()) == "null");
    CHECK(text_of(std::nan("")) == "null");
    CHECK(text_of(json(nullptr)) == "null");
    CHECK(text_of(true) == "true");
    CHECK(text_of(std::int64_t{-42}) == "-42");
    CHECK(text_of(std::numeric_limits<std::uint64_t>::max()) == "18446744073709551615");
    CHECK(text_of("a \"quote\"\n\u00e9") == json("a \"quote\"\n\u00e9").dump());
    const json nested =
        json::parse(R"({"model": [[1.0, 0.0], [0.5, -2.25]], "names": ["a\\b", "c"], "n": 3,)"
                    R"( "empty": {}, "none": [], "deep": {"x": [1e-7, true, null]}})");
    check_same(nested);
    CHECK(text_of(nested) == nested.dump());  // dump's own digits, here
}
