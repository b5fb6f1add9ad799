#include "grading/class/build_lab.hpp"

#include <unistd.h>

#include <fstream>

#include "framework/error.hpp"
#include "framework/text.hpp"
#include "grading/class/content_hash.hpp"
#include "grading/commands/lab_sources.hpp"
#include "grading/release/release.hpp"
#include "grading/report/report_text.hpp"

namespace grading::cls {

namespace fs = std::filesystem;

LabBuilder::LabBuilder(const std::string& lab_binary, fs::path objects)
    : objects_(std::move(objects)) {
    const LabSources sources = lab_sources(lab_binary);
    if (sources.manifest.empty())
        throw fw::UsageError("'" + lab_binary +
                             "' has no LAB.sources beside it: grade-class builds each "
                             "submission against a `lab` this project's CMake built");
    root_ = sources.source;
    const fs::path build(sources.build);
    commands_.emplace(build, root_);
    link_dir_ = (build / "labs").string();
    std::string link = read_file(build / "labs" / "CMakeFiles" / "lab.dir" / "link.txt");
    while (!link.empty() && (link.back() == '\n' || link.back() == ' ')) link.pop_back();
    link_command_ = link;
    const size_t o = link.find(" -o ");
    if (o == std::string::npos)
        throw fw::UsageError("the link command of `lab` in " + build.string() + " names no -o");
    link_output_ = link.substr(o + 4, link.find(' ', o + 4) - (o + 4));
    fs::create_directories(objects_);
}

std::optional<std::string> LabBuilder::object_of(const std::string& rel, const fs::path& from,
                                                 const fs::path& work, const fs::path& log,
                                                 BuiltLab& b) const {
    const std::string text = read_file(from);
    if (text == read_file(commands_->source(rel))) return "";  // the course's own object stands
    const fs::path source = work / rel;
    fs::create_directories(source.parent_path());
    report::write_text_file(source.string(), text);
    // Kept by the build's command and the text.
    const std::string key = commands_->command(rel, commands_->source(rel), commands_->object(rel));
    const fs::path object = objects_ / (content_hash(key + '\0' + rel + '\0' + text) + ".o");
    if (fs::exists(object)) return object.string();
    const fs::path partial = object.string() + ".part" + std::to_string(getpid());
    ++b.compiled;
    if (!run_build_command(commands_->command(rel, source.string(), partial.string()),
                           commands_->directory(rel), log, b.cpu_seconds, /*memory_cap=*/true))
        return std::nullopt;
    fs::rename(partial, object);
    return object.string();
}

BuiltLab LabBuilder::build(const std::map<std::string, fs::path>& cpp, const fs::path& versions,
                           const fs::path& work, const fs::path& out) const {
    BuiltLab b;
    const fs::path log = work / "build.log", one = work / "compile.log";
    fs::create_directories(work);
    fs::remove(log);
    // Each file alone, its output kept for its lab; then a lab with a file
    // that did not compile, each of its files at its starting version.
    std::map<std::string, std::string> objects;
    bool ok = true;
    auto compile = [&](const std::string& rel, const fs::path& from) {
        fs::remove(one);
        const std::optional<std::string> object = object_of(rel, from, work, one, b);
        const std::string said = fs::exists(one) ? read_file(one) : "";
        std::ofstream(log, std::ios::app) << said;
        if (object) objects[rel] = *object;
        return object ? "" : without_folder(said, work.string());
    };
    for (const auto& [rel, from] : cpp) {
        const std::string said = compile(rel, from);
        if (objects.count(rel)) continue;
        if (lab_folder(rel).empty())
            ok = false;  // a file of no lab: the whole build fails
        else
            b.not_built[lab_folder(rel)] += said;
    }
    for (const auto& [rel, from] : cpp)
        if (b.not_built.count(lab_folder(rel))) {
            objects.erase(rel);
            compile(rel, versions / rel);
            ok = ok && objects.count(rel);  // the starting code must compile
        }
    std::string link = link_command_;
    for (const auto& [rel, object] : objects)
        if (!object.empty())
            link = replace_in_command(link, " " + commands_->object(rel) + " ",
                                      " " + fw::shell_quote(object) + " ", rel + " (link)");
    if (ok) {
        link = replace_in_command(link, " -o " + link_output_ + " ",
                                  " -o " + fw::shell_quote(out.string()) + " ", "lab (link)");
        // The linker's address space is not capped: mold reserves far more
        // than it uses (its allocator's arenas), and the course's objects
        // make most of what it links.
        ok = run_build_command(link, link_dir_, log, b.cpu_seconds, /*memory_cap=*/false);
    }
    // The student's paths as in their repository, not in the work folder.
    b.log = without_folder(fs::exists(log) ? read_file(log) : "", work.string());
    b.first_error = first_error(b.log);
    b.ok = ok;
    return b;
}

}  // namespace grading::cls
