#include "framework/lab.hpp"

#include <algorithm>
#include <cctype>
#include <set>

#include "framework/error.hpp"
#include "framework/gl/program.hpp"
#include "framework/text.hpp"

namespace fw {

ProgramLibrary::ProgramLibrary(std::string folder) : folder_(std::move(folder)) {}
ProgramLibrary::~ProgramLibrary() = default;

Program& ProgramLibrary::load(const std::vector<std::string>& files,
                              const std::vector<std::string>& feedback) {
    std::vector<std::string> paths;
    for (const std::string& file : files)
        paths.push_back(
            folder_.empty() || file.find('/') != std::string::npos ? file : folder_ + "/" + file);
    try {
        programs_.push_back(std::make_unique<Program>(Program::from_files(paths, {}, feedback)));
    } catch (const ShaderError& e) {
        programs_.push_back(std::make_unique<Program>(Program::failed(paths, e, feedback)));
    }
    return *programs_.back();
}

std::vector<std::string> ProgramLibrary::reload_all() {
    std::vector<std::string> errors;
    for (auto& program : programs_) {
        try {
            Program fresh = Program::from_files(program->files(),
                                                program->build_error() ? "" : program->label(),
                                                program->feedback());
            *program = std::move(fresh);
        } catch (const ShaderError& e) {
            // A program that never built stays failed, with the new reason.
            if (program->build_error())
                *program = Program::failed(program->files(), e, program->feedback());
            errors.push_back(e.what());
        } catch (const Error& e) {
            errors.push_back(e.what());
        }
    }
    return errors;
}

std::vector<const ShaderError*> ProgramLibrary::build_errors() const {
    std::vector<const ShaderError*> errors;
    for (const auto& program : programs_)
        if (program->build_error()) errors.push_back(program->build_error());
    return errors;
}

namespace {
std::vector<RegisteredLab>& registry() {
    static std::vector<RegisteredLab> labs;
    return labs;
}
}  // namespace

void parse_lab_dir(std::string_view dir, int& number, std::string& id) {
    const bool ok = dir.size() > 3 && std::isdigit(static_cast<unsigned char>(dir[0])) &&
                    std::isdigit(static_cast<unsigned char>(dir[1])) && dir[2] == '_';
    if (!ok)
        throw Error("lab folder '" + std::string(dir) +
                    "': a lab's folder is named NN_name, e.g. 02_robot_arm");
    number = (dir[0] - '0') * 10 + (dir[1] - '0');
    id = std::string(dir.substr(3));
    for (char& c : id) {
        if (c == '_') c = '-';
        if (!std::islower(static_cast<unsigned char>(c)) && c != '-' &&
            !std::isdigit(static_cast<unsigned char>(c)))
            throw Error("lab folder '" + std::string(dir) +
                        "': the name after NN_ may hold only a-z, 0-9 and '_'");
    }
}

bool register_lab(std::string_view dir, LabInfo info, LabFactory factory) {
    // The folder's name decides; a value the lab wrote itself would be
    // silently replaced, so it is refused instead.
    if (info.number != 0 || !info.id.empty() || !info.dir.empty())
        throw Error("lab folder '" + std::string(dir) +
                    "': info() sets number, id or dir, which come from the folder's name; "
                    "remove them from info()");
    parse_lab_dir(dir, info.number, info.id);
    info.dir = std::string(dir);
    auto& labs = registry();
    for (const RegisteredLab& other : labs)
        if (other.info.number == info.number || other.info.id == info.id)
            throw Error("lab folder '" + info.dir + "': lab " + other.info.dir +
                        " has the same number or id; each lab needs its own");
    labs.push_back({std::move(info), std::move(factory)});
    std::sort(labs.begin(), labs.end(), [](const RegisteredLab& a, const RegisteredLab& b) {
        return a.info.number < b.info.number;
    });
    return true;
}

const std::vector<RegisteredLab>& registered_labs() { return registry(); }

const RegisteredLab& find_lab(std::string_view id) {
    for (const RegisteredLab& lab : registry())
        if (lab.info.id == id) return lab;
    const std::string names =
        join(registry(), ", ", [](const RegisteredLab& lab) { return lab.info.id; });
    throw UsageError("unknown lab '" + std::string(id) +
                     "'; the labs are: " + (names.empty() ? "(none)" : names));
}

const RegisteredLab& find_lab_in_folder(std::string_view dir) {
    for (const RegisteredLab& lab : registry())
        if (lab.info.dir == dir) return lab;
    int number = 0;
    std::string id;
    parse_lab_dir(dir, number, id);
    return find_lab(id);  // throws, listing the labs
}

ParamValues default_params(const RegisteredLab& lab) {
    std::set<std::string> seen;
    for (const Param& p : lab.info.params)
        if (!seen.insert(p.name).second)
            throw Error("lab '" + lab.info.id + "' declares parameter '" + p.name + "' twice");
    std::set<int> keys;
    for (const Param& p : lab.info.params) {
        if (p.name == kAnimate.name && p.type != ParamType::Bool)
            throw Error("lab '" + lab.info.id + "', parameter '" + p.name + "': it is " +
                        param_type_name(p.type) +
                        ", and the framework reads a parameter of that name as the bool that "
                        "animates the lab (fw::kAnimate); declare it with "
                        "Param::boolean(fw::kAnimate, ...) or rename it");
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
