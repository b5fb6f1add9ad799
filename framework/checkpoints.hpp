// Checkpoints: named parameter sets with points and checks, read from the
// data file beside the lab (labs/NN_name/checkpoints.json; JSON with //
// comments allowed). `lab` only reads names and parameters; `course` alone
// reads the checks and decides pass or fail. The lab is the one of the
// file's folder.
//
//   {"checkpoints": [
//     {"name": "order_depth", "visibility": "visible",
//      "params": {"scene": "order", "depth_test": true},
//      "checks": [{"kind": "image", "points": 2},
//                 {"kind": "probe", "at": [256, 256], "color": [0, 0, 1], "points": 1}]}
//   ]}
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "framework/lab.hpp"

namespace fw {

struct Checkpoint {
    std::string name;
    std::string visibility = "visible";  // "visible" or "hidden"
    std::string description;
    nlohmann::json params = nlohmann::json::object();  // name -> value, as written
    nlohmann::json checks = nlohmann::json::array();   // raw; interpreted by `course`
    // The numbers of the sheet's parts the checkpoint needs ("parts": [4]);
    // the file's "parts" says where each is. Only `course` reads them.
    std::vector<int> parts;
};

struct CheckpointFile {
    std::string path;
    std::string lab;  // the lab's id, from the folder's name
    std::vector<Checkpoint> checkpoints;
    // A student's copy (`course release`) says what it left out: the number
    // of hidden checkpoints and their points ("hidden": {"checkpoints": N,
    // "points": P}); zero elsewhere.
    int hidden_checkpoints = 0;
    double hidden_points = 0.0;
    // The file's top-level "parts": where each of the sheet's parts is
    // written ([{"part": 4, "function": "back_to_front", "file": "labs/..."}]),
    // raw; `course` reads it (grading/diagnosis/starting_code.hpp).
    nlohmann::json parts = nlohmann::json::array();
};

// Reads the file and checks its structure (fields, names, visibility) without
// the lab's declaration; `course`, which never links lab code, reads it so.
CheckpointFile read_checkpoint_file(const std::string& path);

// Reads and validates the lab's checkpoints file: every parameter name and
// value is checked against the lab's declaration, names must be unique.
// Throws Error with the file path (and line for JSON syntax errors).
std::vector<Checkpoint> load_checkpoints(const RegisteredLab& lab);
std::vector<Checkpoint> load_checkpoints(const RegisteredLab& lab, const std::string& path);

// Throws UsageError listing the valid names.
const Checkpoint& find_checkpoint(const std::vector<Checkpoint>& all, const std::string& name,
                                  const std::string& lab_id);

// Defaults, then the checkpoint's values.
ParamValues checkpoint_params(const RegisteredLab& lab, const Checkpoint& cp);

}  // namespace fw
