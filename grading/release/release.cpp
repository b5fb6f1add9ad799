// `course release`, the text: release markers in C++ and GLSL, hidden
// checkpoints in checkpoints files (release.hpp).
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

constexpr std::string_view kBegin = "// BEGIN SOLUTION";
constexpr std::string_view kEnd = "// END SOLUTION";
constexpr std::string_view kStudent = "// STUDENT:";

std::string_view trim(std::string_view s) {
    size_t b = s.find_first_not_of(" \t\r");
    if (b == std::string_view::npos) return {};
    size_t e = s.find_last_not_of(" \t\r");
    return s.substr(b, e - b + 1);
}

bool starts_with(std::string_view s, std::string_view prefix) {
    return s.substr(0, prefix.size()) == prefix;
}

enum class LineKind { code, begin, end, student };

// A comment whose first word is a marker must be spelt exactly, so that a
// near miss ("//BEGIN SOLUTION", "// END SOLUTION here") cannot leave
// solution code in the student version.
LineKind classify(std::string_view body, const std::string& where) {
    std::string_view t = trim(body);
    if (!starts_with(t, "//")) return LineKind::code;
    std::string_view word = t.substr(2);
    word.remove_prefix(std::min(word.size(), word.find_first_not_of(" \t")));
    auto exactly = [&](std::string_view marker, LineKind kind) {
        if (t != marker)
            throw fw::Error(where + ": write the marker exactly as `" + std::string(marker) +
                            "`, alone on its line (found `" + std::string(t) + "`)");
        return kind;
    };
    if (starts_with(word, "BEGIN SOLUTION")) return exactly(kBegin, LineKind::begin);
    if (starts_with(word, "END SOLUTION")) return exactly(kEnd, LineKind::end);
    if (starts_with(word, "STUDENT:")) {
        if (!starts_with(t, kStudent))
            throw fw::Error(where + ": write a student line as `// STUDENT: <code>` (found `" +
                            std::string(t) + "`)");
        return LineKind::student;
    }
    return LineKind::code;
}

// `<indent>// STUDENT: <code>` -> `<indent><code>`; one space after the colon
// belongs to the marker, further ones to the code.
std::string student_line(std::string_view body) {
    size_t indent = body.find_first_not_of(" \t");
    std::string_view code = body.substr(indent + kStudent.size());
    if (starts_with(code, " ")) code.remove_prefix(1);
    if (trim(code).empty()) return {};
    return std::string(body.substr(0, indent)) + std::string(code);
}

// One line of a text: as written, without its ending ("\n", "\r\n" or none
// at the end of the file), and that ending.
struct TextLine {
    std::string_view whole, body, ending;
};

// The line that starts at `pos`; moves `pos` to the next one.
TextLine take_line(const std::string& text, size_t& pos) {
    const size_t nl = text.find('\n', pos);
    const size_t next = nl == std::string::npos ? text.size() : nl + 1;
    TextLine l;
    l.whole = std::string_view(text.data() + pos, next - pos);
    l.body = l.whole.substr(0, nl == std::string::npos ? l.whole.size() : l.whole.size() - 1);
    if (!l.body.empty() && l.body.back() == '\r') l.body.remove_suffix(1);
    l.ending = l.whole.substr(l.body.size());
    pos = next;
    return l;
}

// The one walk over a file's lines that both checks the markers and writes a
// version of the text: block i is replaced by its student lines when
// `replace(i)`, else kept as written.
class BlockWalk {
public:
    BlockWalk(const std::string& path, const std::function<bool(size_t)>& replace,
              std::vector<SolutionBlock>* blocks)
        : path_(path), replace_(replace), blocks_(blocks) {}

    void add(const TextLine& l) {
        ++line_no_;
        const std::string where = path_ + ":" + std::to_string(line_no_);
        const LineKind kind = classify(l.body, where);
        const bool inside = open_.begin_line != 0;
        const bool cut = inside && replace_(index_);
        switch (kind) {
            case LineKind::begin:
                if (inside)
                    throw fw::Error(
                        where + ": BEGIN SOLUTION inside the block opened at line " +
                        std::to_string(open_.begin_line) +
                        "; blocks do not nest: close that one first with `// END SOLUTION`");
                open_.begin_line = line_no_;
                if (!replace_(index_)) out_ += l.whole;
                break;
            case LineKind::end:
                if (!inside)
                    throw fw::Error(where +
                                    ": END SOLUTION without a BEGIN SOLUTION above it; "
                                    "add `// BEGIN SOLUTION` where the block starts");
                close(line_no_);
                if (!cut) out_ += l.whole;
                break;
            case LineKind::student:
                if (!inside)
                    throw fw::Error(where +
                                    ": STUDENT line outside a solution block; put it between "
                                    "`// BEGIN SOLUTION` and `// END SOLUTION`");
                out_ += cut ? student_line(l.body) + std::string(l.ending) : std::string(l.whole);
                break;
            case LineKind::code:
                if (!cut) out_ += l.whole;
                break;
        }
    }

    // The text as rewritten, once every line is added.
    std::string finish() {
        if (open_.begin_line != 0)
            throw fw::Error(path_ + ":" + std::to_string(open_.begin_line) +
                            ": BEGIN SOLUTION without an END SOLUTION before the end of the "
                            "file; add `// END SOLUTION` where the block ends");
        return std::move(out_);
    }

private:
    void close(int end_line) {
        open_.end_line = end_line;
        if (blocks_) blocks_->push_back(open_);
        open_ = SolutionBlock{};
        ++index_;
    }

    const std::string& path_;
    const std::function<bool(size_t)>& replace_;
    std::vector<SolutionBlock>* blocks_;
    std::string out_;
    SolutionBlock open_;  // begin_line 0: outside a block
    size_t index_ = 0;    // of the block open or next
    int line_no_ = 0;
};

std::string rewrite_blocks(const std::string& text, const std::string& path,
                           const std::function<bool(size_t)>& replace,
                           std::vector<SolutionBlock>* blocks) {
    BlockWalk walk(path, replace, blocks);
    for (size_t pos = 0; pos < text.size();) walk.add(take_line(text, pos));
    return walk.finish();
}

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
    if (!trim(s.substr(line, begin - line)).empty()) return begin;
    while (line > 0) {
        size_t prev = line_start(s, line - 1);
        if (!starts_with(trim(s.substr(prev, line - 1 - prev)), "//")) break;
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

bool is_marked_source(const std::string& path) {
    static const std::set<std::string> kExtensions = {".cpp",  ".hpp",  ".h",    ".vert", ".frag",
                                                      ".geom", ".tesc", ".tese", ".comp", ".glsl"};
    return kExtensions.count(fs::path(path).extension().string()) > 0;
}

std::vector<SolutionBlock> solution_blocks(const std::string& text, const std::string& path) {
    std::vector<SolutionBlock> blocks;
    const auto keep_all = [](size_t) { return false; };
    rewrite_blocks(text, path, keep_all, &blocks);
    return blocks;
}

std::string student_text(const std::string& text, const std::string& path) {
    const auto replace_all = [](size_t) { return true; };
    return rewrite_blocks(text, path, replace_all, nullptr);
}

std::string student_text_of_block(const std::string& text, const std::string& path, size_t index) {
    const auto only_that_block = [index](size_t i) { return i == index; };
    return rewrite_blocks(text, path, only_that_block, nullptr);
}

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
