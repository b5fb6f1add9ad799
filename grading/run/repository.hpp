// What course runs and reads: the repository of the labs' data and the `lab`
// executable each child runs.
#pragma once

#include <string>

namespace grading {

// The repository whose labs/ (checkpoints, references) `course` reads: $LAB_ROOT
// if set, else the source tree it was built from.
std::string source_root();

// --lab, or `lab` beside course; throws fw::UsageError naming the path when missing.
std::string resolve_lab_binary(const std::string& given);

}  // namespace grading
