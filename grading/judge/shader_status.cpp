// A lab's status line when its programs did not all build: the files the
// child's child.json names (checks.hpp, shader_error_status).
#include <algorithm>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/text.hpp"
#include "grading/judge/checks.hpp"

namespace grading {

using nlohmann::json;

std::string shader_error_status(const ChildOutputs& outputs) {
    std::string bytes, why;
    if (!outputs.read("child.json", 256 * 1024, bytes, why)) return {};
    const json child = json::parse(bytes, nullptr, /*allow_exceptions=*/false);
    if (!child.is_object() || !child.contains("shader_errors") ||
        !child["shader_errors"].is_array())
        return {};
    // The child's word, used only for this status line: never for a score.
    std::vector<std::string> files;
    for (const json& e : child["shader_errors"]) {
        if (!e.is_object() || !e.contains("file") || !e["file"].is_string()) continue;
        std::string file = e["file"];
        if (file.size() > 200) file = file.substr(0, 200) + "...";
        if (std::find(files.begin(), files.end(), file) == files.end()) files.push_back(file);
    }
    if (files.empty()) return {};
    const size_t shown = std::min<size_t>(files.size(), 4);
    std::string text =
        "shader error in " +
        fw::join(std::vector<std::string>(files.begin(), files.begin() + shown), ", ");
    if (files.size() > shown) text += " and " + std::to_string(files.size() - shown) + " more";
    return text;
}

}  // namespace grading
