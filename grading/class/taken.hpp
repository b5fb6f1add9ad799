// What grade-class took from one submission (class_submission.cpp), kept in
// DIR/.class/taken/KEY.json, so that a later run that finds the same files
// (submissions.hpp, source_key) and the same student files to choose from
// need not unpack the submission to know that nothing changed.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace grading::cls {

struct Taken {
    std::string key;                            // the source's key and what choosing depends on
    std::string graded;                         // ClassRow::graded
    std::vector<std::string> missing, extra;    // ClassRow's
    std::map<std::string, std::string> hashes;  // each student file's content hash
    std::string files_txt;                      // the text of its files.txt
};

// None when there is none, or it cannot be read.
std::optional<Taken> read_taken(const std::filesystem::path& file);

// Written whole or not at all; where it cannot be written (a file name that
// is not UTF-8), none is kept.
void write_taken(const std::filesystem::path& file, const Taken& taken);

}  // namespace grading::cls
