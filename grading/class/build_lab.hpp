// One `lab` executable per submission, built against the course's own build:
// only the student's C++ files are compiled (with the build's own compile
// commands, -Werror left out), and the course's objects for every other file
// are linked with them (the build's own link command). An object is kept by
// the hash of its command and text, so a file many students left as the
// release wrote it, or handed in alike, is compiled once. A lab whose file
// does not compile has every C++ file of it linked at its starting code, and
// is that lab's failure alone (grading/platforms/compile_units.hpp).
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>

#include "grading/platforms/compile_units.hpp"

namespace grading::cls {

struct BuiltLab {
    bool ok = false;          // `lab` was linked
    std::string log;          // the compilers' and the linker's output
    std::string first_error;  // its first line with "error" or "fatal", for the class page
    // The labs, by folder, whose C++ files did not all compile, each with
    // what the compiler said of them: linked at their starting code.
    std::map<std::string, std::string> not_built;
    int compiled = 0;        // files compiled (not found among the kept objects)
    double cpu_seconds = 0;  // of the compilers and the linker
};

class LabBuilder {
public:
    // `lab_binary`: the course's `lab`, up to date; its LAB.sources names the
    // build folder (with CMake's compile_commands.json and the Makefile
    // generator's link.txt). `objects`: where compiled objects are kept.
    // Throws fw::UsageError saying what is missing.
    LabBuilder(const std::string& lab_binary, std::filesystem::path objects);

    // Builds `out` with `cpp` (a repository path such as
    // "labs/07_framebuffer_ops/blending.cpp" to the file that stands for it)
    // in place of those files; where a lab's file does not compile, each C++
    // file of that lab is its starting version, `versions`/PATH, instead.
    // `work` is a folder of its own for the sources.
    BuiltLab build(const std::map<std::string, std::filesystem::path>& cpp,
                   const std::filesystem::path& versions, const std::filesystem::path& work,
                   const std::filesystem::path& out) const;

    // The repository paths of the C++ files build() can put in place.
    bool knows(const std::string& rel) const { return commands_->knows(rel); }

private:
    // The object for `rel` compiled from the file `from` ("" when it is the
    // course's own); nullopt when it does not compile. The compiler's output
    // goes to `log`.
    std::optional<std::string> object_of(const std::string& rel, const std::filesystem::path& from,
                                         const std::filesystem::path& work,
                                         const std::filesystem::path& log, BuiltLab& b) const;

    std::optional<CompileCommands> commands_;
    std::string link_dir_, link_command_, link_output_;
    std::filesystem::path objects_;
    std::string root_;
};

}  // namespace grading::cls
