// What the PrairieLearn tests check of a results.json: the schema as
// docs/contract.md (PrairieLearn's results.json) describes it, field by
// field, and the pictures decoded by this file's own base64 decoder and
// image headers, not by course's code.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace prairielearn_test {

using nlohmann::json;

// results.json's size limit: PrairieLearn's 1 MB.
constexpr size_t kMegabyte = 1000 * 1000;

// The width and height in a PNG's or a baseline or progressive JPEG's
// header; false when `bytes` is neither.
bool image_size(const std::string& bytes, int& width, int& height);

// A picture of a test, its data URL decoded.
struct Picture {
    std::string label;  // rendered | expected | difference
    std::string type;   // png | jpeg
    std::string bytes;
};

// Checks `results` against the documented schema: exactly the documented
// fields, in their types, for a gradable result (score in [0, 1], the sum of
// the tests' points over the sum of their max_points; each test's points
// within [0, max_points]; every picture a PNG or JPEG data URL of at most
// 160 pixels a side) or for one that is not (score 0, format errors, no
// tests). Returns the pictures of every test, in order.
std::vector<Picture> check_schema(const json& results);

}  // namespace prairielearn_test
