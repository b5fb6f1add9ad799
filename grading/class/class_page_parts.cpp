#include "grading/class/class_page_parts.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <map>
#include <sstream>

#include "framework/text.hpp"
#include "grading/report/by_checkpoint.hpp"
#include "grading/report/report_text.hpp"

namespace grading::cls {

namespace fs = std::filesystem;
using report::escape_markup;
using report::points;

namespace {

// A frame larger than this is linked, not inlined.
constexpr std::streamoff kInlineFrameBytes = 1 << 20;

// A path relative to the page, for an href or src: each byte but the
// unreserved ones and '/' percent-encoded (a submission's key is a folder's
// name, which may hold anything).
std::string href(const std::string& relative) {
    static const char* const kHex = "0123456789ABCDEF";
    std::string out;
    for (unsigned char c : relative) {
        if (std::isalnum(c) || c == '-' || c == '.' || c == '_' || c == '~' || c == '/') {
            out += char(c);
        } else {
            out += '%';
            out += kHex[c >> 4];
            out += kHex[c & 15];
        }
    }
    return out;
}

// A submission as the page names it: its key, and its students' names
// where Gradescope's metadata gives them.
std::string who(const ClassRow& r) {
    std::vector<std::string> names;
    for (const Student& s : r.submission.students)
        names.push_back(!s.name.empty() ? s.name : !s.email.empty() ? s.email : s.sid);
    return escape_markup(r.submission.key) +
           (names.empty() ? "" : " (" + escape_markup(fw::join(names, ", ")) + ")");
}

// A link to the submission's report of `lab`, named by who().
std::string report_link(const ClassRow& r, const std::string& lab) {
    return "<a href=\"" + href("students/" + r.submission.key + "/" + lab + "/index.html") + "\">" +
           who(r) + "</a>";
}

std::string number(double v) { return fw::trimmed_decimals(v, 1); }

std::string bin_label(const Histogram& h, size_t i) {
    const bool last = i + 1 == h.from.size();
    return points(h.from[i]) +
           (last ? " to " + points(h.max) : " to under " + points(h.from[i] + h.width));
}

std::string histogram_svg(const Histogram& h, const std::string& lab, const std::string& id) {
    const double left = 56, top = 20, pw = 568, ph = 184;
    const size_t n = h.counts.size();
    const size_t most = std::max<size_t>(1, *std::max_element(h.counts.begin(), h.counts.end()));
    const double bw = pw / double(n);
    std::ostringstream s;
    s << "<svg class=\"histogram\" xmlns=\"http://www.w3.org/2000/svg\" role=\"img\" "
         "aria-labelledby=\""
      << id << "-title\" viewBox=\"0 0 640 260\" width=\"640\" height=\"260\" font-size=\"12\" "
      << "fill=\"#222\">\n<title id=\"" << id << "-title\">Histogram of the scores in "
      << escape_markup(lab) << ": students (up) by points (across); the table below gives its "
      << "numbers</title>\n<g stroke=\"#555\"><line x1=\"" << left << "\" y1=\"" << top + ph
      << "\" x2=\"" << left + pw << "\" y2=\"" << top + ph << "\"/><line x1=\"" << left
      << "\" y1=\"" << top << "\" x2=\"" << left << "\" y2=\"" << top + ph << "\"/></g>\n";
    for (size_t i = 0; i < n; ++i) {
        const double x = left + bw * double(i), bh = ph * double(h.counts[i]) / double(most);
        if (h.counts[i] > 0)
            s << "<rect x=\"" << number(x + 1) << "\" y=\"" << number(top + ph - bh)
              << "\" width=\"" << number(bw - 2) << "\" height=\"" << number(bh)
              << "\" fill=\"#1a56a8\"/><text x=\"" << number(x + bw / 2) << "\" y=\""
              << number(top + ph - bh - 4) << "\" text-anchor=\"middle\">" << h.counts[i]
              << "</text>\n";
    }
    for (size_t i = 0; i <= n; ++i)
        s << "<text x=\"" << number(left + bw * double(i)) << "\" y=\"" << top + ph + 16
          << "\" text-anchor=\"middle\">" << points(i < n ? h.from[i] : h.max) << "</text>\n";
    s << "<text x=\"" << left - 6 << "\" y=\"" << top + 4 << "\" text-anchor=\"end\">" << most
      << "</text><text x=\"" << left - 6 << "\" y=\"" << top + ph + 4
      << "\" text-anchor=\"end\">0</text>\n<text x=\"" << left + pw / 2
      << "\" y=\"250\" text-anchor=\"middle\">points</text><text transform=\"rotate(-90)\" x=\""
      << -(top + ph / 2) << "\" y=\"20\" text-anchor=\"middle\">students</text>\n</svg>\n";
    return s.str();
}

}  // namespace

Histogram histogram(const std::vector<double>& scores, double max) {
    Histogram h;
    h.max = max;
    if (max <= 0) return h;
    const bool whole = std::abs(max - std::round(max)) < 1e-9;
    h.width = whole ? std::max(1.0, std::ceil(max / 10)) : max / 10;
    const size_t n = std::max<size_t>(1, size_t(std::ceil(max / h.width - 1e-9)));
    for (size_t i = 0; i < n; ++i) h.from.push_back(double(i) * h.width);
    h.counts.assign(n, 0);
    for (double s : scores) {
        const double bin = std::floor(s / h.width + 1e-9);
        ++h.counts[size_t(std::clamp(bin, 0.0, double(n - 1)))];
    }
    return h;
}

std::string histogram_html(const Histogram& h, const std::string& lab, const std::string& id) {
    if (h.counts.empty()) return "";
    std::ostringstream s;
    s << histogram_svg(h, lab, id) << "<table class=\"labs\">\n<caption>Scores in "
      << escape_markup(lab) << ": students by points</caption>\n"
      << "<tr><th scope=\"col\">points</th><th scope=\"col\">students</th></tr>\n";
    for (size_t i = 0; i < h.counts.size(); ++i)
        s << "<tr><th scope=\"row\">" << bin_label(h, i) << "</th><td class=\"num\">" << h.counts[i]
          << "</td></tr>\n";
    s << "</table>\n";
    return s.str();
}

namespace {

// The frame as an <img> inside a link to its file; the link alone where it
// cannot be read or is too large to inline.
std::string frame_html(const fs::path& out, const NamedMistake& m) {
    if (m.frame.empty())
        return "none: no checkpoint that names it has a frame that failed its image check";
    const std::string caption = m.frame_submission + ", checkpoint " + m.frame_checkpoint;
    std::ifstream file(out / m.frame, std::ios::binary | std::ios::ate);
    std::string bytes;
    if (file && file.tellg() <= kInlineFrameBytes) {
        file.seekg(0);
        bytes.assign(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
    }
    if (bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0)
        return "<a href=\"" + href(m.frame) + "\">" + escape_markup(caption) + "</a>";
    return "<a href=\"" + href(m.frame) + "\"><img class=\"frame\" src=\"data:image/png;base64," +
           base64(bytes) + "\" alt=\"" +
           escape_markup("The frame of checkpoint " + m.frame_checkpoint + " in " +
                         m.frame_submission + "'s report") +
           "\"></a><small>" + escape_markup(caption) + "</small>";
}

std::string mistake_row(const fs::path& out, const NamedMistake& m, size_t rank,
                        const std::map<std::string, const ClassRow*>& by_key) {
    std::ostringstream h;
    h << "<tr><td class=\"num\">" << rank << "</td><th scope=\"row\">"
      << escape_markup(m.naming.name) << "<details><summary>as the report says it</summary><pre>"
      << escape_markup(m.naming.sentence) << "</pre></details></th><td>" << escape_markup(m.lab)
      << "</td><td class=\"num\">" << points(m.students) << "</td><td><ul>\n";
    for (const auto& [key, checkpoints] : m.submissions) {
        const auto row = by_key.find(key);
        h << "<li>" << (row == by_key.end() ? escape_markup(key) : report_link(*row->second, m.lab))
          << ": " << escape_markup(fw::join(checkpoints, ", ")) << "</li>\n";
    }
    h << "</ul></td><td>" << frame_html(out, m) << "</td></tr>\n";
    return h.str();
}

}  // namespace

std::string mistakes_html(const fs::path& out, const std::vector<ClassRow>& rows,
                          const ClassFindings& f) {
    std::ostringstream h;
    h << "<section class=\"part\" id=\"mistakes\">\n<h2>Named mistakes</h2>\n"
      << "<p>The mistakes the reports name, the most students first: a unit or buffer check's "
         "\"Likely mistake (ID)\", an image check's frame that a known mistake draws, or that "
         "another checkpoint expects. A failed check that names none is not counted here.</p>\n";
    if (f.mistakes.empty()) {
        h << "<p>No report names a mistake.</p>\n</section>\n";
        return h.str();
    }
    std::map<std::string, const ClassRow*> by_key;
    for (const ClassRow& r : rows) by_key[r.submission.key] = &r;
    h << "<table class=\"labs\">\n<caption>Named mistakes, the most students first</caption>\n"
      << "<tr><th scope=\"col\">rank</th><th scope=\"col\">mistake</th><th scope=\"col\">lab</th>"
         "<th scope=\"col\">students</th><th scope=\"col\">submissions (the checkpoints that "
         "name it)</th><th scope=\"col\">example frame</th></tr>\n";
    for (size_t i = 0; i < f.mistakes.size(); ++i)
        h << mistake_row(out, f.mistakes[i], i + 1, by_key);
    h << "</table>\n</section>\n";
    return h.str();
}

namespace {

// A table of `rows` under `heading`, or `none` when there are none.
std::string listing(const std::string& heading, const std::string& head,
                    const std::vector<std::string>& rows, const std::string& none) {
    std::string h = "<h3>" + heading + " (" + std::to_string(rows.size()) + ")</h3>\n";
    if (rows.empty()) return h + "<p>" + none + "</p>\n";
    h += "<table class=\"labs\">\n<caption>" + heading + "</caption>\n<tr>" + head + "</tr>\n";
    for (const std::string& r : rows) h += r;
    return h + "</table>\n";
}

std::string first_lab_not_built(const ClassRow& r) {
    for (const auto& [id, g] : r.labs)
        if (g.status == "not built") return id;
    return "";
}

}  // namespace

std::string attention_html(const std::vector<ClassRow>& rows,
                           const std::vector<std::pair<std::string, std::string>>& labs) {
    std::vector<std::string> unbuilt, stopped, ungraded;
    for (const ClassRow& r : rows) {
        if (!r.error.empty())
            ungraded.push_back("<tr><th scope=\"row\">" + who(r) + "</th><td>every lab</td><td>" +
                               escape_markup(r.error) + "</td></tr>\n");
        if (const std::string lab = first_lab_not_built(r); !lab.empty())
            unbuilt.push_back("<tr><th scope=\"row\">" + report_link(r, lab) + "</th><td><pre>" +
                              escape_markup(r.first_error.empty() ? "(the compiler said no error)"
                                                                  : r.first_error) +
                              "</pre></td></tr>\n");
        for (const auto& [id, dir] : labs) {
            const auto g = r.labs.find(id);
            if (g == r.labs.end() || g->second.status == "graded" ||
                g->second.status == "not built" || (!r.error.empty()))
                continue;
            const bool not_graded = g->second.status == "not graded";
            (not_graded ? ungraded : stopped)
                .push_back("<tr><th scope=\"row\">" + report_link(r, id) + "</th><td>" +
                           escape_markup(id) + "</td><td>" +
                           escape_markup(not_graded ? g->second.reason : g->second.status) +
                           "</td></tr>\n");
        }
    }
    return "<section class=\"part\" id=\"attention\">\n<h2>Submissions to look at</h2>\n" +
           listing("Did not build",
                   "<th scope=\"col\">submission</th><th scope=\"col\">the compiler's first "
                   "error</th>",
                   unbuilt, "Every submission built.") +
           listing("Timed out or crashed",
                   "<th scope=\"col\">submission</th><th scope=\"col\">lab</th><th "
                   "scope=\"col\">what stopped it</th>",
                   stopped, "No lab timed out or crashed.") +
           listing("Not graded",
                   "<th scope=\"col\">submission</th><th scope=\"col\">lab</th><th "
                   "scope=\"col\">why</th>",
                   ungraded, "Every submission was graded.") +
           "</section>\n";
}

}  // namespace grading::cls
