// units.json parsed while the child renders (grading/judge/early_units.hpp):
// judge_lab gets the parse of exactly the bytes it reads, or none, never
// another record's; and what a hostile child sends cannot make course hold
// or start more than a few parses.
#include "grading/judge/early_units.hpp"
#include "tests/support/test_support.hpp"

using grading::EarlyUnits;
using nlohmann::json;

TEST_CASE("early units: a units.json record is parsed once, for its own bytes") {
    EarlyUnits early(2);
    const std::string first = "{\"u0\":{\"result\":[1.5,2]}}\n";
    const std::string second = "{\"u0\":{\"error\":\"thrown\"}}\n";
    early.record_done("/tmp/course-x/0/units.json", first);
    early.record_done("/tmp/course-x/0/order.stats.json", "{\"draws\":1}");
    early.record_done("/tmp/course-x/1/units.json", second);

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
    EarlyUnits early(1);
    const std::string bytes = "{\"u0\": [1, 2";
    early.record_done("/w/units.json", bytes);
    const std::optional<json> got = early.take(bytes);
    REQUIRE(got.has_value());
    CHECK(got->is_discarded());
    CHECK(json::parse(bytes, nullptr, false).is_discarded());
}

TEST_CASE("early units: a child's records cannot make course hold or start more parses") {
    SUBCASE("a record of a path held replaces its parse") {
        EarlyUnits early(3);
        early.record_done("/w/0/units.json", "[1]");
        early.record_done("/w/0/units.json", "[2]");
        CHECK_FALSE(early.take("[1]").has_value());
        CHECK(early.take("[2]") == std::optional<json>(json::array({2})));
    }
    SUBCASE("at most kKept parses held: the next path waits for judge_lab") {
        EarlyUnits early(10);
        for (int i = 0; i < 5; ++i)
            early.record_done("/w/" + std::to_string(i) + "/units.json",
                              "[" + std::to_string(i) + "]");
        CHECK(EarlyUnits::kKept == 2);
        CHECK(early.take("[0]").has_value());
        CHECK(early.take("[1]").has_value());
        CHECK_FALSE(early.take("[2]").has_value());
        // Taken, the room is free again.
        early.record_done("/w/5/units.json", "[5]");
        CHECK(early.take("[5]").has_value());
    }
    SUBCASE("at most kStartsPerLab parses a lab, however often one path comes") {
        EarlyUnits early(1);
        for (int i = 0; i < 10; ++i)
            early.record_done("/w/units.json", "[" + std::to_string(i) + "]");
        CHECK(EarlyUnits::kStartsPerLab == 2);
        CHECK(early.take("[1]").has_value());  // the second start; none after it
        CHECK_FALSE(early.take("[9]").has_value());
    }
    SUBCASE("a record over the cap judge_lab reads is left alone") {
        EarlyUnits early(1);
        const std::string big = "[" + std::string(grading::kUnitsJsonMax, ' ') + "]";
        early.record_done("/w/units.json", big);
        CHECK_FALSE(early.take(big).has_value());
    }
}
