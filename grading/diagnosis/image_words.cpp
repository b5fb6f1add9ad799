#include "grading/diagnosis/image_words.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <unordered_map>
#include <utility>
#include <vector>

namespace grading {

namespace {

std::string channel(std::uint8_t v) {
    char text[16];
    std::snprintf(text, sizeof text, "%.2f", v / 255.0);
    std::string s = text;
    s.erase(s.find_last_not_of('0') + 1);
    if (s.back() == '.') s.pop_back();
    return s;
}

// 1204 -> "1,204".
std::string count_text(long n) {
    std::string digits = std::to_string(n), out;
    for (size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) out += ',';
        out += digits[i];
    }
    return out;
}

struct Box {
    int x0 = 1 << 30, y0 = 1 << 30, x1 = -1, y1 = -1;
    void add(int x, int y) {
        x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
    }
    std::string text() const {
        auto range = [](int a, int b) {
            return a == b ? std::to_string(a) : std::to_string(a) + "-" + std::to_string(b);
        };
        return "x " + range(x0, x1) + ", y " + range(y0, y1);
    }
};

std::uint32_t rgb_key(const fw::Rgba8& c) {
    return (std::uint32_t(c.r) << 16) | (std::uint32_t(c.g) << 8) | c.b;
}
fw::Rgba8 from_key(std::uint32_t k) {
    return {std::uint8_t(k >> 16), std::uint8_t(k >> 8), std::uint8_t(k), 255};
}

// The pair of colours (expected, found) seen most often at the same pixel
// (ties: the smaller key, so the text is stable). A pair, not each side's
// most common colour on its own: where two shades trade places (lines
// shifted by a pixel), each side's favourite can be the same colour.
std::pair<fw::Rgba8, fw::Rgba8> most_common(const std::unordered_map<std::uint64_t, long>& pairs) {
    std::uint64_t best = 0;
    long best_n = -1;
    for (const auto& [key, n] : pairs)
        if (n > best_n || (n == best_n && key < best)) best = key, best_n = n;
    return {from_key(static_cast<std::uint32_t>(best >> 24)),
            from_key(static_cast<std::uint32_t>(best & 0xFFFFFF))};
}

struct Group {
    std::string expected_name, found_name;
    long pixels = 0;
    Box box;
    std::unordered_map<std::uint64_t, long> pairs;  // (expected << 24 | found) -> pixels
};

}  // namespace

std::string colour_name(const fw::Rgba8& c) {
    const double r = c.r / 255.0, g = c.g / 255.0, b = c.b / 255.0;
    const double hi = std::max({r, g, b}), lo = std::min({r, g, b}), chroma = hi - lo;
    if (hi < 0.1) return "black";
    const double saturation = chroma / hi;
    if (saturation < 0.2 || chroma < 0.08) {
        if (hi > 0.9) return "white";
        return hi < 0.35 ? "dark grey" : hi > 0.7 ? "light grey" : "grey";
    }
    double hue = 0.0;  // degrees
    if (hi == r)
        hue = 60.0 * std::fmod((g - b) / chroma + 6.0, 6.0);
    else if (hi == g)
        hue = 60.0 * ((b - r) / chroma + 2.0);
    else
        hue = 60.0 * ((r - g) / chroma + 4.0);
    std::string name;
    if (hue < 15 || hue >= 345)
        name = "red";
    else if (hue < 40)
        name = hi < 0.6 ? "brown" : "orange";
    else if (hue < 70)
        name = "yellow";
    else if (hue < 165)
        name = "green";
    else if (hue < 195)
        name = "cyan";
    else if (hue < 255)
        name = "blue";
    else if (hue < 285)
        name = "purple";
    else if (hue < 320)
        name = "magenta";
    else
        name = "pink";
    if (name == "brown") return name;
    if (hi < 0.45) return "dark " + name;
    // Pale: half white or more, (0.5, 0.5, 1) light blue; washed out towards
    // grey, (0.5, 0.6, 0.7) greyish blue.
    if (saturation < 0.55 && hi > 0.8) return "light " + name;
    if (saturation < 0.35) return "greyish " + name;
    return name;
}

std::string colour_words(const fw::Rgba8& c) {
    return colour_name(c) + " (" + channel(c.r) + ", " + channel(c.g) + ", " + channel(c.b) + ")";
}

std::string describe_difference(const fw::Image& actual, const fw::Image& expected,
                                const fw::CompareResult& result, size_t groups) {
    if (result.size_mismatch || result.failed_pixels == 0 || actual.width != expected.width ||
        actual.height != expected.height ||
        result.failed.size() != static_cast<size_t>(actual.width) * actual.height)
        return {};
    Box all;
    std::map<std::pair<std::string, std::string>, Group> by_names;
    for (int y = 0; y < actual.height; ++y)
        for (int x = 0; x < actual.width; ++x) {
            if (!result.failed[static_cast<size_t>(y) * actual.width + x]) continue;
            all.add(x, y);
            const fw::Rgba8 want = expected.at(x, y), got = actual.at(x, y);
            Group& g = by_names[{colour_name(want), colour_name(got)}];
            ++g.pixels;
            g.box.add(x, y);
            ++g.pairs[(std::uint64_t(rgb_key(want)) << 24) | rgb_key(got)];
        }
    std::vector<const Group*> sorted;
    for (auto& [names, g] : by_names) {
        g.expected_name = names.first;
        g.found_name = names.second;
        sorted.push_back(&g);
    }
    std::stable_sort(sorted.begin(), sorted.end(),
                     [](const Group* a, const Group* b) { return a->pixels > b->pixels; });
    std::string text = "Where: the differing pixels lie in " + all.text() +
                       " (pixels from the bottom-left corner, as probes count them)";
    long rest = 0;
    for (size_t i = 0; i < sorted.size(); ++i) {
        const Group& g = *sorted[i];
        if (i >= groups) {
            rest += g.pixels;
            continue;
        }
        // A colour name that is the same on both sides means a shade differs:
        // the exact colours say which.
        const auto [want, got] = most_common(g.pairs);
        text += "\n  " + count_text(g.pixels) + (g.pixels == 1 ? " pixel" : " pixels") +
                ": expected " + colour_words(want) + ", found " + colour_words(got) + ", in " +
                g.box.text();
    }
    if (rest > 0)
        text += "\n  " + count_text(rest) + (rest == 1 ? " pixel" : " pixels") +
                " more, of other colours";
    return text;
}

}  // namespace grading
