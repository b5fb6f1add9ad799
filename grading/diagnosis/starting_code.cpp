#include "grading/diagnosis/starting_code.hpp"

#include <cctype>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "framework/error.hpp"
#include "grading/diagnosis/solution_blocks.hpp"

namespace grading {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr const char* kBeginMarker = "// BEGIN SOLUTION";

bool name_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

std::optional<std::string> read_text(const fs::path& path) {
    std::error_code ec;
    if (!fs::is_regular_file(path, ec)) return std::nullopt;
    std::ifstream in(path, std::ios::binary);
    if (!in) return std::nullopt;
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

// The index just past the bracket that closes the one at `open`, or npos.
size_t closing(const std::string& code, size_t open, char left, char right) {
    int depth = 0;
    for (size_t i = open; i < code.size(); ++i) {
        if (code[i] == left) ++depth;
        if (code[i] == right && --depth == 0) return i + 1;
    }
    return std::string::npos;
}

// `code` without the whitespace a formatter may change: a space is kept
// only where it separates two names or numbers ("return order").
std::string squeezed(const std::string& code) {
    std::string out;
    bool gap = false;
    for (char c : code) {
        if (std::isspace(static_cast<unsigned char>(c))) {
            gap = true;
            continue;
        }
        if (gap && !out.empty() && name_char(out.back()) && name_char(c)) out += ' ';
        gap = false;
        out += c;
    }
    return out;
}

bool has_blocks(const std::string& text) { return text.find(kBeginMarker) != std::string::npos; }

// Blanks text[from, to) but its newlines.
void blank(std::string& text, size_t from, size_t to) {
    for (size_t i = from; i < to && i < text.size(); ++i)
        if (text[i] != '\n') text[i] = ' ';
}

// The end of the literal that starts with the quote at `i` (past its closing
// quote, or the end of the line where it is not closed).
size_t literal_end(const std::string& t, size_t i) {
    const char quote = t[i];
    for (size_t j = i + 1; j < t.size(); ++j) {
        if (t[j] == '\\') {
            ++j;
            continue;
        }
        if (t[j] == quote || t[j] == '\n') return j + 1;
    }
    return t.size();
}

}  // namespace

std::string code_only(const std::string& text) {
    std::string t = text;
    for (size_t i = 0; i < t.size();) {
        if (t.compare(i, 2, "//") == 0) {
            const size_t end = t.find('\n', i);
            blank(t, i, end == std::string::npos ? t.size() : end);
            i = end == std::string::npos ? t.size() : end;
        } else if (t.compare(i, 2, "/*") == 0) {
            const size_t close = t.find("*/", i + 2);
            const size_t end = close == std::string::npos ? t.size() : close + 2;
            blank(t, i, end);
            i = end;
        } else if (t[i] == '"' ||
                   (t[i] == '\'' &&
                    !(i > 0 && std::isxdigit(static_cast<unsigned char>(t[i - 1]))))) {
            // (A ' after a digit separates digits: 1'000.)
            const size_t end = literal_end(t, i);
            blank(t, i, end);
            i = end;
        } else {
            ++i;
        }
    }
    return t;
}

std::vector<PartPlace> read_parts(const fw::CheckpointFile& file) {
    std::vector<PartPlace> places;
    for (size_t i = 0; i < file.parts.size(); ++i) {
        const json& p = file.parts[i];
        const std::string where = file.path + ": parts[" + std::to_string(i) + "]: ";
        const bool ok = p.is_object() && p.contains("part") && p["part"].is_number_unsigned() &&
                        p["part"].get<int>() >= 1 && p.contains("file") && p["file"].is_string() &&
                        p.contains("function") && p["function"].is_string() && p.size() == 3;
        if (!ok)
            throw fw::UsageError(where +
                                 "expected {\"part\": N (1, 2, ...), \"file\": a path in the "
                                 "repository, \"function\": its name}");
        PartPlace place{p["part"].get<int>(), p["file"].get<std::string>(),
                        p["function"].get<std::string>(), ""};
        const fs::path rel(place.file);
        if (place.file.empty() || rel.is_absolute() || place.file.find("..") != std::string::npos)
            throw fw::UsageError(where + "\"file\" must be a path inside the repository");
        if (place.function.empty() || std::find_if_not(place.function.begin(), place.function.end(),
                                                       name_char) != place.function.end())
            throw fw::UsageError(where + "\"function\" must be a name, as \"back_to_front\"");
        places.push_back(std::move(place));
    }
    for (const fw::Checkpoint& cp : file.checkpoints)
        for (int n : cp.parts) {
            bool known = false;
            for (const PartPlace& p : places) known = known || p.part == n;
            if (!known)
                throw fw::UsageError(file.path + ": checkpoint '" + cp.name + "' needs part " +
                                     std::to_string(n) +
                                     ", which the file's \"parts\" does not place");
        }
    return places;
}

std::optional<std::string> function_body(const std::string& text, const std::string& function) {
    const std::string code = code_only(text);
    for (size_t at = code.find(function); at != std::string::npos;
         at = code.find(function, at + 1)) {
        const size_t after = at + function.size();
        if ((at > 0 && name_char(code[at - 1])) || after >= code.size()) continue;
        // A definition starts a line: its first character is not indented.
        const size_t line = code.rfind('\n', at);
        const size_t start = line == std::string::npos ? 0 : line + 1;
        if (std::isspace(static_cast<unsigned char>(code[start]))) continue;
        size_t open = after;
        while (open < code.size() && std::isspace(static_cast<unsigned char>(code[open]))) ++open;
        if (open >= code.size() || code[open] != '(') continue;
        const size_t params = closing(code, open, '(', ')');
        if (params == std::string::npos) return std::nullopt;
        const size_t brace = code.find_first_of("{;", params);
        if (brace == std::string::npos) return std::nullopt;
        if (code[brace] == ';') continue;  // a declaration
        const size_t end = closing(code, brace, '{', '}');
        if (end == std::string::npos) return std::nullopt;
        return squeezed(code.substr(brace, end - brace));
    }
    return std::nullopt;
}

std::optional<std::string> starting_version(const std::string& root, const std::string& file) {
    if (const std::optional<std::string> staff = read_text(fs::path(root) / file);
        staff && has_blocks(*staff)) {
        try {
            return student_text(*staff, file);
        } catch (const fw::Error&) {
            return std::nullopt;  // `course release` says what is wrong with the markers
        }
    }
    return read_text(fs::path(root) / "student_versions" / file);
}

std::string starting_hash(const std::string& body) {
    std::uint64_t h = 14695981039346656037ull;
    for (unsigned char c : body) {
        h ^= c;
        h *= 1099511628211ull;
    }
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
    return hex;
}

std::string starting_file(const std::string& lab_dir) {
    return "labs/" + lab_dir + "/grading/starting.json";
}

std::string starting_file_text(const std::string& root, const std::vector<PartPlace>& places) {
    json entries = json::array();
    for (const PartPlace& p : places) {
        const std::optional<std::string> start = starting_version(root, p.file);
        const std::optional<std::string> body =
            start ? function_body(*start, p.function) : std::nullopt;
        if (body)
            entries.push_back({{"part", p.part},
                               {"file", p.file},
                               {"function", p.function},
                               {"fnv1a64", starting_hash(*body)}});
    }
    return json{{"parts", entries}}.dump() + "\n";
}

void read_starting_file(const std::string& root, const std::string& lab_dir,
                        std::vector<PartPlace>& places) {
    const std::string rel = starting_file(lab_dir);
    const std::optional<std::string> text = read_text(fs::path(root) / rel);
    if (!text) return;
    const std::string expected =
        ": expected {\"parts\": [{\"part\": N, \"file\": F, \"function\": NAME, "
        "\"fnv1a64\": 16 hexadecimal digits}, ...]}, as `course release` writes it";
    json doc;
    try {
        doc = json::parse(*text);
    } catch (const json::parse_error& e) {
        throw fw::UsageError(rel + ": not valid JSON (" + e.what() + ")" + expected);
    }
    if (!doc.is_object() || !doc.contains("parts") || !doc["parts"].is_array())
        throw fw::UsageError(rel + expected);
    const auto hex = [](const json& h) {
        return h.is_string() && h.get<std::string>().size() == 16 &&
               h.get<std::string>().find_first_not_of("0123456789abcdef") == std::string::npos;
    };
    for (size_t i = 0; i < doc["parts"].size(); ++i) {
        const json& e = doc["parts"][i];
        if (!e.is_object() || !e.contains("part") || !e["part"].is_number_unsigned() ||
            !e.contains("file") || !e["file"].is_string() || !e.contains("function") ||
            !e["function"].is_string() || !e.contains("fnv1a64") || !hex(e["fnv1a64"]))
            throw fw::UsageError(rel + ": parts[" + std::to_string(i) + "]" + expected);
        for (PartPlace& p : places)
            if (p.part == e["part"].get<int>() && p.file == e["file"].get<std::string>() &&
                p.function == e["function"].get<std::string>())
                p.start = e["fnv1a64"].get<std::string>();
    }
}

bool still_starting(const std::string& root, const std::string& sources, const PartPlace& place) {
    const std::optional<std::string> mine = read_text(fs::path(sources) / place.file);
    const std::optional<std::string> body =
        mine ? function_body(*mine, place.function) : std::nullopt;
    if (!body) return false;
    if (const std::optional<std::string> start = starting_version(root, place.file))
        return function_body(*start, place.function) == body;
    return !place.start.empty() && starting_hash(*body) == place.start;
}

std::string starting_code_sentence(const std::string& root, const std::string& sources,
                                   const std::vector<PartPlace>& places,
                                   const std::vector<int>& needed, const std::string& function) {
    for (int n : needed)
        for (const PartPlace& p : places)
            if (p.part == n && (function.empty() || p.function == function) &&
                still_starting(root, sources, p))
                return "Part " + std::to_string(n) + " (`" + p.function + "()` in " + p.file +
                       ") still has its starting code; this checkpoint needs it.";
    return "";
}

void say_starting_code(const std::string& sentence, std::vector<CheckResult>& results) {
    if (sentence.empty()) return;
    CheckResult* first = nullptr;
    for (CheckResult& r : results) {
        if (r.passed) continue;
        if (r.diagnosis.find(sentence) != std::string::npos) return;
        if (!first) first = &r;
    }
    if (!first) return;
    first->diagnosis = first->diagnosis.empty() ? sentence : sentence + "\n" + first->diagnosis;
    first->output += "\n" + sentence;
}

void check_part_places(const std::string& root, const std::string& checkpoints_file,
                       const std::vector<PartPlace>& places) {
    for (const PartPlace& p : places) {
        const std::optional<std::string> staff = read_text(fs::path(root) / p.file);
        if (!staff || !has_blocks(*staff)) continue;  // a student's copy: nothing to check
        const std::string where = checkpoints_file + ": part " + std::to_string(p.part) + ": ";
        const std::optional<std::string> solution = function_body(*staff, p.function);
        const std::optional<std::string> start = starting_version(root, p.file);
        if (!solution) throw fw::UsageError(where + p.file + " defines no function " + p.function);
        if (!start || function_body(*start, p.function) == solution)
            throw fw::UsageError(where + p.function + "() in " + p.file +
                                 " has no solution block: its starting code is the solution");
    }
}

}  // namespace grading
