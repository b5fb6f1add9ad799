// What course takes from the child's child.json: the files of its programs
// that did not build, for the lab's status line (checks.hpp,
// shader_error_status), and where its time went (child_seconds).
#include <algorithm>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/text.hpp"
#include "grading/judge/checks.hpp"

namespace grading {

using nlohmann::json;

namespace {

json child_json(const ChildOutputs& outputs) {
    std::string bytes, why;
    if (!outputs.read("child.json", 256 * 1024, bytes, why)) return {};
    return json::parse(bytes, nullptr, /*allow_exceptions=*/false);
}

}  // namespace

void child_seconds(const ChildOutputs& outputs, LabTime& time) {
    const json child = child_json(outputs);
    if (!child.is_object() || !child.contains("seconds") || !child["seconds"].is_object()) return;
    const json& s = child["seconds"];
    // The child's word, used only for course grade --verbose's time table.
    auto take = [&s](const char* key, double& to) {
        if (s.contains(key) && s[key].is_number()) to = s[key].get<double>();
    };
    take("units", time.child_units);
    take("start", time.child_start);
    take("render", time.child_render);
    take("record", time.child_record);
    take("usage", time.child_usage);
}

std::string shader_error_status(const ChildOutputs& outputs) {
    const json child = child_json(outputs);
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
