// What course runs and reads: the repository of the labs' data and the `lab`
// executable each child runs.
#pragma once

#include <string>

namespace grading {

// The repository whose labs/ (checkpoints, references) `course` reads: $LAB_ROOT
// if set, else the source tree it was built from.
std::string source_root();

// The tree whose source files a lab's source checks read (the student's
// files): $LAB_SOURCES if set, else `root`. `course autograde` sets it where
// the checkpoints come from elsewhere (PrairieLearn's serverFilesCourse).
std::string sources_root(const std::string& root);

// --lab, or `lab` beside course; throws fw::UsageError naming the path when missing.
std::string resolve_lab_binary(const std::string& given);

}  // namespace grading
