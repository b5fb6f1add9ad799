// `course release`, the text: hidden checkpoints in checkpoints files
// (release.hpp; the release markers' text: grading/diagnosis/solution_blocks.cpp).
#include "grading/release/release.hpp"

#include <algorithm>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <set>
#include <string_view>

#include "framework/error.hpp"
#include "framework/text.hpp"
#include "grading/results/results.hpp"

namespace fs = std::filesystem;

namespace grading {

namespace {

// --- checkpoints files: just enough of a JSON scanner to find where each
// entry of the "checkpoints" array starts and ends in the text. ---

struct Token {
    char kind;  // one of {}[]:, ; 's' a string; 'v' any other value
    size_t begin, end;
};

std::vector<Token> json_tokens(const std::string& text, const std::string& path) {
    std::vector<Token> tokens;
    size_t i = 0, n = text.size();
    auto fail = [&](const std::string& what) { throw fw::Error(path + ": " + what); };
    while (i < n) {
        char c = text[i];
        if (c == ' ' || c == '\t' || c == '\r' || c == '\n') {
            ++i;
        } else if (c == '/' && i + 1 < n && text[i + 1] == '/') {
            i = std::min(n, text.find('\n', i));
        } else if (c == '/' && i + 1 < n && text[i + 1] == '*') {
            size_t e = text.find("*/", i + 2);
            if (e == std::string::npos) fail("a /* comment is not closed");
            i = e + 2;
        } else if (c == '"') {
            size_t b = i++;
            while (i < n && text[i] != '"') i += text[i] == '\\' ? 2 : 1;
            if (i >= n) fail("a string is not closed");
            tokens.push_back({'s', b, ++i});
        } else if (std::string_view("{}[]:,").find(c) != std::string_view::npos) {
            tokens.push_back({c, i, i + 1});
            ++i;
        } else {
            size_t b = i;
            while (i < n &&
                   std::string_view(" \t\r\n{}[]:,\"/").find(text[i]) == std::string_view::npos)
                ++i;
            if (i == b) fail("unexpected '/' at offset " + std::to_string(i));
            tokens.push_back({'v', b, i});
        }
    }
    return tokens;
}

// The start of the line holding offset `at`.
size_t line_start(std::string_view s, size_t at) {
    size_t nl = at == 0 ? std::string_view::npos : s.rfind('\n', at - 1);
    return nl == std::string_view::npos ? 0 : nl + 1;
}

// Where the entry starting at `begin` starts once the comment lines directly
// above it (no blank line between) are counted as its own.
size_t with_comments_above(const std::string& text, size_t begin) {
    std::string_view s(text);
    size_t line = line_start(s, begin);
    if (s.substr(line, begin - line).find_first_not_of(" \t\r") != std::string_view::npos)
        return begin;
    while (line > 0) {
        size_t prev = line_start(s, line - 1);
        const std::string_view above = s.substr(prev, line - 1 - prev);
        const size_t first = above.find_first_not_of(" \t\r");
        if (first == std::string_view::npos || above.substr(first, 2) != "//") break;
        line = prev;
    }
    return line;
}

// The token that opens the "checkpoints" array: a key at depth 1 of the
// top-level object.
size_t checkpoints_array(const std::vector<Token>& t, const std::string& text,
                         const std::string& path) {
    for (size_t i = 0, depth = 0; i + 2 < t.size(); ++i) {
        const char k = t[i].kind;
        if (k == '{' || k == '[') ++depth;
        if ((k == '}' || k == ']') && depth > 0) --depth;
        if (depth == 1 && k == 's' && text.compare(t[i].begin, 13, "\"checkpoints\"") == 0 &&
            t[i].end - t[i].begin == 13 && t[i + 1].kind == ':' && t[i + 2].kind == '[')
            return i + 2;
    }
    throw fw::Error(path + ": expected an object with a \"checkpoints\" array");
}

// Each entry of the array opened at token `open`, as [first token, last
// token] at depth 0 of the array.
std::vector<std::pair<size_t, size_t>> array_entries(const std::vector<Token>& t, size_t open,
                                                     const std::string& path) {
    std::vector<std::pair<size_t, size_t>> entries;
    size_t first = 0, depth = 0;
    for (size_t i = open + 1; i < t.size(); ++i) {
        const char k = t[i].kind;
        if (depth == 0 && (k == ',' || k == ']')) {
            if (first) entries.push_back({first, i - 1});
            first = 0;
            if (k == ']') return entries;
            continue;
        }
        if (depth == 0 && !first) first = i;
        if (k == '{' || k == '[') ++depth;
        if (k == '}' || k == ']') --depth;
    }
    throw fw::Error(path + ": the \"checkpoints\" array is not closed");
}

// The text with only the entries `kept` (indices into starts/ends, which
// span every entry), each with the separator (comma, comments) that followed
// it; the last one with what followed the array's last entry.
std::string kept_entries(const std::string& text, const std::vector<size_t>& starts,
                         const std::vector<size_t>& ends, const std::vector<size_t>& kept) {
    std::string out = text.substr(0, starts.front());
    for (size_t j = 0; j < kept.size(); ++j) {
        const size_t e = kept[j];
        out += text.substr(starts[e], ends[e] - starts[e]);
        if (j + 1 < kept.size()) out += text.substr(ends[e], starts[e + 1] - ends[e]);
    }
    return out + text.substr(ends.back());
}

nlohmann::json parse_json(const std::string& text, const std::string& path) {
    try {
        return nlohmann::json::parse(text, nullptr, true, /*ignore_comments=*/true);
    } catch (const nlohmann::json::parse_error& e) {
        throw fw::Error(path + ": not valid JSON: " + e.what());
    }
}

}  // namespace

VisibleCheckpoints drop_hidden_checkpoints(const std::string& text, const std::string& path) {
    const nlohmann::json doc = parse_json(text, path);
    const std::vector<Token> t = json_tokens(text, path);
    VisibleCheckpoints result;
    std::vector<size_t> kept;
    std::vector<size_t> starts, ends;
    nlohmann::json expected = doc;
    expected["checkpoints"] = nlohmann::json::array();
    for (const auto& [first, last] : array_entries(t, checkpoints_array(t, text, path), path)) {
        const size_t b = t[first].begin, end = t[last].end;
        nlohmann::json entry = parse_json(text.substr(b, end - b), path);
        starts.push_back(with_comments_above(text, b));
        ends.push_back(end);
        if (entry.is_object() &&
            entry.value("visibility", std::string(name_of(Visibility::Visible))) ==
                name_of(Visibility::Hidden)) {
            result.dropped.push_back(entry.value("name", std::string("(unnamed)")));
            for (const nlohmann::json& check : entry.value("checks", nlohmann::json::array()))
                if (check.is_object() && check.value("points", nlohmann::json()).is_number())
                    result.hidden_points += check["points"].get<double>();
        } else {
            kept.push_back(starts.size() - 1);
            expected["checkpoints"].push_back(entry);
        }
    }
    if (result.dropped.empty()) {
        result.text = text;
        return result;
    }
    result.text = kept_entries(text, starts, ends, kept);
    // What the student's copy knows of them: how many, and their points.
    const nlohmann::json hidden = {{"checkpoints", result.dropped.size()},
                                   {"points", result.hidden_points}};
    const size_t brace = json_tokens(result.text, path).front().end;
    result.text.insert(brace,
                       "\"hidden\": {\"checkpoints\": " + std::to_string(result.dropped.size()) +
                           ", \"points\": " + fw::number_text(result.hidden_points, 6) + "},\n ");
    expected["hidden"] = hidden;
    if (parse_json(result.text, path + " (without its hidden checkpoints)") != expected)
        throw fw::Error(path +
                        ": cutting the hidden checkpoints out of the text did not leave "
                        "exactly the visible ones; simplify the layout around them");
    return result;
}

}  // namespace grading
