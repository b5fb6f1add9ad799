// The rows of grade-class kept on disk, so that `course merge-class` can
// put the slices of a class (--shard K/N) back together: DIR/class.json
// names the labs, DIR/students/KEY/row.json holds each submission's row.
#pragma once

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "grading/class/class_submission.hpp"
#include "grading/class/lms_export.hpp"

namespace grading::cls {

using LabList = std::vector<std::pair<std::string, std::string>>;  // id, folder

void write_row(const std::filesystem::path& out, const ClassRow& row);

// A lab's grade as a row or a lab's class.json keeps it ({"status", "score",
// "max_score", "reason"}), marked resumed; throws nlohmann's error when a
// field is missing.
LabGrade lab_grade_of(const nlohmann::json& j);
void write_class_file(const std::filesystem::path& out, const LabList& labs);

// What a grade-class run left in `dir`: its labs and every row, sorted by
// key. Throws fw::UsageError naming the file that is missing or malformed.
struct ClassResult {
    LabList labs;
    std::vector<ClassRow> rows;
};
ClassResult read_class(const std::filesystem::path& dir);

// `course merge-class OUT DIR...`: the slices' rows and reports in OUT, and
// the gradebook one run would have written, with the import files of
// Canvas and Moodle (`lms`, as grade-class's --roster, --canvas-column and --moodle-total).
// Exit status as grade-class's.
int merge_class_command(const std::string& out, const std::vector<std::string>& dirs,
                        const LmsOptions& lms = {});

}  // namespace grading::cls
