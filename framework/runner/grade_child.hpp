// `lab grade-child --job JOB.json --out DIR [--job ... --out ...]`: what
// `course grade` runs in a child process, for one lab or several in turn. It renders the frames and
// evaluates the unit calls that the job lists, in one context, and writes raw outputs only; it
// decides nothing.
//
// JOB.json (written by `course`):
//   {"lab": "transforms",
//    "renders": [{"name": "trs_default", "params": {"angle": 30}, "width": 512, "height": 512,
//                 "depth": false, "buffers": false, "usage": false}],
//    "units":   [{"function": "translate", "first": 0, "args": [[[1, 2, 3]], [[0, 0, 1]]]}],
//                 (the calls of one function: call k has args[k] and the id u<first + k>)
//    "shader_overrides": {"01_transforms/transforms.vert": "#version 430 ..."}}
//   ("shader_overrides", optional: texts compiled in place of those files of
//   the shader directory for this job, fw::set_shader_overrides)
//
// DIR afterwards:
//   NAME.pam, NAME.stats.json             per render (NAME.error.txt instead on failure)
//   NAME.pfm                              per render whose entry has "depth": true
//   NAME.buffers.json                     per render whose entry has "buffers": true
//                                         (Lab::buffers, framework/lab_buffers.hpp)
//   NAME.usage.json                       per render whose entry has "usage": true, also
//                                         for one that failed (framework/trace/usage.hpp)
//   units.json                            {"u0": {"result": ...} | {"error": "..."}, "u1": ...}
//   child.json                            written last: {"complete": true, "context": {...}}
//
// With --output-fd N every output but child.json is a record on descriptor N
// instead of a file: "OUTPUT SIZE PATH\n" and then SIZE bytes, PATH the file's
// path as above (course grade keeps them in memory; docs/contract.md).
#pragma once

#include <string>
#include <vector>

namespace fw {

void grade_child(const std::string& job_path, const std::string& out_dir,
                 const std::string& backend);

// Several labs in one process, in turn: jobs[i] into outs[i]. Each lab has a
// context of its own, and its child.json appears (by rename) only when all
// of its outputs are written and its output is flushed, so course can tell
// how far the child got and when each lab ended. With several jobs the
// records on `outputs_fd` are written by a thread of their own while the
// lab draws on (output_queue.hpp); with one, each before the lab goes on.
// `outputs_fd`: --output-fd, or -1 for files. With `job_gate_fd`
// (--job-gate-fd), the child reads one byte there before it opens each job
// file: course starts the child first and writes each job as it is planned
// (docs/contract.md, `course grade`); an end of the descriptor before a job
// ends the child with an error.
void grade_children(const std::vector<std::string>& jobs, const std::vector<std::string>& outs,
                    const std::string& backend, int outputs_fd = -1, int job_gate_fd = -1);

}  // namespace fw
