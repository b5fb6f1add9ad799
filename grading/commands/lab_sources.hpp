// A `lab` executable against the files it is built from, which CMake lists
// beside it in LAB.sources (cmake/lab_sources.cmake): a `lab` older than one
// of them was built before that file's last change, and grading it would
// grade the code as it was. `course grade`, `course bless` and `course
// warm-cache` refuse it (docs/contract.md, `course`, Exit status).
#pragma once

#include <string>
#include <vector>

namespace grading {

struct LabSources {
    std::string manifest;       // LAB.sources; empty where there is none
    std::string source, build;  // the tree and the build folder it names
    // Its files newer than LAB, relative to the tree when course runs at its
    // top, else in full; "X (gone)" for one that no longer exists.
    std::vector<std::string> newer;
};

// Reads the manifest beside `lab_binary` and compares each file's time with
// the executable's. Throws fw::UsageError when the manifest cannot be read
// or is malformed.
LabSources lab_sources(const std::string& lab_binary);

// Throws fw::UsageError when `lab_binary` is older than a file it is built
// from: the message names the files and the command that rebuilds it; for
// `course grade` (`grading`), also scripts/grade.sh with `labs`, which
// rebuilds and grades. Nothing when there is no manifest (a `lab` that this
// project's CMake did not build: --lab of another program).
void require_lab_up_to_date(const std::string& lab_binary, bool grading,
                            const std::vector<std::string>& labs);

}  // namespace grading
