// The reports of a grading run (docs/contract.md, Reports), all written into
// the output directory: summary.txt (the table also printed), results.json
// (Gradescope's format), junit.xml, and a self-contained index.html.
#pragma once

#include <string>

#include "grading/results.hpp"

namespace grading {

// The score table: one line per lab with its score, status and failed checks.
std::string summary_table(const GradeRun& run);

// Writes all four files; throws fw::Error naming a file that cannot be written.
void write_reports(const GradeRun& run, const std::string& out_dir);

}  // namespace grading
