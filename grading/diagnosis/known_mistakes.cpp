#include "grading/diagnosis/known_mistakes.hpp"

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "framework/error.hpp"
#include "framework/text.hpp"

namespace grading {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

constexpr const char* kSuffix = ".json";

std::string text_field(const json& object, const char* name, const std::string& where) {
    if (!object.is_object() || !object.contains(name) || !object[name].is_string() ||
        object[name].get_ref<const std::string&>().empty())
        throw fw::UsageError(where + ": needs a non-empty string \"" + name + "\"");
    return object[name].get<std::string>();
}

std::vector<MistakeFrame> parse_frames(const json& doc, const fs::path& folder,
                                       const std::string& file) {
    if (!doc.is_object() || !doc.contains("frames") || !doc["frames"].is_array())
        throw fw::UsageError(file + ": expected {\"frames\": [...]}");
    std::vector<MistakeFrame> frames;
    for (size_t i = 0; i < doc["frames"].size(); ++i) {
        const json& f = doc["frames"][i];
        const std::string where = file + ", frame " + std::to_string(i + 1);
        MistakeFrame frame;
        frame.image = text_field(f, "image", where);
        if (frame.image.find('/') != std::string::npos ||
            !fs::is_regular_file(folder / frame.image))
            throw fw::UsageError(where + ": no image " + frame.image + " beside the file");
        if (!f.contains("mistakes") || !f["mistakes"].is_array() || f["mistakes"].empty())
            throw fw::UsageError(where + ": needs a non-empty list \"mistakes\"");
        for (const json& m : f["mistakes"]) {
            KnownMistake known{text_field(m, "id", where), text_field(m, "why", where), "", {}, {}};
            if (m.contains("file")) known.file = text_field(m, "file", where);
            if (m.contains("units")) {
                if (!m["units"].is_array())
                    throw fw::UsageError(where + ": \"units\" must be a list of function names");
                known.units.emplace();
                for (const json& u : m["units"]) {
                    if (!u.is_string())
                        throw fw::UsageError(where +
                                             ": \"units\" must be a list of function names");
                    known.units->push_back(u.get<std::string>());
                }
            }
            if (m.contains("state")) {
                if (!m["state"].is_string())
                    throw fw::UsageError(where + ": \"state\" must be a string");
                known.state = m["state"].get<std::string>();
            }
            frame.mistakes.push_back(std::move(known));
        }
        frames.push_back(std::move(frame));
    }
    return frames;
}

}  // namespace

std::string mistake_frames_dir(const std::string& lab_dir) {
    return "labs/" + lab_dir + "/reference/mistakes";
}

MistakeFrames read_mistake_frames(const std::string& root, const std::string& lab_dir,
                                  const std::vector<std::string>& checkpoints) {
    MistakeFrames out;
    const std::string rel = mistake_frames_dir(lab_dir);
    const fs::path folder = fs::path(root) / rel;
    std::error_code ec;
    if (!fs::is_directory(folder, ec)) return out;
    for (const fs::directory_entry& e : fs::directory_iterator(folder)) {
        const std::string name = e.path().filename().string();
        if (e.path().extension() != kSuffix) continue;
        const std::string file = rel + "/" + name;
        const std::string checkpoint = name.substr(0, name.size() - std::string(kSuffix).size());
        bool known = false;
        for (const std::string& c : checkpoints) known = known || c == checkpoint;
        if (!known)
            throw fw::UsageError(file + ": the lab has no checkpoint " + checkpoint +
                                 " (record the frames again: MISTAKES_RECORD=1)");
        std::ifstream in(e.path());
        const json doc = json::parse(in, nullptr, /*allow_exceptions=*/false);
        if (doc.is_discarded()) throw fw::UsageError(file + ": not valid JSON");
        out[checkpoint] = parse_frames(doc, folder, file);
    }
    return out;
}

std::string mistake_frames_text(const std::vector<MistakeFrame>& frames) {
    json list = json::array();
    for (const MistakeFrame& f : frames) {
        json mistakes = json::array();
        for (const KnownMistake& m : f.mistakes) {
            json entry = {{"id", m.id}, {"why", m.why}};
            if (!m.file.empty()) entry["file"] = m.file;
            if (m.units) entry["units"] = *m.units;
            if (m.state) entry["state"] = *m.state;
            mistakes.push_back(entry);
        }
        list.push_back({{"image", f.image}, {"mistakes", mistakes}});
    }
    return json{{"frames", list}}.dump(1) + "\n";
}

std::string known_mistake_sentence(const MistakeFrame& frame) {
    return known_mistake_sentence(frame.mistakes);
}

std::string known_mistake_sentence(const std::vector<KnownMistake>& mistakes) {
    std::vector<std::string> ids, whys;
    for (const KnownMistake& m : mistakes) {
        ids.push_back(m.id);
        whys.push_back("code that " + m.why);
    }
    const bool one = mistakes.size() == 1;
    // The frame is the evidence, not the code: another mistake, in another
    // file, may draw the same frame, so the sentence names the misconception
    // and leaves the student to find whether their code holds it.
    return std::string("Your frame is the one ") +
           (one ? "a known mistake draws" : "known mistakes draw") + " (" + fw::join(ids, ", ") +
           "): the frame of " + fw::join(whys, ", or of ") +
           ". Another mistake can draw the same frame: check whether your code does this.";
}

}  // namespace grading
