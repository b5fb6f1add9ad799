#include "framework/lab.hpp"

#include <algorithm>
#include <cctype>
#include <set>

#include "framework/error.hpp"
#include "framework/gl/program.hpp"

namespace fw {

ProgramLibrary::ProgramLibrary() = default;
ProgramLibrary::~ProgramLibrary() = default;

Program& ProgramLibrary::load(const std::vector<std::string>& files) {
    programs_.push_back(std::make_unique<Program>(Program::from_files(files)));
    return *programs_.back();
}

std::vector<std::string> ProgramLibrary::reload_all() {
    std::vector<std::string> errors;
    for (auto& program : programs_) {
        try {
            Program fresh = Program::from_files(program->files(), program->label());
            *program = std::move(fresh);
        } catch (const Error& e) {
            errors.push_back(e.what());
        }
    }
    return errors;
}

namespace {
std::vector<RegisteredLab>& registry() {
    static std::vector<RegisteredLab> labs;
    return labs;
}
}  // namespace

bool register_lab(LabInfo info, LabFactory factory) {
    auto& labs = registry();
    labs.push_back({std::move(info), std::move(factory)});
    std::sort(labs.begin(), labs.end(),
              [](const RegisteredLab& a, const RegisteredLab& b) { return a.info.number < b.info.number; });
    return true;
}

const std::vector<RegisteredLab>& registered_labs() { return registry(); }

const RegisteredLab& find_lab(std::string_view id) {
    std::string names;
    for (const RegisteredLab& lab : registry()) {
        if (lab.info.id == id) return lab;
        names += (names.empty() ? "" : ", ") + lab.info.id;
    }
    throw UsageError("unknown lab '" + std::string(id) +
                     "'; the labs are: " + (names.empty() ? "(none)" : names));
}

ParamValues default_params(const RegisteredLab& lab) {
    std::set<std::string> seen;
    for (const Param& p : lab.info.params)
        if (!seen.insert(p.name).second)
            throw Error("lab '" + lab.info.id + "' declares parameter '" + p.name + "' twice");
    std::set<int> keys;
    for (const Param& p : lab.info.params) {
        if (p.shortcut == 'R' || p.shortcut == 'r')
            throw Error("lab '" + lab.info.id + "', parameter '" + p.name +
                        "': key R is reserved for reloading shaders; choose another key");
        if (p.shortcut && !keys.insert(std::toupper(p.shortcut)).second)
            throw Error("lab '" + lab.info.id + "', parameter '" + p.name + "': key '" +
                        std::string(1, static_cast<char>(p.shortcut)) +
                        "' is already used by another parameter");
    }
    return ParamValues(lab.info.id, &lab.info.params);
}

std::string lab_path(const LabInfo& info, const std::string& file) {
    return std::string(LAB_SOURCE_DIR) + "/labs/" + info.dir + "/" + file;
}

}  // namespace fw
