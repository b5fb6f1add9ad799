// Helpers for the tests that change a copy of the repository, build it and
// grade it with `course grade`: the release tests (test_release_tree.cpp) and
// the mistake suite (tests/mistakes/).
#pragma once

#include <chrono>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <vector>

#include "tests/support/test_support.hpp"

namespace tree_test {

namespace fs = std::filesystem;

double seconds_since(std::chrono::steady_clock::time_point start);

// Runs `command`, printing its time and exit status; on failure (exit status
// other than 0, and than 1 when `may_fail`: `course grade` when a check
// fails) shows its output's tail.
fw::test::CommandResult run(const std::string& command, bool may_fail = false);

// The number of parallel jobs for builds and `course grade --jobs`.
std::string jobs();

// Configures (the suite's build type, warnings as errors; the tree's own
// CMakeLists.txt compiles through ccache when it is installed) and builds
// `targets` of the tree at `source` into source/build.
// Fails the test case when either step fails.
void build_tree(const fs::path& source, const std::string& targets);

// Builds `targets` of a tree that build_tree() configured; whether it built.
bool rebuild_tree(const fs::path& source, const std::string& targets);

// One entry of results.json's "tests", by name. Entries of the same name
// (none today) are summed.
struct Entry {
    double score = 0.0, max_score = 0.0;
    std::string visibility;  // "visible" or "hidden"
    std::string output;
};

struct Grade {
    int exit_code = -1;
    std::string output;
    nlohmann::json results;                     // results.json
    std::map<std::string, std::string> status;  // lab -> its status in summary.txt
    std::set<std::string> passed, failed;       // names of the entries
    std::map<std::string, Entry> entries;
};

// `course grade LABS --lab LAB --out OUT` (LABS empty: every lab) in an
// environment without LAB_ROOT and LAB_SHADER_DIR but with `env` (VAR=value
// ...).
Grade grade(const std::string& course, const std::string& lab, const std::string& labs,
            const fs::path& out, const std::string& env = "");

// What a change costs on the checks students see before the deadline: each
// entry of `solution` that is visible, has full marks there and scores less
// in `changed` (an entry missing there scores 0), with the points it lost,
// over the labs that `changed` graded. Entries are matched by name, whether
// results.json has one per check or one per checkpoint.
struct Loss {
    std::string name;
    double points = 0.0;
};
std::vector<Loss> visible_losses(const Grade& solution, const Grade& changed);

// The labs with a checkpoints file, by folder (NN_name).
std::vector<std::string> lab_dirs(const fs::path& root);

// The lab folder a file belongs to (labs/NN_name/..., shaders/NN_name/...);
// empty for shared code (framework/), which every lab uses.
std::string lab_of(const std::string& file);

// Whether a repository file is under shaders/, which the built `lab` reads
// from LAB_SHADER_DIR at run time (no rebuild).
bool is_shader(const std::string& file);

// Makes `copy` hold the project's `files` as in `source`, rewriting only what
// differs so that its build (copy/build) stays incremental between runs.
void sync_tree(const fs::path& source, const fs::path& copy, const std::vector<std::string>& files);

}  // namespace tree_test
