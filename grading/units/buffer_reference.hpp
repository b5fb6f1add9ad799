// Course's references for `buffer` checks (docs/contract.md, Checks): what a
// buffer the lab's shaders wrote (fw::LabBuffer: transform feedback, a compute
// shader) must hold, computed by course in closed form, never by lab code.
// Each lab registers its references in its own folder (labs/NN_name/grading/
// *.cpp, compiled into `course` only), for the lab of that folder:
//
//   grading::BufferExpectation ref_fall(const nlohmann::json& params) {
//       const int steps = params.at("steps"), count = params.at("count");
//       grading::BufferExpectation e{3, {}};   // a vec3 per particle
//       ...                                    // e.values: x, y, z of each particle
//       return e;
//   }
//   COURSE_BUFFER_REFERENCE(fall, &ref_fall, "particle", "is at", {"steps", "count"})
//   COURSE_BUFFER_MISTAKE(fall, "gravity-twice", "gravity applied twice", &ref_fall_twice)
//
// COURSE_BUFFER_REFERENCE(NAME, FN, ELEMENT, VERB, {PARAMS...}): checks name it
// in "reference"; FN computes the expectation from the checkpoint's "params"
// object exactly as checkpoints.json writes it (course never links the lab, so
// the lab's defaults are not filled in: every param FN reads must be in
// PARAMS, and a checkpoint of a check that lacks one is an error when the
// checks are read). FN may throw fw::Error for params it cannot take; that
// error, too, names the checkpoint and the check. ELEMENT is the noun of one
// element ("particle"; plural with -s/-es/-ies) and VERB what the report says
// of it, starting with "is" or "has": "particle 12 is at (0.4, 1.2, 0) but
// should be at (0.4, 0.71, 0); 240 of 256 particles differ".
//
// COURSE_BUFFER_MISTAKE(NAME, ID, SENTENCE, FN): a known wrong answer to
// reference NAME of the same lab. FN computes it from the same params; when
// the lab's buffer matches it (every float within the check's tolerance) the
// report says so: "...; 240 of 256 particles differ: gravity applied twice?"
// and "Likely mistake (gravity-twice): gravity applied twice." ID is stable
// (letters, digits, '-'); the mistake suite names mistakes by it.
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "grading/units/reference.hpp"

namespace grading {

// What a buffer should hold: `components` floats per element, element after
// element (the layout of fw::LabBuffer).
struct BufferExpectation {
    int components = 1;
    std::vector<float> values;
};
// The expectation from the checkpoint's params as written in checkpoints.json.
using BufferReferenceFn = BufferExpectation (*)(const nlohmann::json& params);

struct BufferReference {
    std::string lab;   // lab id, filled in by register_buffer_reference
    std::string name;  // what a check's "reference" gives
    BufferReferenceFn function = nullptr;
    std::string element;              // "particle"
    std::string verb;                 // "is at": starts with "is" or "has"
    std::vector<std::string> params;  // the params a checkpoint must give
};

struct BufferMistake {
    std::string lab;        // lab id, filled in by register_buffer_mistake
    std::string reference;  // the BufferReference's name
    std::string id;         // "gravity-twice"
    std::string sentence;   // "gravity applied twice"
    BufferReferenceFn function = nullptr;
};

// Register for the lab of folder `lab_dir` ("09_particles"), which fills in
// `lab`. Throw fw::Error for a name registered twice, an empty noun, a verb
// that starts with neither "is" nor "has", a null function or a bad ID.
bool register_buffer_reference(std::string_view lab_dir, BufferReference reference);
bool register_buffer_mistake(std::string_view lab_dir, BufferMistake mistake);

// The lab's reference of that name; throws fw::Error listing the lab's
// references when there is none, or when a mistake of the lab names a
// reference that does not exist. The registry owns them for the life of the
// program.
const BufferReference& find_buffer_reference(std::string_view lab, std::string_view name);
// The mistakes registered for a reference, in registration order.
std::vector<const BufferMistake*> buffer_mistakes(std::string_view lab, std::string_view reference);

// "particles", "vertices" ("vertex"), "boxes": an element noun's plural.
std::string plural_noun(const std::string& noun);
// What a reference's VERB says of the expected value: "is at" -> "should be
// at", "has" -> "should have".
std::string expected_verb(const std::string& verb);

}  // namespace grading

// COURSE_BUFFER_REFERENCE(name, &fn, "particle", "is at", {"steps", "count"})
#define COURSE_BUFFER_REFERENCE(NAME, FN, ELEMENT, VERB, ...)                            \
    namespace {                                                                          \
    static_assert(sizeof(FW_LAB_DIR) > 1,                                                \
                  "COURSE_BUFFER_REFERENCE is only for files in labs/NN_name/grading/"); \
    const bool COURSE_REFERENCE_CAT(course_buffer_reference_, __LINE__) =                \
        ::grading::register_buffer_reference(FW_LAB_DIR,                                 \
                                             ::grading::BufferReference{                 \
                                                 "", #NAME, FN, ELEMENT, VERB,           \
                                                 std::vector<std::string> __VA_ARGS__}); \
    }
// COURSE_BUFFER_MISTAKE(name, "id", "what the code did", &fn)
#define COURSE_BUFFER_MISTAKE(NAME, ID, SENTENCE, FN)                                              \
    namespace {                                                                                    \
    static_assert(sizeof(FW_LAB_DIR) > 1,                                                          \
                  "COURSE_BUFFER_MISTAKE is only for files in labs/NN_name/grading/");             \
    const bool COURSE_REFERENCE_CAT(course_buffer_mistake_, __LINE__) =                            \
        ::grading::register_buffer_mistake(FW_LAB_DIR,                                             \
                                           ::grading::BufferMistake{"", #NAME, ID, SENTENCE, FN}); \
    }
