// Parts of the class's page (class_page.hpp): the histogram of a lab's
// scores, the named mistakes, and the submissions to look at.
#pragma once

#include <filesystem>
#include <string>
#include <utility>
#include <vector>

#include "grading/class/class_findings.hpp"
#include "grading/class/class_submission.hpp"

namespace grading::cls {

// Scores in bins of equal width from 0 to the lab's points: about ten
// bins, of a whole number of points where the lab's points are whole; a
// bin holds [from, from + width), the last one its upper end too.
struct Histogram {
    double width = 1, max = 0;
    std::vector<double> from;    // each bin's lower end
    std::vector<size_t> counts;  // students in it
};
Histogram histogram(const std::vector<double>& scores, double max);

// The histogram as inline SVG (role img, named by its <title>), and its
// numbers in a table; `id` is unique on the page.
std::string histogram_html(const Histogram& h, const std::string& lab, const std::string& id);

// The named mistakes, the most students first, with an example frame
// (students/KEY/LAB/LAB/CHECKPOINT.png under `out`, inline) and the students.
std::string mistakes_html(const std::filesystem::path& out, const std::vector<ClassRow>& rows,
                          const ClassFindings& findings);

// The submissions that did not build (with the compiler's first error),
// that timed out or crashed, and that could not be graded.
std::string attention_html(const std::vector<ClassRow>& rows,
                           const std::vector<std::pair<std::string, std::string>>& labs);

}  // namespace grading::cls
