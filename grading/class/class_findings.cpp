#include "grading/class/class_findings.hpp"

#include <sys/stat.h>

#include <algorithm>
#include <cctype>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

#include "framework/error.hpp"
#include "framework/text.hpp"
#include "grading/release/release.hpp"
#include "grading/report/report_text.hpp"
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

// What one lab's report gives the page, in the order it is read: a
// checkpoint's rate, or a name (with the frame to show where the
// checkpoint's image check failed, when that file exists).
struct Event {
    bool rate = false;
    std::string checkpoint;
    bool hidden = false, passed = false;
    Naming naming;
    std::string frame;
};

struct LabReport {
    bool rated = false;  // its results.json is of its form
    std::vector<Event> events;
};

// One test of a report; a test not of its form gives what it gave before
// the part it lacks (no rate, no name from it).
void read_test(const std::string& lab, const std::string& rel, const json& test, LabReport& r) {
    const json& extra = test.at("extra_data");
    const std::string checkpoint = extra.at("checkpoint");
    const bool passed = test.at("status") == "passed";
    r.events.push_back(
        {true, checkpoint, test.value("visibility", "visible") != "visible", passed, {}, ""});
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
            r.events.push_back({false, checkpoint, false, false, n, frame_failed ? frame : ""});
    }
}

LabReport read_report(const fs::path& file, const std::string& lab, const std::string& rel) {
    LabReport r;
    json results;
    try {
        results = json::parse(read_file(file));
        if (!results.at("tests").is_array()) return r;
    } catch (const std::exception&) {
        return r;
    }
    r.rated = true;
    for (const json& test : results["tests"]) {
        try {
            read_test(lab, rel, test, r);
        } catch (const json::exception&) {
            // A test not of its form: no rate, no name from it.
        }
    }
    return r;
}

// What stands for a file's bytes between runs: its size, inode and times
// ("" when it is missing). A report is written whole, never in place.
std::string stamp_of(const fs::path& file) {
    struct stat st;
    if (::stat(file.c_str(), &st) != 0) return "";
    return std::to_string(st.st_size) + ' ' + std::to_string(st.st_ino) + ' ' +
           std::to_string(st.st_mtim.tv_sec) + '.' + std::to_string(st.st_mtim.tv_nsec) + ' ' +
           std::to_string(st.st_ctim.tv_sec) + '.' + std::to_string(st.st_ctim.tv_nsec);
}

json report_json(const std::string& stamp, const LabReport& r) {
    json events = json::array();
    for (const Event& e : r.events)
        events.push_back({e.rate, e.checkpoint, e.hidden, e.passed, e.naming.key, e.naming.name,
                          e.naming.sentence, e.frame});
    return {{"stamp", stamp}, {"rated", r.rated}, {"events", events}};
}

LabReport report_of(const json& j) {
    LabReport r;
    r.rated = j.at("rated");
    for (const json& e : j.at("events"))
        r.events.push_back(
            {e.at(0), e.at(1), e.at(2), e.at(3), {e.at(4), e.at(5), e.at(6)}, e.at(7)});
    return r;
}

// What each lab's report of a submission gave, kept in DIR/.class/findings/
// KEY.json (when DIR/.class is there: grade-class's DIR), read again only
// when the report's stamp changed.
class KeptReports {
public:
    KeptReports(const fs::path& out, const std::string& key)
        : file_(out / ".class" / "findings" / (key + ".json")),
          on_(fs::is_directory(out / ".class")) {
        try {
            if (on_ && fs::exists(file_)) kept_ = json::parse(read_file(file_));
        } catch (const std::exception&) {
            kept_ = json::object();
        }
        if (!kept_.is_object()) kept_ = json::object();
    }

    LabReport read(const fs::path& results, const std::string& lab, const std::string& rel) {
        const std::string stamp = on_ ? stamp_of(results) : "";
        try {
            const auto it = kept_.find(lab);
            if (!stamp.empty() && it != kept_.end() && it->at("stamp") == stamp) {
                now_[lab] = *it;
                return report_of(*it);
            }
        } catch (const json::exception&) {
            // Not of its form: read the report again.
        }
        const LabReport r = read_report(results, lab, rel);
        if (!stamp.empty()) now_[lab] = report_json(stamp, r);
        return r;
    }

    void save() {
        if (!on_ || now_ == kept_) return;
        std::error_code ec;
        try {
            fs::create_directories(file_.parent_path());
            report::write_text_file(file_.string() + ".part", now_.dump() + "\n");
            fs::rename(file_.string() + ".part", file_);
        } catch (const std::exception&) {
            fs::remove(file_, ec);
        }
    }

private:
    fs::path file_;
    bool on_;
    json kept_ = json::object(), now_ = json::object();
};

class Reader {
public:
    Reader(const fs::path& out, ClassFindings& f) : out_(out), f_(f) {}

    void read(const ClassRow& row, const std::string& lab, KeptReports& kept) {
        const std::string rel = "students/" + row.submission.key + "/" + lab;
        const LabReport r = kept.read(out_ / rel / "results.json", lab, rel);
        if (!r.rated) return;
        f_.rated[lab] += students_of(row);
        for (const Event& e : r.events) {
            if (e.rate)
                rate(lab, e.checkpoint, e.hidden, e.passed, row);
            else
                add(row, lab, e.checkpoint, e.naming,
                    !e.frame.empty() && fs::is_regular_file(out_ / e.frame) ? e.frame : "");
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
    for (const ClassRow& row : rows) {
        KeptReports kept(out, row.submission.key);
        for (const auto& [id, dir] : labs) {
            const auto g = row.labs.find(id);
            if (g != row.labs.end() && g->second.status != "not built" &&
                g->second.status != "not graded")
                reader.read(row, id, kept);
        }
        kept.save();
    }
    reader.finish(labs);
    return f;
}

}  // namespace grading::cls
