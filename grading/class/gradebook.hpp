// The class's gradebook, DIR/grades.csv (docs/contract.md, `course
// grade-class`): a row per student (per submission where the layout names
// no students), RFC 4180 quoting, a field that a spreadsheet would take
// for a formula (= + - @ first) prefixed with an apostrophe.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "grading/class/class_submission.hpp"

namespace grading::cls {

// One field as RFC 4180 writes it: quoted where it holds a comma, a quote
// or a line break, and otherwise as it is.
std::string csv_quoted(const std::string& text);
// csv_quoted, after an apostrophe where a spreadsheet would take the field
// for a formula.
std::string csv_field(const std::string& text);

// Writes `text` to `file` whole or not at all (through FILE.part): a run
// stopped midway leaves the file of the run before.
void write_whole(const std::filesystem::path& file, const std::string& text);

void write_grades_csv(const std::filesystem::path& file, const std::vector<ClassRow>& rows,
                      const std::vector<std::pair<std::string, std::string>>& labs);

}  // namespace grading::cls
