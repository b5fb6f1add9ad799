// Which submitted file stands for each file students edit
// (submitted_files.hpp), for `course autograde`.
#include "grading/platforms/submitted_files.hpp"

#include <algorithm>
#include <fstream>
#include <iterator>

#include "framework/error.hpp"

namespace fs = std::filesystem;

namespace grading {

namespace {

std::string real_path(const fs::path& path) {
    std::error_code ec;
    const fs::path real = fs::canonical(path, ec);
    return ec ? "" : real.string();
}

// Regular files named `name` below `dir`, not through links (as find -type f).
std::vector<fs::path> files_named(const fs::path& dir, const std::string& name) {
    std::vector<fs::path> found;
    std::error_code ec;
    fs::recursive_directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec);
    for (; !ec && it != fs::recursive_directory_iterator(); it.increment(ec))
        if (it->path().filename() == name && fs::is_regular_file(it->symlink_status()))
            found.push_back(it->path());
    return found;
}

}  // namespace

bool same_contents(const fs::path& a, const fs::path& b) {
    std::error_code ec;
    if (!fs::is_regular_file(a, ec) || !fs::is_regular_file(b, ec) ||
        fs::file_size(a, ec) != fs::file_size(b, ec))
        return false;
    std::ifstream x(a, std::ios::binary), y(b, std::ios::binary);
    try {
        return x && y &&
               std::equal(std::istreambuf_iterator<char>(x), std::istreambuf_iterator<char>(),
                          std::istreambuf_iterator<char>(y), std::istreambuf_iterator<char>());
    } catch (const std::ios_base::failure&) {
        return false;  // a read error: copy it again
    }
}

bool copy_contents(const fs::path& from, const fs::path& to) {
    std::ifstream in(from, std::ios::binary);
    if (!in) return false;
    std::ofstream out(to, std::ios::binary | std::ios::trunc);
    if (!out) return false;
    // Streaming an empty file would set failbit: an empty file is copied too.
    if (in.peek() != std::ifstream::traits_type::eof()) out << in.rdbuf();
    return !in.bad() && out.flush();
}

std::vector<std::string> read_lines(const fs::path& path) {
    std::ifstream in(path);
    if (!in)
        throw fw::Error("cannot read '" + path.string() +
                        "': the autograder folder lacks its list of student files; write it "
                        "again with `course gradescope` or `course prairielearn`");
    std::vector<std::string> lines;
    for (std::string line; std::getline(in, line);)
        if (!line.empty()) lines.push_back(line);
    return lines;
}

SubmittedFiles::SubmittedFiles(const fs::path& submission, const fs::path& versions,
                               const std::vector<std::string>& files)
    : submission_(submission), real_(real_path(submission)), versions_(versions) {
    for (const std::string& rel : files) ++names_[fs::path(rel).filename().string()];
}

Chosen SubmittedFiles::choose(const std::string& rel) const {
    const std::string name = fs::path(rel).filename().string();
    if (inside(submission_ / rel)) return {submission_ / rel, "submitted"};
    Chosen student{versions_ / rel, "not submitted: graded with the student version"};
    // A name two student files share says nothing of which one it is.
    if (real_.empty() || names_.at(name) > 1) return student;
    const std::vector<fs::path> found = files_named(real_, name);
    if (found.size() == 1 && inside(found[0]))
        return {found[0], "submitted as " + found[0].string().substr(real_.size() + 1)};
    if (found.size() > 1)
        student.how = std::to_string(found.size()) + " files named " + name +
                      " were submitted, none at " + rel + ": graded with the student version";
    return student;
}

bool SubmittedFiles::inside(const fs::path& path) const {
    const std::string real = real_path(path);
    return !real_.empty() && !real.empty() && fs::is_regular_file(real) &&
           real.rfind(real_ + "/", 0) == 0;
}

}  // namespace grading
