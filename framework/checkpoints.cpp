#include "framework/checkpoints.hpp"

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "framework/error.hpp"
#include "framework/text.hpp"

namespace fw {

std::vector<Checkpoint> load_checkpoints(const RegisteredLab& lab) {
    return load_checkpoints(lab, lab_path(lab.info, "checkpoints.json"));
}

namespace {

// The lab a checkpoints file belongs to: the id of its folder's name
// (labs/02_robot_arm/checkpoints.json: "robot-arm"). An optional "lab" field
// must agree; a file outside a lab folder must have one.
template <class Fail>
std::string lab_of_checkpoint_file(const std::string& path, const nlohmann::json& doc, Fail fail) {
    if (doc.contains("lab") && !doc["lab"].is_string())
        fail("\"lab\" must be a string: the lab's id");
    const std::string named = doc.value("lab", std::string());
    const std::string folder = std::filesystem::path(path).parent_path().filename().string();
    int number = 0;
    std::string id;
    try {
        parse_lab_dir(folder, number, id);
    } catch (const Error&) {
        if (named.empty())
            fail("the file is not in a lab folder (labs/NN_name/) and has no \"lab\"");
        return named;
    }
    if (!named.empty() && named != id)
        fail("\"lab\" is \"" + named + "\" but the file is in folder " + folder + ", lab '" + id +
             "'; the folder's name decides: remove \"lab\"");
    return id;
}

// A checkpoint's "parts": the sheet's part numbers (1, 2, ...).
template <class Fail>
std::vector<int> part_numbers(const nlohmann::json& parts, const std::string& where, Fail fail) {
    if (!parts.is_array()) fail(where + "\"parts\" must be an array of part numbers");
    std::vector<int> numbers;
    for (const nlohmann::json& n : parts) {
        if (!n.is_number_unsigned() || n.get<int>() < 1)
            fail(where + "\"parts\" must list the sheet's part numbers (1, 2, ...)");
        numbers.push_back(n.get<int>());
    }
    return numbers;
}

// The file's fields beside "checkpoints": "hidden" (what course release
// left out) and "parts" (raw; course reads it).
template <class Fail>
void read_top_level(const nlohmann::json& doc, CheckpointFile& file, Fail fail) {
    if (doc.contains("hidden")) {
        const nlohmann::json& h = doc["hidden"];
        if (!h.is_object() || !h.value("checkpoints", nlohmann::json()).is_number_unsigned() ||
            !h.value("points", nlohmann::json()).is_number() || h["points"].get<double>() < 0)
            fail(
                "\"hidden\" must be {\"checkpoints\": N, \"points\": P} (what course release "
                "left out)");
        file.hidden_checkpoints = h["checkpoints"].get<int>();
        file.hidden_points = h["points"].get<double>();
    }
    if (doc.contains("parts")) {
        if (!doc["parts"].is_array())
            fail("\"parts\" must be an array of {\"part\", \"file\", \"function\"}");
        file.parts = doc["parts"];
    }
}

}  // namespace

CheckpointFile read_checkpoint_file(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw Error("cannot read checkpoints file '" + path + "'");
    nlohmann::json doc;
    try {
        doc = nlohmann::json::parse(in, nullptr, true, /*ignore_comments=*/true);
    } catch (const nlohmann::json::parse_error& e) {
        throw Error(path + ": not valid JSON: " + e.what());
    }
    auto fail = [&](const std::string& what) { throw Error(path + ": " + what); };
    if (!doc.is_object() || !doc.contains("checkpoints") || !doc["checkpoints"].is_array())
        fail("expected an object with a \"checkpoints\" array");
    CheckpointFile file;
    file.path = path;
    file.lab = lab_of_checkpoint_file(path, doc, fail);
    read_top_level(doc, file, fail);
    std::set<std::string> names;
    for (const auto& item : doc["checkpoints"]) {
        Checkpoint cp;
        if (!item.is_object() || !item.contains("name") || !item["name"].is_string())
            fail("every checkpoint needs a string \"name\"");
        cp.name = item["name"].get<std::string>();
        std::string where = "checkpoint '" + cp.name + "': ";
        if (!names.insert(cp.name).second) fail(where + "the name is used twice");
        // Names become file names (NAME.png) in renders and reports.
        if (cp.name.empty() || cp.name.find_first_not_of(
                                   "abcdefghijklmnopqrstuvwxyz"
                                   "ABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-") != std::string::npos)
            fail(where + "names may use only letters, digits, '_' and '-'");
        for (const auto& [key, value] : item.items())
            if (key != "name" && key != "visibility" && key != "description" && key != "params" &&
                key != "checks" && key != "parts")
                fail(where + "unknown field \"" + key +
                     "\"; fields are name, visibility, description, params, checks, parts");
        cp.visibility = item.value("visibility", std::string("visible"));
        if (cp.visibility != "visible" && cp.visibility != "hidden")
            fail(where + "visibility must be \"visible\" or \"hidden\", not \"" + cp.visibility +
                 "\"");
        cp.description = item.value("description", std::string());
        if (item.contains("params")) {
            if (!item["params"].is_object()) fail(where + "\"params\" must be an object");
            cp.params = item["params"];
        }
        if (item.contains("checks")) {
            if (!item["checks"].is_array()) fail(where + "\"checks\" must be an array");
            cp.checks = item["checks"];
        }
        if (item.contains("parts")) cp.parts = part_numbers(item["parts"], where, fail);
        file.checkpoints.push_back(std::move(cp));
    }
    return file;
}

std::vector<Checkpoint> load_checkpoints(const RegisteredLab& lab, const std::string& path) {
    CheckpointFile file = read_checkpoint_file(path);
    if (file.lab != lab.info.id)
        throw Error(path + ": \"lab\" is \"" + file.lab + "\" but the file belongs to lab '" +
                    lab.info.id + "'");
    for (const Checkpoint& cp : file.checkpoints) {
        try {
            checkpoint_params(lab, cp);
        } catch (const Error& e) {
            throw Error(path + ": checkpoint '" + cp.name + "': " + e.what());
        }
    }
    return file.checkpoints;
}

const Checkpoint& find_checkpoint(const std::vector<Checkpoint>& all, const std::string& name,
                                  const std::string& lab_id) {
    for (const Checkpoint& cp : all)
        if (cp.name == name) return cp;
    const std::string names = join(all, ", ", &Checkpoint::name);
    throw UsageError("lab '" + lab_id + "' has no checkpoint '" + name +
                     "'; its checkpoints are: " + (names.empty() ? "(none)" : names));
}

ParamValues checkpoint_params(const RegisteredLab& lab, const Checkpoint& cp) {
    ParamValues values = default_params(lab);
    for (const auto& [key, value] : cp.params.items()) values.set_json(key, value);
    return values;
}

}  // namespace fw
