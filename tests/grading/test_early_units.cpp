// units.json parsed while the child renders (grading/judge/early_units.hpp):
// judge_lab gets the parse of exactly the bytes it reads, or none, never
// another record's.
#include "grading/judge/early_units.hpp"
#include "tests/support/test_support.hpp"

using nlohmann::json;

TEST_CASE("early units: a units.json record is parsed once, for its own bytes") {
    grading::EarlyUnits early;
    const std::string first = "{\"u0\":{\"result\":[1.5,2]}}\n";
    const std::string second = "{\"u0\":{\"error\":\"thrown\"}}\n";
    early.record_done("/tmp/course-x/0/units.json", first);
    early.record_done("/tmp/course-x/units.json", second);
    early.record_done("/tmp/course-x/0/order.stats.json", "{\"draws\":1}");

    const std::optional<json> got = early.take(second);
    REQUIRE(got.has_value());
    CHECK(*got == json::parse(second));
    CHECK_FALSE(early.take(second).has_value());  // taken once
    CHECK(early.take(first) == std::optional<json>(json::parse(first)));
    // Bytes no units.json record had: no parse, judge_lab parses them itself.
    CHECK_FALSE(early.take("{\"draws\":1}").has_value());
    CHECK_FALSE(early.take("{}").has_value());
}

TEST_CASE("early units: what is not JSON is parsed as judge_lab would, discarded") {
    grading::EarlyUnits early;
    const std::string bytes = "{\"u0\": [1, 2";
    early.record_done("/w/units.json", bytes);
    const std::optional<json> got = early.take(bytes);
    REQUIRE(got.has_value());
    CHECK(got->is_discarded());
    CHECK(json::parse(bytes, nullptr, false).is_discarded());
}
