// Recorded unit cases: a lab's cases.json in labs/NN_name/grading/, which the
// release writes into the student's copy in place of the lab's references
// (labs/NN_name/grading/*.cpp give the solutions away), so that `course`
// built there still judges the visible unit checks.
//
// Writing it (course release, or `course cases LAB --out FILE`):
//
//   std::vector<LabData> labs = select_labs(discover_labs(source_root()), {"transforms"});
//   parse_checks(labs[0]);
//   const nlohmann::json cases = record_unit_cases(labs[0], seed, 50);
//   write_unit_cases(out + "/labs/" + labs[0].dir + "/grading/cases.json", cases);
//
// Reading it: parse_checks() loads the file of a lab that has one. Each of
// its functions that `course` has no compiled reference for becomes a
// recorded reference (grading/units/recorded.hpp; compiled ones always win),
// and the plan of a unit check of such a function takes the check's recorded
// random cases, in order, instead of drawing them (the edge cases come from
// checkpoints.json as always, and must be among those recorded).
//
// The file:
//   {"format": 1, "lab": "transforms", "seed": 7, "max_random": 50, "for": "student copy",
//    "functions": {"translate": <a recorded reference, recorded.hpp>, ...},
//    "checks": [{"checkpoint": "translate", "check": 3, "function": "translate",
//                "random": [[args], ...]},
//               {"checkpoint": "falling", "check": 0, "buffer": {"reference": "fall",
//                "element": "particle", "verb": "is at", "components": 3, "values": [...],
//                "mistakes": [{"id", "sentence", "components", "values"}]}}, ...]}
// "check" is the index in the checkpoint's checks, from 0. A buffer check's
// entry holds what course computed from the checkpoint's params (its
// reference in labs/NN_name/grading/*.cpp gives the solution away too); a
// compiled reference wins over it.
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "grading/judge/checks.hpp"

namespace grading {

// The cases of every unit check of every visible checkpoint of `lab` (its
// checks parsed with parse_checks(), its references compiled): min(random,
// max_random) random argument lists per check, drawn from `seed`, and for
// every function the table of results judging needs (recorded.hpp). The
// same lab and seed give the same value. Throws fw::Error when a function
// has no compiled reference.
//
// For whom: a student's copy (`course release`) gets the visible checks only;
// an autograder without references (PrairieLearn's public image) gets every
// check, hidden ones too, and keeps the file where students cannot read it.
enum class RecordFor { StudentCopy, Autograder };
nlohmann::json record_unit_cases(const LabData& lab, unsigned seed, int max_random,
                                 RecordFor recorded_for = RecordFor::StudentCopy);

// Writes `cases` to `path` (its folder created), compactly, one line.
void write_unit_cases(const std::string& path, const nlohmann::json& cases);

// root/labs/NN_name/grading/cases.json.
std::string unit_cases_path(const LabData& lab);

// A check's recorded random argument lists, by checkpoint name and check index;
// for a buffer check, its expectation and its reference's known mistakes.
struct RecordedCheck {
    std::string function;
    std::vector<nlohmann::json> random;
    std::optional<BufferCheck> buffer;
};
using RecordedChecks = std::map<std::pair<std::string, size_t>, RecordedCheck>;

// Reads the lab's cases.json, if it has one (else nothing), registers its
// recorded references (register_reference) and returns its checks' cases.
// Throws fw::UsageError naming the file when it is malformed.
RecordedChecks load_unit_cases(const LabData& lab);

}  // namespace grading
