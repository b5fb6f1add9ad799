// One C++ file of `lab` compiled alone, with the build's own command (CMake's
// compile_commands.json), so that a lab whose file does not compile costs
// that lab alone (docs/contract.md, `course grade-class`): grade-class builds
// every submission so (grading/class/build_lab.hpp), and `course autograde`
// compiles so the files of a submission whose build failed, to find the labs
// at fault (autograde.cpp). Either then builds `lab` with those labs' C++ at
// their starting code.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace grading {

// The compile commands of a build folder, of the files under the
// repository `root` (absolute), by repository path.
class CompileCommands {
public:
    // Throws fw::Error when `build`/compile_commands.json cannot be read.
    CompileCommands(const std::filesystem::path& build, const std::string& root);

    bool knows(const std::string& rel) const { return units_.count(rel) > 0; }
    // The course's file for `rel`, and the object the build makes of it.
    const std::string& source(const std::string& rel) const { return unit(rel).source; }
    const std::string& object(const std::string& rel) const { return unit(rel).object; }
    // The folder its command runs in.
    const std::string& directory(const std::string& rel) const { return unit(rel).directory; }
    // The build's command for `rel`, -Werror left out (a student's warning
    // is no failure), compiling `source` into `object` (both quoted here).
    std::string command(const std::string& rel, const std::string& source,
                        const std::string& object) const;

private:
    struct Unit {
        std::string directory, command, object, source;
    };
    const Unit& unit(const std::string& rel) const;
    std::map<std::string, Unit> units_;
};

// Runs `command` with /bin/sh in `dir`, its output appended to `log`; true
// when it exits 0 within the limits of one compiler or linker run (300 s, and
// 4 GiB of address space with `memory_cap`): a submission that makes the
// compiler loop or swell fails its own build, nothing else. Its CPU time is
// added to `cpu` (a linker's child that it does not wait for, as mold's, is
// not counted).
bool run_build_command(const std::string& command, const std::string& dir,
                       const std::filesystem::path& log, double& cpu, bool memory_cap);

// `text` with its one occurrence of `from` replaced by `to`; throws
// fw::UsageError naming `what` when `from` is not there.
std::string replace_in_command(std::string text, const std::string& from, const std::string& to,
                               const std::string& what);

// The first line of a compiler's `log` with "error" or "fatal"; "" if none.
std::string first_error(const std::string& log);

// `log` with every "FOLDER/" taken out: the paths a compiler names in
// `folder` as they are in the repository.
std::string without_folder(std::string log, const std::string& folder);

// "03_projection" for a repository path under labs/03_projection/; "" for
// a path under no lab folder.
std::string lab_folder(const std::string& rel);

// `course autograde`, after a submission's build failed: the labs whose C++
// does not compile, by folder, each with what the compiler said of its files
// (paths relative to the course's tree `source`). Each C++ file of
// `files` (repository paths) in a lab folder, as it is in `source` and
// unless it is its starting version (`versions`/PATH), is compiled alone
// with `prefix` (the command that runs the rest as the submission's user, or
// "") before the build's command; the logs go into `work`. None where the
// build has no compile_commands.json.
std::map<std::string, std::string> labs_not_compiling(const std::filesystem::path& source,
                                                      const std::vector<std::string>& files,
                                                      const std::filesystem::path& versions,
                                                      const std::string& prefix,
                                                      const std::filesystem::path& work);

}  // namespace grading
