// Switching a forked child to the --run-as user (run_as.cpp, with
// lookup_user and user_can_access of child.hpp).
#pragma once

#include "grading/sandbox/limits.hpp"

namespace grading {

// After fork(), before exec: the groups, gid and uid of `user`, then checked.
// Only async-signal-safe calls; `fail` (which must not return) on an error.
void switch_user(const RunAsUser& user, void (*fail)(const char*)) noexcept;

}  // namespace grading
