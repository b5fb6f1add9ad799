#include "grading/judge/judge_source.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "framework/text.hpp"
#include "grading/diagnosis/diagnosis.hpp"

namespace grading {

namespace {

bool is_name_char(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
           c == ':';
}

}  // namespace

std::vector<int> lines_using(const std::string& text, const std::string& name) {
    const std::string code = code_only(text);
    std::vector<int> lines;
    for (size_t at = code.find(name); at != std::string::npos; at = code.find(name, at + 1)) {
        const bool starts = at == 0 || !is_name_char(code[at - 1]);
        const size_t after = at + name.size();
        const bool ends =
            after >= code.size() || !is_name_char(code[after]) || !is_name_char(name.back());
        if (!starts || !ends) continue;
        const int line = 1 + static_cast<int>(std::count(code.begin(), code.begin() + at, '\n'));
        if (lines.empty() || lines.back() != line) lines.push_back(line);
    }
    return lines;
}

void judge_forbidden(const LabData& lab, const ForbiddenCheck& check, const LabStatus& lab_status,
                     CheckResult& result) {
    const size_t others = check.names.size() - 1;
    result.title = "source without " + check.names.front();
    if (others > 0) result.title += " and " + std::to_string(others) + " other names";
    if (!lab_status.ok()) {
        result.passed = false;
        result.score = 0.0;
        result.output = "Not judged: the lab did not run to its end (" + lab_status.text() +
                        "); the source is judged only beside a lab that runs.";
        return;
    }
    std::string found;
    for (const std::string& file : check.files) {
        std::ifstream in(std::filesystem::path(lab.sources) / file, std::ios::binary);
        if (!in) {
            found += file + ": cannot be read; check that it exists and is readable\n";
            continue;
        }
        std::ostringstream text;
        text << in.rdbuf();
        for (const std::string& name : check.names)
            for (int line : lines_using(text.str(), name))
                found += file + ":" + std::to_string(line) + " uses " + name + "\n";
    }
    result.passed = found.empty();
    result.score = result.passed ? result.max_score : 0.0;
    result.output = result.passed ? "None of " + fw::join(check.names, ", ") + " in " +
                                        fw::join(check.files, ", ") + "."
                                  : "The sheet says: " + check.rule + "\n" + found;
}

}  // namespace grading
