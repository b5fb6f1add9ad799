// A student part still as the release wrote it. A checkpoint may list the
// sheet's parts it needs ("parts": [4]) and the checkpoints file says where
// each part is written, a function in a file:
//
//   "parts": [{"part": 4, "function": "back_to_front",
//              "file": "labs/07_framebuffer_ops/blending.cpp"}, ...]
//
// (a part written in several functions has an entry for each). A function
// still holds its starting code when its body in the student's file
// (LabFiles::sources) is the body of the file's starting version, comments
// left out and whitespace kept only between two names or numbers. The starting version is
// the student version (`course release`) of the file in the staff tree
// (LabFiles::root) where that file has solution blocks, else the file under
// root/student_versions/ (an autograder's folder). A student's own copy
// (`course release`) has neither: there the release wrote each lab's
// starting file, labs/NN_name/grading/starting.json, with a hash of each
// place's starting body,
//
//   {"parts": [{"part": 4, "function": "back_to_front", "fnv1a64": "c7d2bb9f54593c58",
//               "file": "labs/07_framebuffer_ops/blending.cpp"}, ...]}
//
// and a body is the starting one when its hash is that hash. Where none of
// them is found nothing is known and nothing is said.
//
// When a part a failed checkpoint needs still holds its starting code, the
// report says so instead of guessing: "Part 4 (`back_to_front()` in
// labs/07_framebuffer_ops/blending.cpp) still has its starting code; this
// checkpoint needs it." and names no other checkpoint and no mistake, which
// a missing part's frame is no evidence of.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "framework/checkpoints.hpp"
#include "grading/results/results.hpp"

namespace grading {

struct PartPlace {
    int part = 0;
    std::string file;      // relative to the repository
    std::string function;  // its name, as defined at the start of a line
    // The hash of its starting body (starting_hash()) from the lab's
    // starting file, where the tree has one; else empty.
    std::string start;
};

// The file's "parts", checked: every entry has a part number (1, 2, ...), a
// file relative to the repository and a function name; every part a
// checkpoint lists has an entry. Throws fw::UsageError naming the file.
std::vector<PartPlace> read_parts(const fw::CheckpointFile& file);

// `text` (C++ or GLSL) with its comments and string and character literals
// blanked out, so that only code is searched; every newline is kept, so line
// numbers stay the same. The forbidden check (grading/judge/judge_source.hpp)
// searches it too.
std::string code_only(const std::string& text);

// The body of the first definition of `function` in `text` (C++ or GLSL: a
// line that starts unindented with the name's call, then its body in
// braces), comments and literals' text left out, whitespace only where it
// separates two names or numbers; nullopt when there is none.
std::optional<std::string> function_body(const std::string& text, const std::string& function);

// The starting version of `file` (above), or nullopt where it is unknown.
std::optional<std::string> starting_version(const std::string& root, const std::string& file);

// FNV-1a (64 bits) of a body as function_body() gives it, in 16 lowercase
// hexadecimal digits.
std::string starting_hash(const std::string& body);

// The lab's starting file, relative to the repository:
// labs/LAB_DIR/grading/starting.json.
std::string starting_file(const std::string& lab_dir);

// The starting file's text for `places` (a lab's, in the staff tree at
// `root`): an entry for each place whose starting version is known. Nothing
// of the solution is in it.
std::string starting_file_text(const std::string& root, const std::vector<PartPlace>& places);

// Reads the lab's starting file where root has one into the `start` of each
// place it lists (the same part, file and function). Throws fw::UsageError
// naming the file when it is not as starting_file_text() writes it.
void read_starting_file(const std::string& root, const std::string& lab_dir,
                        std::vector<PartPlace>& places);

// Whether `place` is known to hold its starting code in the student's files.
bool still_starting(const std::string& root, const std::string& sources, const PartPlace& place);

// The sentence for a checkpoint whose needed parts (`needed`, of `places`)
// include one that still holds its starting code, naming the first such;
// empty when none does or nothing is known. With `function`, only that
// function's places count (a unit check's own function).
std::string starting_code_sentence(const std::string& root, const std::string& sources,
                                   const std::vector<PartPlace>& places,
                                   const std::vector<int>& needed,
                                   const std::string& function = "");

// Says `sentence` (starting_code_sentence's, "" for none) once under the
// first failed check of a checkpoint's `results`, before what that check
// says, unless a check of them says it already.
void say_starting_code(const std::string& sentence, std::vector<CheckResult>& results);

// Throws fw::UsageError naming the file when a place's file in the staff
// tree has solution blocks but its function has none of them (its starting
// code would be the solution) or is not defined there.
void check_part_places(const std::string& root, const std::string& checkpoints_file,
                       const std::vector<PartPlace>& places);

}  // namespace grading
