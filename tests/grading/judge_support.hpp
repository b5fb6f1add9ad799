// Helpers for the tests that judge a check without a child: a lab built in
// memory, and a work directory read back as a child's outputs.
#pragma once

#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "grading/judge/checks.hpp"
#include "tests/support/test_support.hpp"

namespace judge_test {

// A lab `id` in labs/`dir`, of the checkpoints given, its checks parsed.
inline grading::LabData lab_of(const std::string& id, const std::string& dir,
                               std::vector<fw::Checkpoint> checkpoints) {
    grading::LabData lab;
    lab.id = id;
    lab.dir = dir;
    lab.root = fw::test::out_dir() + "/root";
    lab.file.path = "labs/" + dir + "/checkpoints.json";
    lab.file.lab = lab.id;
    lab.file.checkpoints = std::move(checkpoints);
    grading::parse_checks(lab);
    return lab;
}

// A checkpoint `name` of `checks`, with `params`.
inline fw::Checkpoint checkpoint(const std::string& name, const nlohmann::json& checks,
                                 const nlohmann::json& params = nlohmann::json::object()) {
    fw::Checkpoint cp;
    cp.name = name;
    cp.params = params;
    cp.checks = checks;
    return cp;
}

// A work directory holding `files`, read back as a child's that exited normally.
struct Outputs {
    std::string dir;
    grading::ChildRun run;
    std::unique_ptr<grading::ChildOutputs> outputs;
    using Files = std::vector<std::pair<std::string, std::string>>;
    explicit Outputs(const Files& files) {
        dir = fw::test::out_dir() + "/outputs";
        std::filesystem::remove_all(dir);
        std::filesystem::create_directories(dir);
        for (const auto& [name, text] : files) fw::test::write_text(dir + "/" + name, text);
        outputs = std::make_unique<grading::ChildOutputs>(dir, run, grading::ChildLimits{});
    }
};

}  // namespace judge_test
