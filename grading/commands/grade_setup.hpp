// What `course grade` does before its first child (grade.cpp): the labs'
// files read and checked, and the sandbox's privileged layers probed, the
// two side by side.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "grading/judge/checks.hpp"
#include "grading/sandbox/isolation.hpp"

namespace grading {

// The named labs of `all`, their checks parsed and their reference records
// checked (a usage error names what is wrong before any child runs). The labs
// are read in parallel; of several in error, the first in order is told.
std::vector<LabData> labs_to_grade(const std::vector<LabData>& all,
                                   const std::vector<std::string>& names);

// --not-built FILE: a JSON object from a lab's folder to what the compiler
// said of its C++ (`course autograde`); none without the option. A usage
// error when it is not such an object.
std::map<std::string, std::string> read_not_built(const std::string& file);

// The sandbox's privileged layers where this machine allows them
// (isolation.hpp): the namespaces, by a throwaway child set up as a lab's
// is, and the cgroups, by making them; each with why not where it is off.
struct SandboxProbe {
    bool namespaces = false;
    std::string namespaces_why, cgroups_why;
    std::unique_ptr<CgroupRoot> cgroups;
};

// Both probes at once: each is mostly the kernel's work (tens of ms).
SandboxProbe probe_sandbox();

}  // namespace grading
