// `portable` checks (judge_portable.hpp).
#include "grading/judge/judge_portable.hpp"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "framework/error.hpp"

namespace grading {

namespace {

using nlohmann::json;

// Findings a check's output shows; the rest are counted.
constexpr size_t kShown = 8;
// Characters of one string of the child's a report shows.
constexpr size_t kLongest = 600;

std::string cut(const std::string& s) {
    return s.size() > kLongest ? s.substr(0, kLongest) + "..." : s;
}

UsageFinding parse_finding(const json& entry, size_t i, const std::string& file) {
    const std::string where = file + ": finding " + std::to_string(i);
    if (!entry.is_object())
        throw fw::Error(where + " is not an object {\"rule\", \"call\", \"draw\", \"detail\"}");
    UsageFinding f;
    for (const char* field : {"rule", "call", "detail"}) {
        if (!entry.contains(field) || !entry[field].is_string())
            throw fw::Error(where + ": \"" + field + "\" must be a string");
    }
    f.rule = cut(entry["rule"]);
    f.call = cut(entry["call"]);
    f.detail = cut(entry["detail"]);
    if (!entry.contains("draw") || !entry["draw"].is_number_integer())
        throw fw::Error(where + ": \"draw\" must be an integer");
    f.draw = entry["draw"].get<long long>();
    if (entry.contains("times")) {
        if (!entry["times"].is_number_integer())
            throw fw::Error(where + ": \"times\" must be an integer");
        f.times = std::max(1LL, entry["times"].get<long long>());
    }
    return f;
}

// "call 2 of the checkpoint (glDrawArrays): the buffer ... (3 times)".
std::string line(const UsageFinding& f) {
    return "call " + std::to_string(f.draw) + " of the checkpoint (" + f.call + "): " + f.detail +
           (f.times > 1 ? " (" + std::to_string(f.times) + " times)" : "");
}

void verdict(CheckResult& r, bool pass, const std::string& output) {
    r.passed = pass;
    r.score = pass ? r.max_score : 0.0;
    r.output = output;
}

}  // namespace

bool read_usage(const ChildOutputs& outputs, const std::string& checkpoint,
                std::vector<UsageFinding>& findings, std::string& why) {
    const std::string name = checkpoint + ".usage.json";
    std::string bytes;
    try {
        if (!outputs.read(name, kUsageFileLimit, bytes, why)) throw fw::Error(why);
        // From the bytes read (and size-checked), never from the file again.
        const json doc = json::parse(bytes, nullptr, /*allow_exceptions=*/false);
        if (!doc.is_array()) throw fw::Error(name + " is not a JSON list of findings");
        findings.clear();
        for (size_t i = 0; i < doc.size(); ++i) findings.push_back(parse_finding(doc[i], i, name));
    } catch (const fw::Error& e) {
        why = "no record of the GL usage: " + std::string(e.what());
        return false;
    }
    return true;
}

void judge_portable(const std::vector<UsageFinding>* findings, const std::string& why,
                    bool rendered, const std::string& render_why, CheckResult& r) {
    r.title = "GL usage a GPU accepts";
    const std::string expected =
        "Expected: no GL usage that the GL 4.3 specification leaves undefined or forbids, "
        "which llvmpipe lets pass and a GPU does not: a glMemoryBarrier between a dispatch's "
        "writes and what reads them, every clip distance written enabled, complete textures, "
        "no buffer captured and read by one draw, samplers set to units 0 to N-1, no "
        "invocation writing past the count (a checkpoint's calls are its draws, dispatches and "
        "read-backs, counted from 1)\nObserved: ";
    if (!findings) return verdict(r, false, expected + why);
    if (findings->empty())
        return rendered ? verdict(r, true, expected + "none")
                        : verdict(r, false,
                                  expected + "none up to where the render failed: " + render_why);
    std::vector<std::string> lines;
    for (size_t i = 0; i < std::min(findings->size(), kShown); ++i)
        lines.push_back(line((*findings)[i]));
    if (findings->size() > kShown)
        lines.push_back("and " + std::to_string(findings->size() - kShown) + " more");
    // The first in the Observed line (the terminal's line), the others below it.
    std::string rest;
    for (size_t i = 1; i < lines.size(); ++i) rest += (i > 1 ? "\n" : "") + lines[i];
    r.diagnosis = rest;
    verdict(r, false, expected + lines[0] + (rest.empty() ? "" : "\n" + rest));
}

}  // namespace grading
