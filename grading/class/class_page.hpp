// The class's page, DIR/class.html (docs/contract.md, `course grade-class`,
// class.html), for the course staff: one self-contained file (inline CSS and
// SVG, the example frames as data: URIs, no script) with, for each lab, the
// distribution of the scores (an SVG histogram and its numbers in a table)
// and each checkpoint's pass rate, the most failed first; the mistakes the
// reports name, the most students first, each with an example frame and its
// students; the submissions that did not build (with the compiler's first
// error), that timed out, crashed or could not be graded; and the grading
// time. It reads each lab's report under DIR/students/ (class_findings.hpp)
// and uses index.html's escaping and styles.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "grading/class/class_submission.hpp"

namespace grading::cls {

// Writes `out`/class.html (through a file beside it, renamed into place);
// throws fw::Error when it cannot be written. `labs`: id and folder, in
// order; `seconds`: the run's grading time.
void write_class_page(const std::filesystem::path& out, const std::vector<ClassRow>& rows,
                      const std::vector<std::pair<std::string, std::string>>& labs, double seconds);

}  // namespace grading::cls
