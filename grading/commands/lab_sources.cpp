// A `lab` against the list of the files it is built from (lab_sources.hpp), and the
// refusal `course grade`, `bless` and `warm-cache` make when it is older than one.
#include "grading/commands/lab_sources.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>

#include "framework/error.hpp"
#include "framework/text.hpp"

namespace grading {

namespace fs = std::filesystem;

namespace {

// The files named in a refusal; the rest are counted.
constexpr size_t kNamedFiles = 5;

// `path` relative to the tree when course runs at its top (where a student
// types the commands), else in full: ctest runs the self-checks in the
// build folder, from where a relative command would mislead.
std::string shown(const fs::path& path, const std::string& source) {
    std::error_code ec;
    if (source.empty() || !fs::equivalent(fs::current_path(), source, ec) || ec)
        return path.string();
    const fs::path rel = path.lexically_normal().lexically_relative(source);
    if (rel.empty() || *rel.begin() == "..") return path.string();
    return rel.string();
}

// Whether `file` changed after `built`: newer, or gone.
bool changed_after(const fs::path& file, fs::file_time_type built, bool& gone) {
    std::error_code ec;
    const fs::file_time_type t = fs::last_write_time(file, ec);
    gone = ec && !fs::exists(fs::symlink_status(file));
    // A file that exists but cannot be read for its time (a folder the user
    // may not enter) is no evidence either way.
    return gone || (!ec && t > built);
}

}  // namespace

LabSources lab_sources(const std::string& lab_binary) {
    LabSources found;
    const std::string manifest = lab_binary + ".sources";
    if (!fs::exists(manifest)) return found;
    found.manifest = manifest;
    std::ifstream in(manifest);
    std::error_code ec;
    const fs::file_time_type built = fs::last_write_time(lab_binary, ec);
    if (!in || ec)
        throw fw::UsageError("cannot read '" + manifest + "' or the time of '" + lab_binary +
                             "'; build the lab again (cmake --build BUILD --target lab)");
    std::vector<std::string> files;
    int number = 0;
    for (std::string line; std::getline(in, line);) {
        ++number;
        if (line.empty() || line[0] == '#') continue;
        const size_t space = line.find(' ');
        const std::string key = line.substr(0, space);
        const std::string value = space == std::string::npos ? "" : line.substr(space + 1);
        if (key == "source" && !value.empty())
            found.source = value;
        else if (key == "build" && !value.empty())
            found.build = value;
        else if (key == "file" && !value.empty())
            files.push_back(value);
        else
            throw fw::UsageError(manifest + ":" + std::to_string(number) + ": '" + line +
                                 "' is not a line CMake writes (source, build or file, then a "
                                 "path); configure and build again to write it afresh");
    }
    if (found.source.empty() && !files.empty())
        throw fw::UsageError(manifest + ": no 'source' line; configure and build again");
    for (const std::string& file : files) {
        bool gone = false;
        const fs::path path = fs::path(found.source) / file;
        if (changed_after(path, built, gone))
            found.newer.push_back(shown(path, found.source) + (gone ? " (gone)" : ""));
    }
    return found;
}

void require_lab_up_to_date(const std::string& lab_binary, bool grading,
                            const std::vector<std::string>& labs) {
    const LabSources sources = lab_sources(lab_binary);
    if (sources.newer.empty()) return;
    std::vector<std::string> named(
        sources.newer.begin(),
        sources.newer.begin() + std::ptrdiff_t(std::min(kNamedFiles, sources.newer.size())));
    std::string files = fw::join(named, ", ");
    if (sources.newer.size() > named.size())
        files += " and " + std::to_string(sources.newer.size() - named.size()) + " more";
    const std::string target = fs::path(lab_binary).filename().string();
    std::string rebuild =
        "cmake --build " + shown(sources.build, sources.source) + " --target " + target;
    const fs::path script = fs::path(sources.source) / "scripts" / "grade.sh";
    if (grading && fs::path(sources.build) == fs::path(sources.source) / "build" &&
        fs::exists(script)) {
        std::string command = shown(script, sources.source);
        for (const std::string& lab : labs) command += " " + lab;
        rebuild = command + " (builds, then grades) or " + rebuild;
    }
    const bool one = sources.newer.size() == 1;
    throw fw::UsageError("'" + shown(lab_binary, sources.source) + "' is older than " +
                         (one ? "a file" : std::to_string(sources.newer.size()) + " files") +
                         " it is built from, " + files + ": it would run the code as it was " +
                         (one ? "before that change" : "before those changes") +
                         ". Build it first: " + rebuild + " (" +
                         shown(sources.manifest, sources.source) + " lists the files compared)");
}

}  // namespace grading
