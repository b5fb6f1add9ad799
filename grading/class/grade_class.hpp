// `course grade-class SUBMISSIONS --out DIR` (docs/contract.md, `course
// grade-class`): every submission of a class graded as the autograders
// grade one, each lab of each submission into DIR/students/KEY/LAB/ (its
// summary.txt, index.html and results.json, hidden checkpoints included),
// and the class's gradebook, DIR/grades.csv, with the import files of
// Canvas's and Moodle's gradebooks beside it (lms_export.hpp). A second run
// grades only the labs whose submitted files, or whose course references,
// changed.
#pragma once

#include <string>
#include <vector>

#include "grading/class/lms_export.hpp"

namespace grading::cls {

struct GradeClassOptions {
    std::string submissions, out;
    std::vector<std::string> labs;  // the assignment's labs; empty: every lab
    int jobs = 0;                   // submissions at once; 0: the cores
    std::string deadline;           // git: the last commit before it is graded
    std::string shard;              // "K/N": the K-th of N fixed slices, from 1
    std::string timeout = "60";     // seconds each lab may run, as on Gradescope
    std::string backend;            // passed on to `course grade`; empty: its default
    LmsOptions lms;                 // --roster, --canvas-column, --moodle-total (lms_export.hpp)
};

// Exit status: 0 every submission graded (whatever its grade), 1 some could
// not be (unpacked, built or graded: their rows say why), 130 interrupted
// (what was graded stays, and the next run resumes), 2 usage.
int grade_class_command(const GradeClassOptions& options);

}  // namespace grading::cls
