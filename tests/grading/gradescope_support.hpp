// The end-to-end autograder of the gradescope tests (test_gradescope*.cpp):
// `course gradescope` writes the folder, set up as Gradescope would
// (grading/platforms/gradescope/setup.sh, without apt) in a fake /autograder and built
// once for every test case of the executable; submit() then runs
// run_autograder on a submission, and the checks compare its results.json
// with what the data files promise.
#pragma once

#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace gradescope_test {

namespace fs = std::filesystem;
using nlohmann::json;

// What the data files promise (computed here, not by course): for each
// "lab / checkpoint", how many checks; and the points of them all.
struct Expected {
    std::map<std::string, int> checks;
    std::set<std::string> hidden;  // "lab / checkpoint" of the hidden checkpoints
    double points = 0;
    std::string victim;      // lab 0's name ("lab" in labs/00_*/checkpoints.json)
    std::string victim_dir;  // its folder, e.g. 00_pipeline
};

// A run of run_autograder.
struct Run {
    int exit_code = -1;
    std::string output;  // run_autograder's stdout and stderr
    double seconds = 0;
    json results;                               // results/results.json
    size_t results_bytes = 0;                   // its size
    std::map<std::string, double> lab_seconds;  // from results/grade/summary.txt
};

// The autograder, set up once for every test case.
struct Autograder {
    fs::path dir, root;  // root: the fake /autograder
    std::string user;    // AUTOGRADER_USER; run-as applies when the test runs as root
    std::vector<std::string> student_files;
    std::map<std::string, std::string> solution_text;  // student file -> as copied
    std::map<std::string, std::string> scripts;        // setup.sh, run_autograder -> as copied
    Expected expected;
    std::string failure;  // why it could not be set up
    std::optional<Run> solution;
};

// The autograder, set up on first use; a failed set-up fails the test case.
Autograder& autograder();

// For a setup.sh that builds the tree at `source`: the environment ("NAME=value
// ... ") that makes its build go through ccache, named by paths inside the
// tree, so that set-ups of other copies share the cache's objects; "" when
// ccache is not installed.
std::string ccache_setup_env(const fs::path& source);

// Builds the submission folder from `files` (path in the submission -> text)
// and runs run_autograder on it, with `env` ("NAME=value ...") added.
Run submit(const Autograder& ag, const std::string& what,
           const std::map<std::string, std::string>& files, const std::string& env = "");

// The run of the solution, uploaded flat, made on first use.
const Run& solution_run(Autograder& ag);

// The lab of a results.json test: "lab" of "lab / checkpoint / check".
std::string lab_of(const json& test);

// results.json is complete: every check of every lab, each with its fields,
// the points adding up to the data files' total.
void check_complete(const Run& run, const Expected& e);
// The labs other than the victim (lab 0) score test by test as the solution does.
void check_others_unaffected(Autograder& ag, const Run& run);
// Every check of the victim lab failed for `reason`; the others as with the solution.
void check_victim_failed(Autograder& ag, const Run& run, const std::string& reason);

// The student file of lab 0 under `top` (labs or shaders): its C++ or a shader.
std::string victim_file(const Autograder& ag, const std::string& top, bool shader);
// The solution's student files, at their paths, with `code` added to the
// first solution block of `file`: after its first line, or before its last
// (`at_end`); `includes` goes at the top of the file.
std::map<std::string, std::string> hostile(const Autograder& ag, const std::string& file,
                                           const std::string& code, bool at_end,
                                           const std::string& includes = "");

// Which file is wrong (docs/contract.md) on the autograders: lab 7's
// cutout.frag discarding the opaque fragments instead of the transparent
// ones, and its set_blend_mode with the factors of "over" swapped (C++),
// each a change of one line of the solution's student files `files` (by
// path under the repository).
constexpr const char* kIsolationLab = "framebuffer-ops";
constexpr const char* kIsolationShader = "shaders/07_framebuffer_ops/cutout.frag";
std::map<std::string, std::string> shader_mistake(std::map<std::string, std::string> files);
std::map<std::string, std::string> cpp_mistake(std::map<std::string, std::string> files);
// How many times `text` says which shader file is wrong (any file); and
// the sentence that names `file` (under the repository: shaders/...).
size_t isolation_mentions(const std::string& text);
std::string isolation_sentence(const std::string& file);

// A small fake /autograder for `course autograde`'s error paths, which
// builds nothing of the repository (test_autograde.cpp and the PrairieLearn
// tests): source/ holds lab 0's data file and references, one student file
// (solution and student version), course (a link to this build's) and a
// configured build whose `lab` target runs `lab_script` in the build folder;
// submission/ holds that file, uploaded flat. In out_dir()/NAME.
fs::path make_root(const std::string& name, const std::string& lab_script);

// `lab` scripts for make_root(): a compiler's message with everything JSON
// must escape or drop, then failure; and a `lab` that builds (bin/lab, a
// program that does nothing).
extern const char* const kHostileLog;
extern const char* const kBuilds;
// kHostileLog's text is in `output`, without its control characters.
void check_log_kept(const std::string& output);

}  // namespace gradescope_test
