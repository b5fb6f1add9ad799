// Small text helpers that messages throughout the framework and `course`
// share, so that each idiom is written once.
#pragma once

#include <functional>
#include <string>
#include <string_view>

namespace fw {

// The items of `items` with `sep` between them, each passed through `proj`
// first (a member pointer or a function returning text; by default the item
// itself):
//
//   join(std::vector<std::string>{"a", "b"}, ", ")   // "a, b"
//   join(labs, ", ", &LabData::id)                    // "00_pipeline, 01_transforms"
template <class Range, class Proj = std::identity>
std::string join(const Range& items, std::string_view sep, Proj proj = {}) {
    std::string out;
    bool first = true;
    for (auto&& item : items) {
        if (!first) out += sep;
        first = false;
        out += std::invoke(proj, item);
    }
    return out;
}

// A GL object's label as messages show it: 'quad vertices', or (unlabelled)
// for an empty label. Not named `quoted`: std::quoted would compete through
// argument-dependent lookup wherever <iomanip> is included.
std::string quoted_label(const std::string& label);

// A number as printf's %.*g writes it, with `digits` significant digits:
//   number_text(0.5)            // "0.5"
//   number_text(1.0 / 3, 7)     // "0.3333333"
std::string number_text(double v, int digits = 6);

// A number with at most `decimals` decimals, trailing zeros and a trailing
// point dropped, and never "-0":
//   trimmed_decimals(2.50, 2)   // "2.5"
//   trimmed_decimals(-0.001, 2) // "0"
std::string trimmed_decimals(double v, int decimals);

// `s` as one word for /bin/sh: in single quotes, each ' written as '\''.
//   shell_quote("it's")   // 'it'\''s'
std::string shell_quote(std::string_view s);

}  // namespace fw
