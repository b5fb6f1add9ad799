// The files the gradebooks import (lms_export.hpp): a table of points a
// row per student, written as CSV with no blank cell over a grade (split
// into BASE.csv, BASE_2.csv, ... where some students lack some columns),
// Moodle's list of grade items, and an earlier run's files removed.
#pragma once

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "grading/class/gradebook.hpp"
#include "grading/class/roster.hpp"

namespace grading::cls {

// Points as the import files write them: at most two decimals.
std::string import_points(double v);

// A lab's score as an import should take it: none where it was not graded.
std::optional<double> lab_score(const ClassRow& r, const std::string& lab);

// A roster student as messages name them: the name and the SIS login or
// ID number.
std::string roster_who(const RosterStudent& st);

// roster_match.csv (roster_match_file.cpp), for the staff: each roster
// student's submission, how it was found and which of `labs` were not
// graded, then the submissions no roster row names; each line said on
// stderr too.
std::string roster_match_text(const Roster& roster, const RosterMatch& match,
                              const std::vector<ClassRow>& rows,
                              const std::vector<std::string>& labs);

// A file to import: the columns that identify the student, then a column
// of points per lab (or per total); a row per student.
struct ImportTable {
    std::vector<std::string> lead, columns;
    // Canvas's Points Possible row: its identifier cells, a cell per column.
    std::vector<std::string> possible_lead, possible;
    struct Row {
        std::vector<std::string> lead;
        std::vector<std::optional<std::string>> values;  // none: a lab not graded
        std::string who;
    };
    std::vector<Row> rows;
};

// One CSV record, CRLF-ended, each field quoted by `quote`.
std::string line_of(const std::vector<std::string>& fields,
                    std::string (*quote)(const std::string&) = csv_quoted);

// Removes an earlier run's file that this run does not write; says so.
void remove_stale(const std::filesystem::path& file);

// Removes BASE_N.csv from an earlier run for each N >= `from`.
void remove_stale_parts(const std::filesystem::path& out, const std::string& base, size_t from);

// BASE.csv and its BASE_N.csv parts of an earlier run, for each of `bases`.
void remove_all_stale(const std::filesystem::path& out, const std::vector<std::string>& bases);

// Writes BASE.csv with every column and the rows that have a value in each,
// then BASE_2.csv, ... for the other rows (the definition says why).
void write_split(const std::filesystem::path& out, const std::string& base, const ImportTable& t);

// DIR/moodle_items.csv: the grade item to make for each of `labs` (and the
// total), with its maximum from `max`; said on stderr too.
void write_moodle_items(const std::filesystem::path& out, const std::vector<std::string>& labs,
                        bool total, const std::map<std::string, double>& max);

// A cell as Canvas's import reads a number; none for another text.
std::optional<double> canvas_number(const std::string& cell);

}  // namespace grading::cls
