// What the class page (class_page.hpp) reads back from the report of each
// lab that ran, DIR/students/KEY/LAB/results.json (Gradescope's format: a
// test per checkpoint, its checks listed in its extra_data in the order its
// html output shows them, each check's output in a <pre>): how many students
// passed each checkpoint, and the mistakes the failed checks name.
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "grading/class/class_submission.hpp"

namespace grading::cls {

// A sentence of a failed check's output that names a mistake, as the
// grader words it (the sentences the mistakes suite takes as naming one):
// - "Likely mistake (ID): ..." under a unit or buffer check; the IDs of a
//   check whose output adds "The likely mistakes above give the same values
//   on these cases" are one name, "ID or ID2", as the check cannot tell them
//   apart;
// - "Your frame is the one a known mistake draws (ID): ..." or "Your frame
//   is the one known mistakes draw (ID, ID2): ..." under an image check;
// - "Your frame is the one checkpoint X expects ..." under an image check.
// Nothing else is a name: not the difference's words, not the state diff's,
// not a part still at its starting code.
struct Naming {
    std::string key;  // "likely:ID", "known:ID or ID2", "checkpoint:X"
    std::string
        name;  // as the page shows it: "ID", "ID or ID2", "the frame checkpoint X expects, ..."
    std::string sentence;  // the line that names it
};

// The names in the output of a failed check of kind `kind` ("unit",
// "image", ...), each once, in the order the output gives them.
std::vector<Naming> namings_in(const std::string& kind, const std::string& output);

// A submission's students: as many as Gradescope's metadata names, else 1.
double students_of(const ClassRow& row);

// How many students passed and failed one checkpoint of a lab.
struct CheckpointRate {
    std::string checkpoint;
    bool hidden = false;  // its test is not visible to students before the due date
    double passed = 0, failed = 0;
};

// One name, with everyone whose report gives it.
struct NamedMistake {
    std::string lab;  // the lab's id
    Naming naming;
    std::map<std::string, std::vector<std::string>>
        submissions;  // key -> its checkpoints that name it
    double students = 0;
    // An example: the failed frame of a checkpoint that names it, relative
    // to DIR (students/KEY/LAB/LAB/CHECKPOINT.png); empty when no such
    // checkpoint has a frame that failed its image check.
    std::string frame, frame_submission, frame_checkpoint;
};

struct ClassFindings {
    // By lab id: its checkpoints, the most failed first, and the students counted.
    std::map<std::string, std::vector<CheckpointRate>> rates;
    std::map<std::string, double> rated;
    std::vector<NamedMistake> mistakes;  // the most students first
};

// Reads the report of each lab of `rows` that ran (neither "not built" nor
// "not graded") under `out`; a report that is missing or not of its form is
// left out.
ClassFindings read_findings(const std::filesystem::path& out, const std::vector<ClassRow>& rows,
                            const std::vector<std::pair<std::string, std::string>>& labs);

}  // namespace grading::cls
