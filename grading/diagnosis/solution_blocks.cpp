// The release markers' text (solution_blocks.hpp): a file's solution blocks
// and its student version.
#include "grading/diagnosis/solution_blocks.hpp"

#include <filesystem>
#include <functional>
#include <set>
#include <string_view>

#include "framework/error.hpp"

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

}  // namespace grading
