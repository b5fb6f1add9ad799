#include "grading/class/class_findings.hpp"

#include <algorithm>
#include <cctype>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "framework/error.hpp"
#include "framework/text.hpp"
#include "grading/release/release.hpp"
#include "grading/results/results.hpp"

namespace grading::cls {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

const std::string kLikely = "Likely mistake (";
const std::string kKnownOne = "Your frame is the one a known mistake draws (";
const std::string kKnownMany = "Your frame is the one known mistakes draw (";
const std::string kCheckpoint = "Your frame is the one checkpoint ";
const std::string kCoincide = "The likely mistakes above give the same values on these cases";

// A mistake's or a checkpoint's id as the grader writes them: letters,
// digits, '-' and '_'; anything else is no name.
bool is_id(const std::string& id) {
    return !id.empty() && id.size() <= 80 && std::all_of(id.begin(), id.end(), [](unsigned char c) {
        return std::isalnum(c) || c == '-' || c == '_';
    });
}

// The ids in "ID" or "ID, ID2" (the text between the parentheses); empty
// when one of them is not an id.
std::vector<std::string> ids_in(const std::string& list) {
    std::vector<std::string> ids;
    for (size_t from = 0; from <= list.size();) {
        const size_t comma = std::min(list.find(", ", from), list.size());
        ids.push_back(list.substr(from, comma - from));
        if (!is_id(ids.back())) return {};
        from = comma + 2;
    }
    return ids;
}

// The text between `lead` (which `line` starts with) and the ')' that
// follows it, when a ':' follows that.
std::string in_parentheses(const std::string& line, const std::string& lead) {
    const size_t close = line.find(')', lead.size());
    if (close == std::string::npos || line.compare(close, 2, "):") != 0) return "";
    return line.substr(lead.size(), close - lead.size());
}

std::string trimmed(const std::string& line) {
    const size_t from = line.find_first_not_of(' ');
    return from == std::string::npos ? "" : line.substr(from);
}

// The name a line of an image check's output gives, if any.
std::optional<Naming> frame_naming(const std::string& line) {
    for (const std::string& lead : {kKnownOne, kKnownMany})
        if (line.rfind(lead, 0) == 0) {
            const std::vector<std::string> ids = ids_in(in_parentheses(line, lead));
            if (ids.empty() || (ids.size() == 1) != (lead == kKnownOne)) return std::nullopt;
            const std::string name = fw::join(ids, " or ");
            return Naming{"known:" + name, name, line};
        }
    if (line.rfind(kCheckpoint, 0) != 0) return std::nullopt;
    const size_t end = line.find(" expects", kCheckpoint.size());
    const std::string other =
        end == std::string::npos ? "" : line.substr(kCheckpoint.size(), end - kCheckpoint.size());
    if (!is_id(other)) return std::nullopt;
    return Naming{"checkpoint:" + other,
                  "the frame checkpoint " + other + " expects, drawn for another checkpoint", line};
}

}  // namespace

std::vector<Naming> namings_in(const std::string& kind, const std::string& output) {
    std::vector<Naming> found;
    std::vector<std::string> likely, likely_lines;
    std::istringstream lines(output);
    for (std::string raw; std::getline(lines, raw);) {
        const std::string line = trimmed(raw);
        if (kind == name_of(CheckKind::Image)) {
            if (std::optional<Naming> n = frame_naming(line)) found.push_back(*n);
        } else if ((kind == name_of(CheckKind::Unit) || kind == name_of(CheckKind::Buffer)) &&
                   line.rfind(kLikely, 0) == 0) {
            const std::string id = in_parentheses(line, kLikely);
            if (!is_id(id)) continue;
            likely.push_back(id);
            likely_lines.push_back(line);
        }
    }
    if (!likely.empty() && output.find(kCoincide) != std::string::npos) {
        const std::string name = fw::join(likely, " or ");
        found.push_back({"likely:" + name, name, fw::join(likely_lines, "\n")});
    } else {
        for (size_t i = 0; i < likely.size(); ++i)
            found.push_back({"likely:" + likely[i], likely[i], likely_lines[i]});
    }
    std::vector<Naming> once;
    for (const Naming& n : found)
        if (std::none_of(once.begin(), once.end(), [&](const Naming& o) { return o.key == n.key; }))
            once.push_back(n);
    return once;
}

double students_of(const ClassRow& row) {
    return row.submission.students.empty() ? 1.0 : double(row.submission.students.size());
}

namespace {

// Text from the reports' markup: the character references escape_markup
// writes, undone.
std::string unescape(const std::string& html) {
    static const std::pair<std::string, char> kRefs[] = {
        {"&amp;", '&'}, {"&lt;", '<'}, {"&gt;", '>'}, {"&quot;", '"'}, {"&#39;", '\''}};
    std::string out;
    for (size_t i = 0; i < html.size();) {
        bool done = false;
        for (const auto& [ref, c] : kRefs)
            if (!done && html.compare(i, ref.size(), ref) == 0) {
                out += c;
                i += ref.size();
                done = true;
            }
        if (!done) out += html[i++];
    }
    return out;
}

// The text of each check's <pre> in a test's html output, in the order the
// checks are shown ("<p><strong>PASS|FAIL</strong> TITLE ...</p>", then its
// <pre> when it has output); "" for a check without output.
std::vector<std::string> check_texts(const std::string& html) {
    const std::string lead = "<p><strong>";
    std::vector<size_t> starts;
    for (size_t at = html.find(lead); at != std::string::npos; at = html.find(lead, at + 1))
        if (html.compare(at + lead.size(), 4, "PASS") == 0 ||
            html.compare(at + lead.size(), 4, "FAIL") == 0)
            starts.push_back(at);
    std::vector<std::string> texts;
    for (size_t i = 0; i < starts.size(); ++i) {
        const size_t end = i + 1 < starts.size() ? starts[i + 1] : html.size();
        const std::string part = html.substr(starts[i], end - starts[i]);
        const size_t open = part.find("<pre>"), close = part.rfind("</pre>");
        texts.push_back(open != std::string::npos && close != std::string::npos && close > open
                            ? unescape(part.substr(open + 5, close - open - 5))
                            : "");
    }
    return texts;
}

class Reader {
public:
    Reader(const fs::path& out, ClassFindings& f) : out_(out), f_(f) {}

    void read(const ClassRow& row, const std::string& lab) {
        const std::string rel = "students/" + row.submission.key + "/" + lab;
        json results;
        try {
            results = json::parse(read_file(out_ / rel / "results.json"));
            if (!results.at("tests").is_array()) return;
        } catch (const std::exception&) {
            return;
        }
        f_.rated[lab] += students_of(row);
        for (const json& test : results["tests"]) {
            try {
                read_test(row, lab, rel, test);
            } catch (const json::exception&) {
                // A test not of its form: no rate, no name from it.
            }
        }
    }

    // The mistakes of every lab, the most students first (then in the labs'
    // order, then by name).
    void finish(const std::vector<std::pair<std::string, std::string>>& labs) {
        for (auto& [key, m] : mistakes_) f_.mistakes.push_back(std::move(m));
        auto lab_index = [&](const std::string& id) {
            return std::find_if(labs.begin(), labs.end(),
                                [&](const auto& l) { return l.first == id; }) -
                   labs.begin();
        };
        std::stable_sort(f_.mistakes.begin(), f_.mistakes.end(), [&](const auto& a, const auto& b) {
            if (a.students != b.students) return a.students > b.students;
            if (a.lab != b.lab) return lab_index(a.lab) < lab_index(b.lab);
            return a.naming.name < b.naming.name;
        });
        for (auto& [lab, rates] : f_.rates)
            std::stable_sort(rates.begin(), rates.end(), [](const auto& a, const auto& b) {
                const double fa = a.failed / std::max(1.0, a.passed + a.failed),
                             fb = b.failed / std::max(1.0, b.passed + b.failed);
                return fa > fb;
            });
    }

private:
    void read_test(const ClassRow& row, const std::string& lab, const std::string& rel,
                   const json& test) {
        const json& extra = test.at("extra_data");
        const std::string checkpoint = extra.at("checkpoint");
        const bool passed = test.at("status") == "passed";
        rate(lab, checkpoint, test.value("visibility", "visible") != "visible", passed, row);
        const json& checks = extra.at("checks");
        const std::vector<std::string> texts = check_texts(test.value("output", ""));
        if (passed || texts.size() != checks.size()) return;  // no name without its check
        bool frame_failed = false;
        for (const json& c : checks)
            frame_failed |= c.at("kind") == name_of(CheckKind::Image) && !c.at("passed");
        const std::string frame = rel + "/" + lab + "/" + checkpoint + ".png";
        for (size_t i = 0; i < checks.size(); ++i) {
            if (checks[i].at("passed")) continue;
            for (const Naming& n : namings_in(checks[i].at("kind"), texts[i]))
                add(row, lab, checkpoint, n,
                    frame_failed && fs::is_regular_file(out_ / frame) ? frame : "");
        }
    }

    void rate(const std::string& lab, const std::string& checkpoint, bool hidden, bool passed,
              const ClassRow& row) {
        std::vector<CheckpointRate>& rates = f_.rates[lab];
        auto it = std::find_if(rates.begin(), rates.end(),
                               [&](const CheckpointRate& r) { return r.checkpoint == checkpoint; });
        if (it == rates.end()) it = rates.insert(rates.end(), {checkpoint, hidden, 0, 0});
        (passed ? it->passed : it->failed) += students_of(row);
    }

    void add(const ClassRow& row, const std::string& lab, const std::string& checkpoint,
             const Naming& n, const std::string& frame) {
        NamedMistake& m = mistakes_[{lab, n.key}];
        if (m.lab.empty()) {
            m.lab = lab;
            m.naming = n;
        }
        std::vector<std::string>& where = m.submissions[row.submission.key];
        if (where.empty()) m.students += students_of(row);
        if (std::find(where.begin(), where.end(), checkpoint) == where.end())
            where.push_back(checkpoint);
        if (m.frame.empty() && !frame.empty()) {
            m.frame = frame;
            m.frame_submission = row.submission.key;
            m.frame_checkpoint = checkpoint;
        }
    }

    fs::path out_;
    ClassFindings& f_;
    std::map<std::pair<std::string, std::string>, NamedMistake> mistakes_;
};

}  // namespace

ClassFindings read_findings(const fs::path& out, const std::vector<ClassRow>& rows,
                            const std::vector<std::pair<std::string, std::string>>& labs) {
    ClassFindings f;
    Reader reader(out, f);
    for (const ClassRow& row : rows)
        for (const auto& [id, dir] : labs) {
            const auto g = row.labs.find(id);
            if (g != row.labs.end() && g->second.status != "not built" &&
                g->second.status != "not graded")
                reader.read(row, id);
        }
    reader.finish(labs);
    return f;
}

}  // namespace grading::cls
