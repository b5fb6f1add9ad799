// Content hashes of grade-class: git's own (SHA-1 of the text as a blob, as
// `git hash-object` gives it), so that a file's hash in grades.csv can be
// looked up in a student's repository.
#pragma once

#include <string>

namespace grading::cls {

// 40 lowercase hexadecimal digits.
std::string content_hash(const std::string& text);

}  // namespace grading::cls
