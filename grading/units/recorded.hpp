// A reference recorded as data: what course's judging of a unit check needs
// from a compiled reference (its shape, domains, tolerance, element names,
// and its results), written to a lab's cases.json (beside the references) by the release so
// that the student's copy, which has no labs/NN_name/grading/*.cpp, can
// still judge its visible unit checks (grading/judge/cases.hpp).
//
// The results are a table, argument list -> result, for every call judging a
// case can make: the reference on the case, the reference on the arguments
// mistake recognition changes (angles negated or converted, with their
// neighbouring floats: of these, only how much the result changes between
// them, ReferenceUnit::float_step) and every alternative on the case. A recorded
// reference answers from that table and throws fw::Error "not recorded" for
// any other argument list, which mistake recognition takes as "no value".
//
// One function's entry in the file:
//   {"shape": {"kind": "matrix", "columns": 4, "rows": 4, "list": false},
//    "element_names": [], "tolerance": 0.0001,
//    "domains": [{"kind": "scalar", "lo": -720, "hi": 720, "degrees": true}],
//    "reference": [[args, result], ...],
//    "float_steps": [[[below, above], [change of element 0, ...]], ...],
//    "alternatives": [{"mistake": "reversed-product", "name": "reversed product",
//                      "table": [[args, result], ...]}],
//    "off_by_one": "..."}  (only where the reference has grading::off_by_one's words)
// Numbers are floats written with 9 significant digits (what identifies a
// float), the tables sorted by their argument lists, so that the same cases
// give the same bytes.
#pragma once

#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "grading/units/reference.hpp"

namespace grading {

// Records the calls judging makes of one compiled reference.
class ReferenceRecorder {
public:
    explicit ReferenceRecorder(const ReferenceUnit& ref);
    // Judges `args` as a case at `tolerance`, with a wrong result for each
    // element of the result in turn, so that every call mistake recognition
    // could make for a student's result is recorded. Throws the reference's
    // error when it does not take `args`.
    void record(const nlohmann::json& args, double tolerance);
    // The function's entry for cases.json (above).
    nlohmann::json entry() const;

private:
    using Table = std::map<std::string, std::pair<nlohmann::json, nlohmann::json>>;
    const ReferenceUnit& ref_;
    ReferenceUnit recording_;  // ref_ with every function recording into a table
    std::shared_ptr<Table> reference_, float_steps_;
    std::vector<std::shared_ptr<Table>> alternatives_;
};

// The reference `name` of an entry as ReferenceRecorder::entry() writes it,
// marked `recorded`; register it with register_reference(). Throws fw::Error
// naming the field when the entry is malformed.
ReferenceUnit recorded_reference(const std::string& name, const nlohmann::json& entry);

// A value with every float rounded to the 9 significant digits that identify
// a float (integers, bools and strings as they are): the form cases.json
// writes, and the key of a recorded table.
nlohmann::json float_digits(const nlohmann::json& value);

}  // namespace grading
