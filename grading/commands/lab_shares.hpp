// The labs of one grading shared between its --jobs workers, each of which
// runs one child for its share (grade.cpp).
#pragma once

#include <cstddef>
#include <vector>

#include "grading/judge/checks.hpp"

namespace grading {

// What grading `lab` costs, roughly: a frame for each checkpoint that
// renders, and a unit check's cases (about 200 cost as much as a frame).
double grading_cost(const LabData& lab);

// The positions in `which` (indices into `labs`) shared between `workers`:
// the costliest lab first, each to the worker with the least cost so far, so
// that the workers end at about the same time. Each share keeps the labs'
// order; the same labs give the same shares.
std::vector<std::vector<size_t>> shares(const std::vector<LabData>& labs,
                                        const std::vector<size_t>& which, size_t workers);

}  // namespace grading
