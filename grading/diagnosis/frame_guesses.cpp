#include "grading/diagnosis/frame_guesses.hpp"

#include <algorithm>
#include <set>

#include "framework/text.hpp"
#include "grading/diagnosis/known_mistakes.hpp"

namespace grading {

namespace {

constexpr const char* kShaders = "shaders/";

// The function a unit check's title names: "unit NAME (N cases)".
std::string unit_function(const CheckResult& r) {
    const std::string lead = "unit ";
    if (r.kind != CheckKind::Unit || r.title.rfind(lead, 0) != 0) return "";
    const size_t end = r.title.find(" (", lead.size());
    return r.title.substr(lead.size(), end == std::string::npos ? end : end - lead.size());
}

// Whether each unit-checked function of the lab passes every check of it.
std::map<std::string, bool> unit_passes(const std::vector<CheckResult>& results) {
    std::map<std::string, bool> passes;
    for (const CheckResult& r : results) {
        const std::string f = unit_function(r);
        if (f.empty()) continue;
        auto [it, inserted] = passes.emplace(f, r.passed);
        if (!inserted) it->second = it->second && r.passed;
    }
    return passes;
}

// `text` without the lines of `lines` (each once).
std::string without_lines(const std::string& text, const std::vector<std::string>& lines) {
    std::string out = text;
    for (const std::string& line : lines) {
        const size_t at = out.find(line);
        if (at == std::string::npos) continue;
        size_t from = at, to = at + line.size();
        if (from > 0 && out[from - 1] == '\n')
            --from;
        else if (to < out.size() && out[to] == '\n')
            ++to;
        out.erase(from, to - from);
    }
    return out;
}

void append_line(std::string& text, const std::string& line) {
    text += (text.empty() ? "" : "\n") + line;
}

const MistakeFrame* frame_named(const LabFiles& lab, const std::string& checkpoint,
                                const std::string& image) {
    const auto known = lab.mistake_frames.find(checkpoint);
    if (known == lab.mistake_frames.end()) return nullptr;
    for (const MistakeFrame& f : known->second)
        if (f.image == image) return &f;
    return nullptr;
}

const fw::Checkpoint* checkpoint_named(const LabFiles& lab, const std::string& name) {
    for (const fw::Checkpoint& cp : lab.file.checkpoints)
        if (cp.name == name) return &cp;
    return nullptr;
}

std::string file_name(const std::string& path) {
    const size_t slash = path.rfind('/');
    return slash == std::string::npos ? path : path.substr(slash + 1);
}

// A parameter's value as the sentence shows it.
std::string value_text(const nlohmann::json* value) {
    if (!value) return "the default";
    if (value->is_number_float()) return fw::number_text(value->get<double>(), 6);
    return value->dump();
}

// The checkpoint's value of parameter `name`, or null for the lab's default.
const nlohmann::json* param(const fw::Checkpoint& checkpoint, const std::string& name) {
    return checkpoint.params.contains(name) ? &checkpoint.params.at(name) : nullptr;
}

// The names of the parameters whose values differ.
std::vector<std::string> differences(const fw::Checkpoint& here, const fw::Checkpoint& there) {
    std::set<std::string> names;
    for (const auto& [name, value] : here.params.items()) names.insert(name);
    for (const auto& [name, value] : there.params.items()) names.insert(name);
    std::vector<std::string> out;
    for (const std::string& name : names) {
        const nlohmann::json *a = param(here, name), *b = param(there, name);
        if (!(a && b && *a == *b)) out.push_back(name);
    }
    return out;
}

}  // namespace

std::string checkpoint_match_sentence(const LabFiles& lab, const fw::Checkpoint& checkpoint,
                                      const std::string& other_name) {
    const fw::Checkpoint* found = nullptr;
    for (const fw::Checkpoint& c : lab.file.checkpoints)
        if (c.name == other_name) found = &c;
    if (!found) return "";
    const fw::Checkpoint& other = *found;
    const std::vector<std::string> differ = differences(checkpoint, other);
    const std::string text = "Your frame is the one checkpoint " + other.name + " expects";
    if (differ.empty())
        return text + " (" + other.description + "): compare what the two checkpoints ask.";
    if (differ.size() == 1) {
        const std::string& name = differ.front();
        const std::string here = value_text(param(checkpoint, name)),
                          there = value_text(param(other, name));
        return text + " (" + name + " " + there + ", here " + here +
               "): your code most likely treats " + name + " " + here + " as " + there + ".";
    }
    std::vector<std::string> pairs;
    for (const std::string& name : differ) {
        const nlohmann::json *here = param(checkpoint, name), *there = param(other, name);
        pairs.push_back(name + " (" + value_text(there) + " there, " + value_text(here) + " here)");
    }
    return text + ", which differs from " + checkpoint.name + " in " + fw::join(pairs, ", ") +
           ": your code most likely ignores these parameters or mixes them up.";
}

std::string ruled_out(const KnownMistake& mistake, const CheckResult::FrameGuess& guess,
                      const std::map<std::string, bool>& unit_passes,
                      const FrameIsolation* isolation) {
    // The unit checks: those that fail here are those that fail under it.
    if (mistake.units) {
        const std::vector<std::string>& fails = *mistake.units;
        for (const std::string& f : fails) {
            const auto it = unit_passes.find(f);
            if (it != unit_passes.end() && it->second)
                return "your `" + f + "()` passes its unit check, which " + mistake.id + " fails";
        }
        for (const auto& [f, passed] : unit_passes)
            if (!passed && std::find(fails.begin(), fails.end(), f) == fails.end())
                return "your `" + f + "()` fails its unit check, which " + mistake.id + " passes";
    }
    // The state diff: it says something else here than of the mistake.
    if (mistake.state && guess.state_compared && *mistake.state != guess.state) {
        if (guess.state.empty())
            return "your draws are told the state the solution's are, and those of " + mistake.id +
                   " are not";
        if (mistake.state->empty())
            return "the state diff names a state of your draws that " + mistake.id +
                   " leaves as the solution has it";
        return "the state diff names another state of your draws than that of " + mistake.id;
    }
    // File isolation: another file puts the frame right, or its own does not.
    if (isolation && !mistake.file.empty()) {
        const bool in_shader = mistake.file.rfind(kShaders, 0) == 0;
        const std::string own = in_shader ? mistake.file.substr(std::string(kShaders).size()) : "";
        if (!isolation->puts_right.empty() && isolation->puts_right != own)
            return "the frame is right with the course's `" + file_name(isolation->puts_right) +
                   "` in place of yours, and " + mistake.id + " is in " + mistake.file;
        if (in_shader && isolation->replaced.count(own) && isolation->puts_right != own)
            return "your frame stays wrong with the course's `" + file_name(own) +
                   "` in place of yours, and " + mistake.id + " is in it";
    }
    return "";
}

void say_frame_guesses(const LabFiles& lab, std::vector<CheckResult>& results,
                       const FrameIsolations* isolations) {
    const std::map<std::string, bool> units = unit_passes(results);
    bool unit_fails = false;
    for (const auto& [f, passed] : units) unit_fails = unit_fails || !passed;
    for (CheckResult& r : results) {
        CheckResult::FrameGuess& g = r.guess;
        if (g.mistake_image.empty() && g.checkpoint.empty()) continue;
        r.output = without_lines(r.output, g.lines);
        r.diagnosis = without_lines(r.diagnosis, g.lines);
        g.lines.clear();
        const fw::Checkpoint* here = checkpoint_named(lab, r.checkpoint);
        if (!here) continue;
        const FrameIsolation* isolation = nullptr;
        if (isolations) {
            const auto it = isolations->find(r.checkpoint);
            if (it != isolations->end()) isolation = &it->second;
        }
        if (const MistakeFrame* frame = frame_named(lab, r.checkpoint, g.mistake_image)) {
            std::vector<KnownMistake> kept;
            std::vector<std::string> out;
            for (const KnownMistake& m : frame->mistakes) {
                const std::string why = ruled_out(m, g, units, isolation);
                if (why.empty())
                    kept.push_back(m);
                else
                    out.push_back("The frame also matches a known mistake (" + m.id + "), but " +
                                  why + ", so it is not " + m.id + ".");
            }
            if (!kept.empty()) g.lines.push_back(known_mistake_sentence(kept));
            g.lines.insert(g.lines.end(), out.begin(), out.end());
        }
        // Another checkpoint's frame: where the records show the draws of
        // that checkpoint, or cannot tell and no unit check fails.
        if (!g.checkpoint.empty() &&
            (g.record_is_checkpoints > 0 || (g.record_is_checkpoints == 0 && !unit_fails))) {
            const std::string s = checkpoint_match_sentence(lab, *here, g.checkpoint);
            if (!s.empty()) g.lines.push_back(s);
        }
        for (const std::string& line : g.lines) {
            append_line(r.diagnosis, line);
            append_line(r.output, line);
        }
    }
}

}  // namespace grading
