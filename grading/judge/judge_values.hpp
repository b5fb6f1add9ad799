// The checks of a frame's values: a probe's pixel (colour or depth) and a
// stat of the frame's statistics, each against what the checkpoint states;
// and what every judge of a check uses to say its verdict.
#pragma once

#include <string>

#include "grading/judge/checks.hpp"
#include "grading/judge/frame.hpp"

namespace grading {

// A number as a check's Expected and Observed lines print it (7 digits).
std::string num(double v);

// The check's verdict: passed or not, its points, its output.
void verdict(CheckResult& r, bool pass, const std::string& output);

void judge_probe(const ProbeCheck& check, const RenderPlan& plan, Frame& frame, CheckResult& r);
void judge_stat(const StatCheck& check, Frame& frame, CheckResult& r);

}  // namespace grading
