// The course's seed: where the random arguments of unit checks come from.
// A submission's points are a function of its files and the course, so the
// seed is fixed per course, in labs/course_seed.json, which `course bless`
// makes once (from the system's entropy) and the course commits:
//
//   {"seed": 2718281828}
//
// Each checkpoint draws from its own stream, seeded by this seed, the lab's
// id and the checkpoint's name (plan_lab), so every run, layout, shard and
// machine draws the same cases. COURSE_SEED overrides the file; a tree
// without either (a student's copy, whose checks use recorded cases, or a
// course not yet blessed) uses seed 0. `course release` leaves the file out
// of the student's copy: with it, a student could draw the hidden cases.
#pragma once

#include <string>

namespace grading {

// "labs/course_seed.json", relative to the repository.
constexpr const char* kCourseSeedFile = "labs/course_seed.json";

struct CourseSeed {
    unsigned value = 0;
    // Where it came from, for the report: "COURSE_SEED", "labs/course_seed.json",
    // or "none set (course bless makes labs/course_seed.json)".
    std::string from;
};

// COURSE_SEED when set, else the file under `root`, else 0. Throws
// fw::UsageError for a COURSE_SEED that is not a number from 0 to 2^32 - 1,
// or a file that does not hold {"seed": that}.
CourseSeed course_seed(const std::string& root);

// Makes root/labs/course_seed.json from the system's entropy when it does
// not exist; returns the seed made, or nothing when the file was there.
bool make_course_seed(const std::string& root, unsigned& made);

}  // namespace grading
