// `lab grade-child --job JOB.json --out DIR`: what `course grade` runs in a
// child process. It renders the frames and evaluates the unit calls that the
// job lists, in one context, and writes raw outputs only; it decides nothing.
//
// JOB.json (written by `course`):
//   {"lab": "transforms",
//    "renders": [{"name": "trs_default", "params": {"angle": 30}, "width": 512, "height": 512,
//                 "depth": false, "buffers": false}],
//    "units":   [{"id": "u0", "function": "translate", "args": [[1, 2, 3]]}]}
//
// DIR afterwards:
//   NAME.pam, NAME.stats.json             per render (NAME.error.txt instead on failure)
//   NAME.pfm                              per render whose entry has "depth": true
//   NAME.buffers.json                     per render whose entry has "buffers": true
//                                         (Lab::buffers, framework/lab_buffers.hpp)
//   units.json                            {"u0": {"result": ...} | {"error": "..."}}
//   child.json                            written last: {"complete": true, "context": {...}}
#pragma once

#include <string>

namespace fw {

void grade_child(const std::string& job_path, const std::string& out_dir,
                 const std::string& backend);

}  // namespace fw
