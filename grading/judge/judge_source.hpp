// `forbidden` checks: what a lab's sheet forbids the student's files to use
// (lab 1: GLM's transform helpers), found in their code by course, without
// running anything.
#pragma once

#include <string>
#include <vector>

#include "grading/judge/checks.hpp"
#include "grading/results/results.hpp"

namespace grading {

// The 1-based lines where `name` occurs in the code of `text` (its comments
// and literals left out: code_only, grading/diagnosis/starting_code.hpp) as a
// whole name: not inside a longer identifier ("glm::translate" is found in
// "glm::translate(M, t)", not in "glm::translateX" or "my_glm::translate").
std::vector<int> lines_using(const std::string& text, const std::string& name);

// Judges `check` on the files under lab.sources: passes when none of its names
// occurs; else the output names each file, line and name with the rule. A
// lab that did not run to its end (`lab_status`: it did not build, crashed or
// timed out) fails the check unread: code that is not there, or does not
// run, earns no points for what it leaves out.
void judge_forbidden(const LabData& lab, const ForbiddenCheck& check, const LabStatus& lab_status,
                     CheckResult& result);

}  // namespace grading
