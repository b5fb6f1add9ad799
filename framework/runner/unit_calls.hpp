// The unit calls of a grading child's job (framework/runner/grade_child.cpp):
// each call of a lab's unit functions and its result, as units.json.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "framework/lab.hpp"

namespace fw {

// units.json: every unit call of the job's "units" (`groups`), by id, with
// its result or the error it threw (docs/contract.md, `course grade`).
std::string units_text(const RegisteredLab& lab, const nlohmann::json& groups);

}  // namespace fw
