// What `course grade` found: one CheckResult per check of every checkpoint of
// every lab. The reports (summary.txt, results.json, junit.xml, index.html)
// are all written from this one structure.
#pragma once

#include <string>
#include <vector>

namespace grading {

struct CheckResult {
    std::string lab;
    std::string checkpoint;
    std::string kind;        // image | probe | stat | unit
    std::string title;       // e.g. "probe (256, 256) colour", "image vs reference"
    std::string visibility;  // visible | hidden
    double score = 0.0;
    double max_score = 0.0;
    bool passed = false;
    // Expected / observed, thresholds and measured figures, or why the check
    // could not run (the child crashed, timed out, wrote no image...).
    std::string output;
    // Images for the HTML report, relative to the output directory; empty
    // where the check has none.
    std::string rendered, expected, difference;
};

struct LabResult {
    std::string lab;
    // "ok", or what went wrong with the child as a whole: "crashed (signal 11,
    // SIGSEGV)", "timed out after 60 s", "exit status 1", "output unreadable: ...".
    std::string status = "ok";
    std::string log;  // the last part of the child's stdout and stderr
    double seconds = 0.0;
    std::vector<CheckResult> checks;

    double score() const;
    double max_score() const;
    bool passed() const;  // every check passed
};

// One layer of the sandbox around the lab children.
struct SandboxLayer {
    std::string name;  // "seccomp filter", "namespaces", ...
    bool active = false;
    std::string detail;  // what it does, or why it is not used
};

struct GradeRun {
    std::vector<LabResult> labs;
    std::string backend;  // as asked: auto, osmesa, egl
    double seconds = 0.0;
    // The sandbox's layers, active or not (grading/sandbox.hpp), for
    // summary.txt, index.html and results.json.
    std::vector<SandboxLayer> sandbox;

    double score() const;
    double max_score() const;
    bool passed() const;
};

}  // namespace grading
