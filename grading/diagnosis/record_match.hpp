// Two records of the draws made on two implementations of GL (the
// reference blessed on one driver, the student's graded on another): which
// of a program's attributes, uniforms, blocks, samplers and images are active
// is the linker's choice (GL 4.3, 7.3.1: an implementation may or may not
// keep what cannot change the result, such as an attribute that feeds only an
// unused output, or the trailing elements of a uniform array no shader
// reads). Before the two records are compared, each program keeps only the
// interface both records hold active, and an array uniform only the elements
// both hold; what one implementation drops cannot change the result on the
// other, so it is never a difference (docs/contract.md, "The record and the
// state diff").
#pragma once

#include <nlohmann/json.hpp>

namespace grading {

// Narrows the events of `student` and `reference` (records as
// framework/trace/record.hpp writes them) to the program interface both hold
// active, program by program (by its label). A program one record never
// uses is left as it is.
void keep_common_interface(nlohmann::json& student, nlohmann::json& reference);

}  // namespace grading
