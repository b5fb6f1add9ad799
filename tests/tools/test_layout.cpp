// The repository's layout, read from its files (no build, no GL): grading's rooms include only
// rooms below them, and the judge of the diagnosis only its interface (diagnosis.hpp);
// framework and grading headers include no cycle, every repository path and
// docs section that a comment or a Markdown page cites exists, functions and files keep to
// the sizes of docs/conventions.md; a lab's files with student parts neither register the
// lab nor include nlohmann/json.hpp; and each lab sheet's parts and Files: list name the files
// whose `// STUDENT:` lines hold a TODO (docs/conventions.md, Student parts).
//
// The files read are those of framework/ grading/ labs/ shaders/ tests/ bench/ scripts/ docs/
// and README.md that git lists or would add (build*/ and third_party/ left out). Read are:
// - Comments: `//` and `/* */` in C++, GLSL and the labs' checkpoints.json files (JSON with
//   `//` comments), `#` in shell scripts and CMakeLists.txt.
//   Consecutive comment lines are one text, so a citation may wrap. Markdown pages (docs/*.md,
//   README.md, labs/*/README.md) are read paragraph by paragraph, HTML comments left out.
// - A cited path is a word starting with framework/ grading/ labs/ shaders/ tests/ bench/
//   scripts/ docs/ third_party/ cmake/ or .ci/ that does not continue another word or path (so
//   build/grade/, /autograder/tests/ and $OUT/docs/ are no repository paths), up to the first
//   character that cannot be in a path (so `:12-30` is left out) and without a trailing `.`.
//   NN_name and NN_* stand for any lab folder, `*` and an upper-case word (NAME, CHECKPOINT;
//   README excepted) for any part of a name: some path must match, from the top or, as in the
//   listings of a lab's folder, from a lab folder (`tests/*.cpp`). A path without a placeholder
//   or an extension may name the program built from a source of that name (bench/bench_png).
//   labs/90_warmup/ (docs/staff.md, Adding a lab) exists only in its test's copy.
// - A section citation is a page (docs/contract.md, docs/labs.md, docs/conventions.md,
//   labs/NN_name/README.md; README.md is the sheet of the lab the citing file is in, else the
//   top README) followed directly by ", " and comma-separated names, up to `)`, `;`, `:`, `|`,
//   ` (`, a closing `"` or the end of the sentence. The first name is a heading of the page.
//   Each further name is a heading, or the label that opens a paragraph, list item or table row,
//   inside the previous name's section (docs/contract.md, `course`, Sandbox; docs/contract.md,
//   Checks, `image`), unless it starts with a lower-case letter: that is prose
//   (docs/contract.md, Exit status and errors, lists them) and ends the names. A first name that
//   is a file (a word with `/` or `.`) makes a list of files, not a citation. Names compare
//   without backticks and quotes, case-insensitively, and match a heading that continues them
//   after a space or punctuation (`course release` cites "`course release --out DIR`").
#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "framework/checkpoints.hpp"
#include "tests/support/test_support.hpp"

namespace fs = std::filesystem;

namespace {

// grading's rooms, lowest floor first: a room includes only itself and the rooms below.
const std::vector<std::string> kRooms = {"sandbox",   "results",  "run",    "units",
                                         "diagnosis", "judge",    "report", "release",
                                         "platforms", "commands", "class"};
// The one header of grading/diagnosis/ that grading/judge/ includes: the judge
// reads the diagnosis through it alone (docs/architecture.md).
const std::string kDiagnosisInterface = "grading/diagnosis/diagnosis.hpp";
// The lab that docs/staff.md, Adding a lab, makes, in a copy of the tree only
// (tests/tools/test_new_lab.cpp).
const std::string kNewLab = "90_warmup";

struct Problem {
    std::string where;  // file:line
    std::string what;   // what is wrong and what to fix
};

struct Repo {
    fs::path root;
    std::vector<std::string> files;  // the files read, relative to root
    std::vector<std::string> all;    // every file and folder under root, for patterns
};

unsigned char u(char c) { return static_cast<unsigned char>(c); }  // for <cctype>
bool starts_with(const std::string& s, const std::string& prefix) {
    return s.rfind(prefix, 0) == 0;
}
bool ends_with(const std::string& s, const std::string& suffix) {
    return s.size() >= suffix.size() &&
           s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

Repo read_repo(const fs::path& root) {
    static const std::regex read("(framework|grading|labs|shaders|tests|bench|scripts|docs)/.*");
    Repo repo{root, {}, {}};
    for (auto it = fs::recursive_directory_iterator(root); it != fs::recursive_directory_iterator();
         ++it) {
        const std::string name = it->path().filename().string();
        if (it->is_directory() && (name == ".git" || starts_with(name, "build"))) {
            it.disable_recursion_pending();
            continue;
        }
        const std::string rel = fs::relative(it->path(), root).generic_string();
        repo.all.push_back(rel);
        if (it->is_regular_file() && std::regex_match(rel, read) &&
            rel.find("third_party/") == std::string::npos)
            repo.files.push_back(rel);
    }
    if (fs::exists(root / "README.md")) repo.files.push_back("README.md");
    std::sort(repo.files.begin(), repo.files.end());
    return repo;
}

std::vector<std::string> read_lines(const fs::path& path) {
    std::ifstream in(path);
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);) lines.push_back(line);
    return lines;
}

// The `#include "X"` lines of a C++ file: (line number, X).
std::vector<std::pair<int, std::string>> quoted_includes(const fs::path& path) {
    static const std::regex include(R"re(^\s*#\s*include\s*"([^"]+)")re");
    std::vector<std::pair<int, std::string>> out;
    const std::vector<std::string> lines = read_lines(path);
    std::smatch m;
    for (size_t i = 0; i < lines.size(); ++i)
        if (std::regex_search(lines[i], m, include)) out.emplace_back(int(i) + 1, m[1].str());
    return out;
}

// grading/ROOM/... -> its floor in kRooms; -1 for a path in no room.
int floor_of(const std::string& path, std::string& room) {
    const size_t slash = path.find('/', 8);
    room = starts_with(path, "grading/") && slash != std::string::npos ? path.substr(8, slash - 8)
                                                                       : "";
    const auto it = std::find(kRooms.begin(), kRooms.end(), room);
    return it == kRooms.end() ? -1 : int(it - kRooms.begin());
}

std::vector<Problem> room_problems(const Repo& repo) {
    static const std::regex checked(R"((grading/.*|labs/[^/]+/grading/[^/]+)\.(cpp|hpp))");
    std::vector<Problem> out;
    for (const std::string& f : repo.files) {
        if (!std::regex_match(f, checked) || f == "grading/main.cpp") continue;
        const bool in_lab = starts_with(f, "labs/");
        std::string room, to;
        const int floor = floor_of(f, room);
        for (const auto& [line, inc] : quoted_includes(repo.root / f)) {
            const int to_floor = floor_of(inc, to);
            const std::string where = f + ":" + std::to_string(line);
            if (!starts_with(inc, "grading/")) continue;
            if (to_floor < 0)
                out.push_back({where, "includes \"" + inc + "\", which is in no room of grading/"});
            else if (in_lab && to != "units")
                out.push_back({where, "a lab's grading reference includes \"" + inc +
                                          "\"; it may include grading/units/ only"});
            else if (!in_lab && floor < 0)
                out.push_back({where, f + " is in no room; move it into one of grading's rooms"});
            else if (!in_lab && to_floor > floor)
                out.push_back({where, "room " + room + " includes \"" + inc + "\" of room " + to +
                                          ", which is above it; move what it needs down into " +
                                          room + " or a room below"});
        }
    }
    return out;
}

// The includes of grading/judge/ into grading/diagnosis/ other than its interface.
std::vector<Problem> interface_problems(const Repo& repo, size_t& judge_files) {
    std::vector<Problem> out;
    for (const std::string& f : repo.files) {
        if (!starts_with(f, "grading/judge/")) continue;
        ++judge_files;
        for (const auto& [line, inc] : quoted_includes(repo.root / f))
            if (starts_with(inc, "grading/diagnosis/") && inc != kDiagnosisInterface)
                out.push_back({f + ":" + std::to_string(line),
                               "the judge includes \"" + inc + "\"; it reads the diagnosis only " +
                                   "through \"" + kDiagnosisInterface +
                                   "\": include that, and add there what the judge needs"});
    }
    return out;
}

// Follows the includes from `at`; true when one leads back to a header on `path`, which then
// holds the chain "a.hpp:3 includes b.hpp", ... that closes the cycle.
using Graph = std::map<std::string, std::vector<std::pair<int, std::string>>>;
bool find_cycle(const Graph& g, const std::string& at, std::map<std::string, int>& state,
                std::vector<std::string>& path) {
    state[at] = 1;  // on the path
    for (const auto& [line, to] : g.at(at)) {
        path.push_back(at + ":" + std::to_string(line) + " includes " + to);
        if (state[to] == 1 || (state[to] == 0 && find_cycle(g, to, state, path))) return true;
        path.pop_back();
    }
    state[at] = 2;  // no cycle through it
    return false;
}

std::vector<Problem> cycle_problems(const Repo& repo, size_t& headers) {
    static const std::regex header("(framework|grading)/.*\\.hpp");
    Graph g;
    for (const std::string& f : repo.files)
        if (std::regex_match(f, header)) g[f];
    headers = g.size();
    for (auto& [f, edges] : g)
        for (const auto& [line, inc] : quoted_includes(repo.root / f))
            if (g.count(inc)) edges.emplace_back(line, inc);
    std::map<std::string, int> state;
    std::vector<Problem> out;
    for (const auto& [f, edges] : g) {
        std::vector<std::string> path;
        if (state[f] != 0 || !find_cycle(g, f, state, path)) continue;
        const std::string back_to = path.back().substr(path.back().rfind(' ') + 1);
        std::string chain;
        for (const std::string& step : path)
            if (!chain.empty() || starts_with(step, back_to + ":")) chain += "\n  " + step;
        out.push_back({chain.substr(3, chain.find(' ', 3) - 3),
                       "header cycle; break it with a forward declaration or by moving what the "
                       "last include needs into a header of its own:" +
                           chain});
    }
    return out;
}

// A text to search for citations: consecutive comment lines, or a Markdown paragraph, joined
// by spaces; line_at[i] is the line of text[i].
struct Passage {
    std::string text;
    std::vector<int> line_at;
    int last = 0;         // its last line
    bool closed = false;  // a Markdown heading, table row or line of code: nothing joins it
};

// Adds `piece`, on `line`, to the last passage when that is open and ended on the line before.
void add_piece(std::vector<Passage>& out, const std::string& piece, int line, bool alone = false) {
    if (alone || out.empty() || out.back().closed || out.back().last < line - 1) out.emplace_back();
    Passage& p = out.back();
    if (p.last != 0) p.text += ' ', p.line_at.push_back(line);
    p.text += piece;
    p.line_at.insert(p.line_at.end(), piece.size(), line);
    p.last = line;
    p.closed = alone;
}

void add_comment(std::vector<Passage>& out, const std::string& piece, int line) {
    const size_t start = piece.find_first_not_of(" \t/*#!");
    add_piece(out, start == std::string::npos ? "" : piece.substr(start), line);
}

// Skips the string, character or raw string literal that opens at s[i]; for a raw string not
// closed on this line, sets `raw_end` to its `)delim"`. Returns the index of its last character.
size_t skip_literal(const std::string& s, size_t i, std::string& raw_end) {
    const char quote = s[i];
    if (quote == 'R') {
        const size_t open = s.find('(', i);
        if (open == std::string::npos) return s.size();
        raw_end = ")" + s.substr(i + 2, open - i - 2) + "\"";
        const size_t end = s.find(raw_end, open);
        if (end == std::string::npos) return s.size();
        i = end + raw_end.size() - 1;
        raw_end.clear();
        return i;
    }
    for (++i; i < s.size() && s[i] != quote; ++i) i += s[i] == '\\';
    return i;
}

// Comments of C++ and GLSL; literals are skipped.
std::vector<Passage> c_comments(const std::vector<std::string>& lines) {
    std::vector<Passage> out;
    bool block = false;
    std::string raw_end;  // inside a raw string literal: its closing `)delim"`
    for (size_t n = 0; n < lines.size(); ++n) {
        const std::string& s = lines[n];
        size_t i = 0, begin = 0;
        if (!raw_end.empty()) {
            const size_t end = s.find(raw_end);
            i = end == std::string::npos ? s.size() : end + raw_end.size();
            if (end != std::string::npos) raw_end.clear();
        }
        for (; i < s.size(); ++i) {
            const bool word_before = i > 0 && (std::isalnum(u(s[i - 1])) || s[i - 1] == '_');
            if (block) {
                if (s.compare(i, 2, "*/") != 0) continue;
                add_comment(out, s.substr(begin, i - begin), int(n) + 1);
                block = false, ++i;
            } else if (s.compare(i, 2, "//") == 0) {
                add_comment(out, s.substr(i), int(n) + 1);
                break;
            } else if (s.compare(i, 2, "/*") == 0) {
                block = true, begin = i + 2, ++i;
            } else if (s[i] == '"' || (!word_before && (s[i] == '\'' || !s.compare(i, 2, "R\"")))) {
                i = skip_literal(s, i, raw_end);
            }
        }
        if (block) add_comment(out, s.substr(std::min(begin, s.size())), int(n) + 1);
    }
    return out;
}

// `#` comments of shell scripts and CMakeLists.txt: a `#` outside quotes that starts a word.
std::vector<Passage> hash_comments(const std::vector<std::string>& lines, bool shell) {
    std::vector<Passage> out;
    for (size_t n = 0; n < lines.size(); ++n) {
        const std::string& s = lines[n];
        char quote = 0;
        for (size_t i = 0; i < s.size(); ++i) {
            if (quote) {
                i += s[i] == '\\' && quote == '"';
                quote = i < s.size() && s[i] == quote ? 0 : quote;
            } else if (s[i] == '"' || (shell && s[i] == '\'')) {
                quote = s[i];
            } else if (s[i] == '#' && (i == 0 || std::isspace(u(s[i - 1])) || s[i - 1] == '(')) {
                if (n > 0 || !starts_with(s, "#!")) add_comment(out, s.substr(i), int(n) + 1);
                break;
            }
        }
    }
    return out;
}

bool is_fence(const std::string& s) {
    const size_t start = s.find_first_not_of(' ');
    return start != std::string::npos && s.compare(start, 3, "```") == 0;
}

// Markdown: paragraphs; a heading, a table row and a line of a code block each stand alone.
// An HTML comment, from a line that opens with `<!--` to the line that holds `-->`, shows
// nothing and cites nothing (a picture still to be made waits there).
std::vector<Passage> markdown_passages(const std::vector<std::string>& lines) {
    std::vector<Passage> out;
    bool code = false, hidden = false;
    for (size_t n = 0; n < lines.size(); ++n) {
        const std::string& s = lines[n];
        const size_t start = s.find_first_not_of(' ');
        if (hidden || (!code && start != std::string::npos && s.compare(start, 4, "<!--") == 0)) {
            hidden = s.find("-->", hidden ? 0 : start + 4) == std::string::npos;
            continue;
        }
        code = code != is_fence(s);
        if (start != std::string::npos)
            add_piece(out, s, int(n) + 1, code || s[start] == '#' || s[start] == '|');
    }
    return out;
}

bool is_markdown(const std::string& f) {
    static const std::regex page(R"(docs/[^/]+\.md|README\.md|labs/[^/]+/README\.md)");
    return std::regex_match(f, page);
}

// The passages in which `f` may cite paths and sections; none for other kinds of file.
std::vector<Passage> passages(const Repo& repo, const std::string& f) {
    static const std::set<std::string> c_like = {".cpp",  ".hpp",  ".glsl", ".vert", ".frag",
                                                 ".geom", ".tesc", ".tese", ".comp"};
    const std::string ext = fs::path(f).extension().string();
    const std::vector<std::string> lines = read_lines(repo.root / f);
    if (is_markdown(f)) return markdown_passages(lines);
    if (c_like.count(ext) || fs::path(f).filename() == "checkpoints.json") return c_comments(lines);
    if (ext == ".sh") return hash_comments(lines, true);
    if (fs::path(f).filename() == "CMakeLists.txt") return hash_comments(lines, false);
    return {};
}

// A regex for one folder or file name of a cited path; sets `placeholder` when it has one.
std::string name_regex(const std::string& seg, bool& placeholder) {
    std::string out;
    for (size_t i = 0; i < seg.size();) {
        size_t end = i;
        while (end < seg.size() &&
               (std::isupper(u(seg[end])) || std::isdigit(u(seg[end])) || seg[end] == '_'))
            ++end;
        const std::string word = seg.substr(i, end - i);
        const bool any_lab = seg.compare(i, 7, "NN_name") == 0 || seg.compare(i, 4, "NN_*") == 0;
        const bool any_name = (i == 0 || !std::isalpha(u(seg[i - 1]))) &&
                              (end == seg.size() || !std::islower(u(seg[end]))) &&
                              word.size() >= 2 && word != "README";
        placeholder = placeholder || any_lab || any_name || seg[i] == '*';
        if (any_lab) {
            out += "[0-9][0-9]_[a-z0-9_]+", i += seg[i + 3] == '*' ? 4 : 7;
        } else if (seg[i] == '*') {
            out += "[^/]*", ++i;
        } else if (any_name) {
            out += "[^/]+", i = end;
        } else {
            if (std::string(".^$|()[]{}+?\\").find(seg[i]) != std::string::npos) out += '\\';
            out += seg[i++];
        }
    }
    return out;
}

bool matches_any(const Repo& repo, const std::string& pattern) {
    const std::regex re(pattern);
    return std::any_of(repo.all.begin(), repo.all.end(),
                       [&](const std::string& p) { return std::regex_match(p, re); });
}

bool path_exists(const Repo& repo, const std::string& cited) {
    static const std::regex new_lab("(labs|shaders)/" + kNewLab + "(/.*)?");
    if (fs::exists(repo.root / cited) || std::regex_match(cited, new_lab)) return true;
    // What `course release` writes into a student's copy, beside a lab's
    // sources: its recorded unit cases and its parts' starting hashes.
    for (const char* made : {"grading/cases.json", "grading/starting.json"})
        if (ends_with(cited, made)) return true;
    std::string pattern;
    bool placeholder = false;
    std::stringstream parts(cited);
    for (std::string seg; std::getline(parts, seg, '/');)
        if (!seg.empty()) pattern += (pattern.empty() ? "" : "/") + name_regex(seg, placeholder);
    if (!placeholder) return matches_any(repo, pattern + "\\.[a-z]+");  // a program's source
    return matches_any(repo, pattern) || matches_any(repo, "labs/[0-9][0-9]_[^/]+/" + pattern);
}

// `cited` counts every citation, `in_checkpoints` those in a checkpoints.json.
std::vector<Problem> path_problems(const Repo& repo, size_t& cited, size_t& in_checkpoints) {
    static const std::regex token(
        "(^|[^A-Za-z0-9_./$~}-])((framework|grading|labs|shaders|tests|bench|scripts|docs|"
        "third_party|cmake|\\.ci)/[A-Za-z0-9_.*/-]*)");
    std::vector<Problem> out;
    for (const std::string& f : repo.files)
        for (const Passage& p : passages(repo, f))
            for (auto it = std::sregex_iterator(p.text.begin(), p.text.end(), token);
                 it != std::sregex_iterator(); ++it) {
                std::string path = (*it)[2].str();
                while (ends_with(path, ".")) path.pop_back();
                ++cited;
                in_checkpoints += fs::path(f).filename() == "checkpoints.json";
                if (path_exists(repo, path)) continue;
                const int line = p.line_at[size_t(it->position(2))];
                out.push_back({f + ":" + std::to_string(line),
                               "cites " + path + ", which does not exist; cite where it is now"});
            }
    return out;
}

// Without backticks and quotes, lower case, spaces collapsed.
std::string normalised(const std::string& s) {
    std::string out;
    for (const char c : s) {
        if (c == '`' || c == '"' || (std::isspace(u(c)) && (out.empty() || out.back() == ' ')))
            continue;
        out += std::isspace(u(c)) ? ' ' : char(std::tolower(u(c)));
    }
    if (!out.empty() && out.back() == ' ') out.pop_back();
    return out;
}

// Whether `text` is `name`, or continues it after a space or punctuation (both normalised).
bool opens_with(const std::string& text, const std::string& name) {
    return !name.empty() && starts_with(text, name) &&
           (text.size() == name.size() || !std::isalnum(u(text[name.size()])));
}

// A Markdown page, line by line, normalised: a heading's level (else 0) and text, or the text
// of any other line without its list or table marker; lines of code blocks are left empty.
struct Page {
    std::vector<std::pair<int, std::string>> lines;
    std::string headings;  // all of them, for messages
};

Page read_page(const fs::path& path) {
    static const std::regex heading(R"(^(#{1,6}) +(.*?)[ #]*$)");
    static const std::regex marker(R"(^\s*(- |\* |\| |[0-9]+\. )?(\*\*)?)");
    Page page;
    bool code = false;
    std::smatch m;
    for (const std::string& s : read_lines(path)) {
        const bool fence = is_fence(s);
        code = code != fence;
        if (code || fence) {
            page.lines.emplace_back(0, "");
        } else if (std::regex_match(s, m, heading)) {
            page.lines.emplace_back(int(m[1].length()), normalised(m[2].str()));
            page.headings += (page.headings.empty() ? "" : " | ") + m[2].str();
        } else {
            page.lines.emplace_back(0, normalised(std::regex_replace(s, marker, "")));
        }
    }
    return page;
}

// The sections [begin, end) inside `within` whose heading is `name`; for a further name
// (`first` false) `within` itself when a paragraph, list item or table row in it opens so.
using Section = std::pair<size_t, size_t>;
std::vector<Section> find_name(const Page& page, Section within, const std::string& name,
                               bool first) {
    std::vector<Section> found;
    for (size_t i = within.first; i < within.second; ++i) {
        const auto& [level, text] = page.lines[i];
        if (!opens_with(text, name) || (level == 0 && first)) continue;
        if (level == 0) return {within};
        size_t end = i + 1;
        while (end < page.lines.size() &&
               !(page.lines[end].first > 0 && page.lines[end].first <= level))
            ++end;
        found.emplace_back(i, end);
    }
    return found;
}

// Whether a cited name is a file rather than a heading: its first word has a `/`, or it is
// one word with a `.`.
bool names_file(const std::string& name) {
    const std::string word = name.substr(0, name.find(' '));
    return word.find('/') != std::string::npos ||
           (word == name && name.find('.') != std::string::npos);
}

// The names cited after "FILE, " at t[i], normalised (the file's header says how they are
// read). A `"` opens a quoted name at the start of a name; another one ends the names.
std::vector<std::string> cited_names(const std::string& t, size_t i) {
    std::vector<std::string> names(1);
    bool code = false, quoted = false;
    for (; i < t.size(); ++i) {
        const char c = t[i];
        const bool blank = names.back().find_first_not_of(' ') == std::string::npos;
        const bool ends = c == ')' || c == ';' || c == ':' || c == '|' ||
                          (c == '"' && !blank && !quoted) || (c == '(' && t[i - 1] == ' ') ||
                          (c == '.' && (i + 1 == t.size() || t[i + 1] == ' '));
        if (c == '`') code = !code;
        if (c == '"' && !code) quoted = blank;
        if (!code && ends) break;
        if (!code && c == ',') names.emplace_back();
        if (code || c != ',') names.back() += c;
    }
    for (size_t n = 0; n < names.size(); ++n) {
        const size_t first = names[n].find_first_not_of(' ');
        const bool prose = first != std::string::npos && std::islower(u(names[n][first]));
        names[n] = normalised(names[n]);
        if (names[n].empty() || (n > 0 && (prose || names_file(names[n])))) names.resize(n);
    }
    if (!names.empty() && names_file(names[0])) names.clear();  // a list of files
    return names;
}

// What is wrong with citing `names` of `page` (`file`); empty when each is there.
std::string citation_problem(const Page& page, const std::string& file,
                             const std::vector<std::string>& names) {
    std::vector<Section> in = {{0, page.lines.size()}};
    for (size_t n = 0; n < names.size(); ++n) {
        std::vector<Section> found;
        for (const Section& s : in) {
            const std::vector<Section> here = find_name(page, s, names[n], n == 0);
            found.insert(found.end(), here.begin(), here.end());
        }
        if (found.empty() && n == 0)
            return "cites \"" + names[0] + "\" of " + file +
                   ", which has no such heading; cite one of: " + page.headings;
        if (found.empty())
            return "cites \"" + names[n] + "\" under \"" + names[n - 1] + "\" of " + file +
                   ", where no heading, paragraph, list item or table row opens so";
        in = found;
    }
    return "";
}

std::vector<Problem> heading_problems(const Repo& repo, size_t& cited) {
    static const std::regex citation(
        "(^|[^A-Za-z0-9_./-])(docs/[a-z_]+\\.md|labs/[0-9][0-9]_[a-z0-9_]+/README\\.md|"
        "README\\.md), ");
    static const std::regex lab_folder("labs/[0-9][0-9]_[a-z0-9_]+/");
    std::map<std::string, Page> pages;
    std::vector<Problem> out;
    for (const std::string& f : repo.files)
        for (const Passage& p : passages(repo, f))
            for (auto it = std::sregex_iterator(p.text.begin(), p.text.end(), citation);
                 it != std::sregex_iterator(); ++it) {
                std::smatch lab;
                std::string file = (*it)[2].str();
                if (file == "README.md" && std::regex_search(f, lab, lab_folder) &&
                    lab.position(0) == 0)
                    file = lab.str(0) + file;
                const auto names = cited_names(p.text, size_t(it->position(0) + it->length(0)));
                if (names.empty() || !fs::exists(repo.root / file)) continue;
                if (!pages.count(file)) pages[file] = read_page(repo.root / file);
                ++cited;
                const std::string problem = citation_problem(pages[file], file, names);
                const int line = p.line_at[size_t(it->position(2))];
                if (!problem.empty()) out.push_back({f + ":" + std::to_string(line), problem});
            }
    return out;
}

// docs/conventions.md, Size: a function of framework/ and grading/ under about 60 lines, a file
// under about 400; a lab's file about 150 to 250 lines and its draw() too under 60. Measured
// here with a margin: 60 lines a function (signature to closing brace), 420 lines a file of
// framework/ or grading/; a lab file (its tests and grading references left out) at most 250,
// the sheet's bound, since students read every line of it.
constexpr size_t kFunctionLines = 60, kFileLines = 420, kLabFileLines = 250;

// The functions of a C++ file: a statement at indentation 0 or 4 (namespaces are not indented;
// 4 is a class member) that holds a `(` and opens a block at its end, up to the `}` at its own
// indentation. Types, namespaces and control statements are no functions.
std::vector<std::pair<int, size_t>> function_lengths(const std::vector<std::string>& lines) {
    static const std::regex not_function(
        R"(\s*(namespace|struct|class|enum|union|extern|if|for|while|switch|else|do|try)\b.*)");
    std::vector<std::pair<int, size_t>> out;
    for (size_t i = 0; i < lines.size(); ++i) {
        const std::string& l = lines[i];
        if (l.empty() || l.back() != '{') continue;
        size_t first = i;  // the statement's first line
        while (first > 0) {
            const std::string& prev = lines[first - 1];
            const size_t end = prev.find_last_not_of(' ');
            if (end == std::string::npos || prev[end] == ';' || prev[end] == '}' ||
                prev[end] == '{' || prev[end] == ':' || prev.find("//") != std::string::npos ||
                prev[0] == '#')
                break;
            --first;
        }
        const size_t indent = lines[first].find_first_not_of(' ');
        if (indent != 0 && indent != 4) continue;
        std::string statement;
        for (size_t k = first; k <= i; ++k) statement += lines[k] + " ";
        if (statement.find('(') == std::string::npos || std::regex_match(statement, not_function))
            continue;
        const std::string close = std::string(indent, ' ') + "}";
        size_t j = i + 1;
        while (j < lines.size() && lines[j].rfind(close, 0) != 0) ++j;
        out.push_back({int(first) + 1, j - first + 1});
        i = j;
    }
    return out;
}

std::vector<Problem> size_problems(const Repo& repo, size_t& functions) {
    static const std::regex lab_code(R"(labs/\d\d_[a-z0-9_]+/[^/]+\.(cpp|hpp))");
    std::vector<Problem> out;
    for (const std::string& f : repo.files) {
        const bool lab = std::regex_match(f, lab_code);
        if (!lab && !((starts_with(f, "framework/") || starts_with(f, "grading/")) &&
                      (ends_with(f, ".cpp") || ends_with(f, ".hpp"))))
            continue;
        const std::vector<std::string> lines = read_lines(repo.root / f);
        const size_t file_limit = lab ? kLabFileLines : kFileLines;
        if (lines.size() > file_limit)
            out.push_back(
                {f + ":1", std::to_string(lines.size()) + " lines, over " +
                               std::to_string(file_limit) +
                               ": split it by responsibility (docs/conventions.md, Size)"});
        for (const auto& [line, length] : function_lengths(lines)) {
            ++functions;
            if (length > kFunctionLines)
                out.push_back({f + ":" + std::to_string(line),
                               "a function of " + std::to_string(length) + " lines, over " +
                                   std::to_string(kFunctionLines) +
                                   ": split it into named steps (docs/conventions.md, Size)"});
        }
    }
    return out;
}

// Whether `file` includes <nlohmann/json.hpp>, itself or through the quoted
// includes it finds beside it or from the repository's root.
bool includes_json(const fs::path& root, const fs::path& file, std::set<fs::path>& seen) {
    if (!seen.insert(file).second) return false;
    for (const std::string& line : read_lines(file))
        if (line.find("#include <nlohmann/json.hpp>") != std::string::npos) return true;
    for (const auto& [line, name] : quoted_includes(file))
        for (const fs::path& at : {file.parent_path() / name, root / name})
            if (fs::is_regular_file(at) && includes_json(root, at, seen)) return true;
    return false;
}

// A lab's file with a student part is compiled again for every submission
// an autograder builds; the lab's class and JSON belong in files without one.
std::vector<Problem> student_file_problems(const Repo& repo, size_t& student_files) {
    static const std::regex lab_file("labs/[0-9][0-9]_[a-z0-9_]+/[^/]+\\.cpp");
    std::vector<Problem> out;
    for (const std::string& f : repo.files) {
        if (!std::regex_match(f, lab_file)) continue;
        const std::string text = fw::test::read_text((repo.root / f).string());
        if (text.find("// BEGIN SOLUTION") == std::string::npos) continue;
        ++student_files;
        auto problem = [&](const std::string& what) {
            out.push_back({f, what + ", which every submission's build then compiles again: "
                                     "move it to a file of the lab without a student part "
                                     "(docs/conventions.md, Student parts)"});
        };
        if (text.find("FW_LAB(") != std::string::npos) problem("it registers the lab (FW_LAB)");
        std::set<fs::path> seen;
        if (includes_json(repo.root, repo.root / f, seen))
            problem("it includes nlohmann/json.hpp, itself or through a header");
    }
    return out;
}

// A lab sheet against the files that carry its parts' TODOs. A part is a numbered item of
// the sheet's "What you implement" section (a section without one has one part: its first
// paragraph that opens with a bold title). The files a part names are the file names in
// backticks of its lead, the text before the first `:` or `. ` outside backticks: its title,
// its files and its functions ("**The blend modes**, `fragment_state.cpp`,
// `set_blend_mode()`:"). The sheet's `Files:` paragraph lists the lab's files. A bare name
// is a file of labs/NN_name/ or shaders/NN_name/; a name with a `/` is a repository path.
struct Sheet {
    std::vector<std::string> parts;  // each part's lead
    std::string files;               // the Files: paragraph
};

Sheet read_sheet(const fs::path& path) {
    static const std::regex item(R"(^[0-9]+\. (.*))");
    Sheet sheet;
    std::string* open = nullptr;  // the paragraph being read
    bool in_section = false, numbered = false;
    std::smatch m;
    for (const std::string& line : read_lines(path)) {
        const bool blank = line.find_first_not_of(' ') == std::string::npos;
        if (starts_with(line, "## ")) in_section = line == "## What you implement";
        if (blank || starts_with(line, "#") || std::regex_match(line, item)) open = nullptr;
        if (starts_with(line, "Files:")) open = &sheet.files;
        if (in_section && std::regex_match(line, m, item)) {
            if (!numbered) sheet.parts.clear();
            numbered = true;
            sheet.parts.push_back(m[1].str());
            open = &sheet.parts.back();
        } else if (in_section && !numbered && sheet.parts.empty() && starts_with(line, "**")) {
            sheet.parts.push_back(line);
            open = &sheet.parts.back();
        } else if (open && !blank) {
            *open += (open->empty() ? "" : " ") + line.substr(line.find_first_not_of(' '));
        }
    }
    for (std::string& part : sheet.parts) {
        bool code = false;
        for (size_t i = 0; i < part.size(); ++i) {
            code = code != (part[i] == '`');
            if (!code && (part[i] == ':' || part[i] == '.') &&
                (i + 1 == part.size() || part[i + 1] == ' ')) {
                part.resize(i);
                break;
            }
        }
    }
    return sheet;
}

// The file names in backticks of `text` (an extension of a source, a shader or an image).
std::vector<std::string> named_files(const std::string& text) {
    static const std::regex name(
        R"(`([A-Za-z0-9_./*-]+\.(cpp|hpp|vert|frag|geom|tesc|tese|comp|glsl|png))`)");
    std::vector<std::string> out;
    for (auto it = std::sregex_iterator(text.begin(), text.end(), name);
         it != std::sregex_iterator(); ++it)
        out.push_back((*it)[1].str());
    return out;
}

// The repository paths that a sheet's `name` stands for (a `*` matches any part of a name).
std::vector<std::string> resolved(const Repo& repo, const std::string& dir,
                                  const std::string& name) {
    std::vector<std::string> candidates = {name};
    if (name.find('/') == std::string::npos)
        candidates = {"labs/" + dir + "/" + name, "shaders/" + dir + "/" + name};
    std::vector<std::string> out;
    for (const std::string& c : candidates) {
        std::string pattern;
        for (const char ch : c)
            pattern += ch == '*' ? std::string("[^/]*")
                       : std::string(".^$|()[]{}+?\\").find(ch) != std::string::npos
                           ? std::string("\\") + ch
                           : std::string(1, ch);
        const std::regex re(pattern);
        for (const std::string& p : repo.all)
            if (std::regex_match(p, re)) out.push_back(p);
    }
    return out;
}

// The files of lab `dir` with a `// STUDENT:` line that holds a TODO (its tests and grading
// references left out: docs/conventions.md, Student parts).
std::set<std::string> todo_files(const Repo& repo, const std::string& dir) {
    std::set<std::string> out;
    for (const std::string& f : repo.files) {
        if (!starts_with(f, "labs/" + dir + "/") && !starts_with(f, "shaders/" + dir + "/"))
            continue;
        if (f.find("/tests/") != std::string::npos || f.find("/grading/") != std::string::npos)
            continue;
        for (const std::string& line : read_lines(repo.root / f)) {
            const size_t at = line.find("// STUDENT:");
            if (at != std::string::npos && line.find("TODO", at) != std::string::npos) {
                out.insert(f);
                break;
            }
        }
    }
    return out;
}

std::vector<Problem> one_sheet_problems(const Repo& repo, const std::string& dir, size_t& parts) {
    const std::string sheet_path = "labs/" + dir + "/README.md";
    const Sheet sheet = read_sheet(repo.root / sheet_path);
    const std::set<std::string> todos = todo_files(repo, dir);
    std::vector<Problem> out;
    auto problem = [&](const std::string& what) { out.push_back({sheet_path, what}); };
    if (sheet.parts.empty()) problem("no parts under \"## What you implement\"");
    if (sheet.files.empty()) problem("no paragraph that opens with \"Files:\"");
    std::set<std::string> in_parts, in_files;
    std::vector<std::string> previous;  // the files the part before names
    for (size_t n = 0; n < sheet.parts.size(); ++n) {
        ++parts;
        const std::string part = "part " + std::to_string(n + 1) + " (" + sheet.parts[n] + ")";
        std::vector<std::string> names = named_files(sheet.parts[n]);
        // A part that names no file is written in the file of the part
        // before it (lab 8's sampler state: units, wraps, filters, mipmaps
        // and the two maps, one file).
        if (names.empty()) names = previous;
        if (names.empty())
            problem(part +
                    " names no file before its first `:` or `.`, and no part before it "
                    "does: name the file that holds its TODO, then the function");
        previous = names;
        for (const std::string& name : names) {
            const std::vector<std::string> paths = resolved(repo, dir, name);
            if (paths.empty()) problem(part + " names `" + name + "`, which does not exist");
            for (const std::string& p : paths) {
                in_parts.insert(p);
                if (!todos.count(p))
                    problem(part + " names " + p +
                            ", which has no `// STUDENT:` line with a TODO; name the file "
                            "that holds the part");
            }
        }
    }
    for (const std::string& name : named_files(sheet.files)) {
        const std::vector<std::string> paths = resolved(repo, dir, name);
        if (paths.empty()) problem("Files: names `" + name + "`, which does not exist");
        in_files.insert(paths.begin(), paths.end());
    }
    for (const std::string& f : todos) {
        if (!in_parts.count(f))
            problem(f + " has a TODO in a `// STUDENT:` line, and no part names it");
        if (!in_files.count(f))
            problem(f + " has a TODO in a `// STUDENT:` line, and the Files: list leaves it out");
    }
    return out;
}

std::vector<Problem> sheet_problems(const Repo& repo, size_t& sheets, size_t& parts) {
    std::vector<Problem> out;
    for (const std::string& f : repo.all) {
        static const std::regex sheet("labs/([0-9][0-9]_[a-z0-9_]+)/README\\.md");
        std::smatch m;
        if (!std::regex_match(f, m, sheet)) continue;
        ++sheets;
        const std::vector<Problem> here = one_sheet_problems(repo, m[1].str(), parts);
        out.insert(out.end(), here.begin(), here.end());
    }
    return out;
}

const Repo& repo() {
    static const Repo r = read_repo(fw::test::source_dir());
    return r;
}

void report(const std::vector<Problem>& problems) {
    for (const Problem& p : problems) FAIL_CHECK(p.where << ": " << p.what);
}

}  // namespace

TEST_CASE("grading's rooms include only their own room and the rooms below it") {
    MESSAGE(
        "rooms, lowest first: sandbox results run units diagnosis judge report release "
        "platforms commands class; grading/main.cpp includes any; labs/NN_name/grading/*.cpp "
        "only units");
    REQUIRE(repo().files.size() > 100);
    report(room_problems(repo()));
}

TEST_CASE("the judge includes of the diagnosis only its interface, diagnosis.hpp") {
    size_t judge_files = 0;
    const std::vector<Problem> problems = interface_problems(repo(), judge_files);
    MESSAGE(judge_files << " files of grading/judge/; its door into grading/diagnosis/: "
                        << kDiagnosisInterface);
    CHECK(judge_files > 10);
    CHECK(std::find(repo().files.begin(), repo().files.end(), kDiagnosisInterface) !=
          repo().files.end());
    report(problems);
}

TEST_CASE("the GL wrapper students read names nothing of what observes it") {
    // framework/gl/ includes its own files and three plain ones of the
    // framework; the record and the usage checks (framework/trace/) attach
    // through glad's hooks (docs/architecture.md).
    static const std::set<std::string> plain = {"framework/error.hpp", "framework/image.hpp",
                                                "framework/text.hpp"};
    static const std::regex observer(R"(framework/trace|gl_record|gl_usage|gl_calls)");
    std::vector<Problem> problems;
    size_t files = 0;
    for (const std::string& f : repo().files) {
        if (!starts_with(f, "framework/gl/")) continue;
        ++files;
        for (const auto& [line, inc] : quoted_includes(repo().root / f))
            if (!starts_with(inc, "framework/gl/") && !plain.count(inc))
                problems.push_back({f + ":" + std::to_string(line),
                                    "includes \"" + inc + "\"; the wrapper includes only its " +
                                        "own files, framework/error.hpp, image.hpp and text.hpp"});
        const std::vector<std::string> lines = read_lines(repo().root / f);
        for (size_t i = 0; i < lines.size(); ++i)
            if (std::regex_search(lines[i], observer))
                problems.push_back({f + ":" + std::to_string(i + 1),
                                    "names what observes GL; it belongs in framework/trace/"});
    }
    MESSAGE(files << " files of framework/gl/");
    CHECK(files > 20);
    report(problems);
}

TEST_CASE("framework and grading headers include no cycle") {
    size_t headers = 0;
    const std::vector<Problem> problems = cycle_problems(repo(), headers);
    MESSAGE(headers << " headers of framework/ and grading/");
    CHECK(headers > 20);
    report(problems);
}

TEST_CASE("every repository path cited in a comment or a Markdown page exists") {
    size_t cited = 0, in_checkpoints = 0;
    const std::vector<Problem> problems = path_problems(repo(), cited, in_checkpoints);
    MESSAGE(cited << " paths cited, " << in_checkpoints << " in checkpoints.json comments");
    CHECK(cited > 100);
    CHECK(in_checkpoints >= 11);  // each lab's file cites its format, framework/checkpoints.hpp
    report(problems);
}

TEST_CASE("every docs section cited in a comment or a Markdown page is there") {
    size_t cited = 0;
    const std::vector<Problem> problems = heading_problems(repo(), cited);
    MESSAGE(cited << " sections cited");
    CHECK(cited > 20);
    report(problems);
}

TEST_CASE("functions and files keep to the sizes of docs/conventions.md") {
    size_t functions = 0;
    const std::vector<Problem> problems = size_problems(repo(), functions);
    MESSAGE(functions << " functions of framework/, grading/ and the labs measured");
    CHECK(functions > 300);
    report(problems);
}

TEST_CASE("a lab's files with student parts hold neither the lab's class nor JSON") {
    size_t student_files = 0;
    const std::vector<Problem> problems = student_file_problems(repo(), student_files);
    MESSAGE(student_files << " lab files with student parts");
    CHECK(student_files > 10);
    report(problems);
}

TEST_CASE("each lab sheet's parts name the files that hold their TODOs, and Files: lists them") {
    size_t sheets = 0, parts = 0;
    const std::vector<Problem> problems = sheet_problems(repo(), sheets, parts);
    MESSAGE(sheets << " lab sheets, " << parts << " parts");
    CHECK(sheets >= 7);
    CHECK(parts > 40);
    report(problems);
}

// A sheet's checkpoint table (the one whose header starts "| checkpoint |")
// lists the lab's visible checkpoints, in the file's order: a student reads
// there what the grader runs.
TEST_CASE("each lab sheet's checkpoint table lists the visible checkpoints, in order") {
    const fs::path root = fw::test::source_dir();
    int labs = 0;
    for (const auto& entry : fs::directory_iterator(root / "labs")) {
        const fs::path sheet = entry.path() / "README.md", data = entry.path() / "checkpoints.json";
        if (!fs::exists(sheet) || !fs::exists(data)) continue;
        ++labs;
        std::vector<std::string> expected, listed;
        for (const fw::Checkpoint& cp : fw::read_checkpoint_file(data.string()).checkpoints)
            if (cp.visibility == "visible") expected.push_back(cp.name);
        std::istringstream lines(fw::test::read_text(sheet));
        bool in_table = false;
        for (std::string line; std::getline(lines, line);) {
            if (line.rfind("| checkpoint |", 0) == 0) {
                in_table = true;
                continue;
            }
            if (!in_table) continue;
            if (line.rfind("|-", 0) == 0) continue;
            if (line.rfind("| `", 0) != 0) break;
            listed.push_back(line.substr(3, line.find('`', 3) - 3));
        }
        INFO(sheet.string() << ": its checkpoint table against checkpoints.json's visible ones");
        CHECK(listed == expected);
    }
    CHECK(labs >= 7);
}
