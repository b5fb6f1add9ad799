// A lab's image folder in the report (OUT/LAB): its files are written in
// place from one grading to the next, and the files this grading did not
// write are removed when the lab has been judged (keep_only), so that
// grading the same labs again allocates no new files. A frame equal to its
// reference is a second name (a hard link) of the report's copy of that
// reference; every write first makes its name a file of its own, so that
// writing one name never changes another.
#pragma once

#include <set>
#include <string>

#include "framework/image.hpp"

namespace grading {

// Makes `path` a name of its own: removed when it is one of several names
// of a file (a hard link), so that the next write does not change the others.
void unshare_report_file(const std::string& path);

// Course's own file `from` (a reference) into the report as `to`, not
// encoded again.
void copy_into_report(const std::string& from, const std::string& to);

// `image` encoded as a PNG into the report as `to`.
void write_report_png(const std::string& to, const fw::Image& image);

// `to` becomes a second name of the report's file `existing` (a hard link),
// or a copy of it where the filesystem has no hard links.
void link_in_report(const std::string& existing, const std::string& to);

// Removes every entry of `dir` whose name is not in `names` (a file a
// grading before this one wrote); nothing when `dir` does not exist.
void keep_only(const std::string& dir, const std::set<std::string>& names);

}  // namespace grading
