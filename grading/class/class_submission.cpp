#include "grading/class/class_submission.hpp"

#include <algorithm>
#include <chrono>
#include <nlohmann/json.hpp>
#include <set>

#include "framework/error.hpp"
#include "grading/class/class_rows.hpp"
#include "grading/class/content_hash.hpp"
#include "grading/class/taken.hpp"
#include "grading/platforms/autograder.hpp"
#include "grading/platforms/run_logged.hpp"
#include "grading/platforms/submitted_files.hpp"
#include "grading/release/release.hpp"
#include "grading/report/report_text.hpp"

namespace grading::cls {

namespace fs = std::filesystem;
using nlohmann::json;

bool ClassRow::graded_any() const {
    for (const auto& [id, lab] : labs)
        if (!lab.resumed) return true;
    return false;
}

bool ClassRow::failed() const {
    if (!error.empty()) return true;
    for (const auto& [id, lab] : labs)
        if (lab.status != "graded") return true;
    return false;
}

namespace {

// Written whole or not at all: a run stopped midway leaves the last one.
void write_atomically(const fs::path& file, const std::string& text) {
    const fs::path partial = file.string() + ".part";
    report::write_text_file(partial.string(), text);
    fs::rename(partial, file);
}

bool is_lab_file(const std::string& rel, const std::string& dir) {
    return rel.rfind("labs/" + dir + "/", 0) == 0 || rel.rfind("shaders/" + dir + "/", 0) == 0;
}

// The lab's points from its results.json (Gradescope's: the tests' scores),
// and its status where its child did not end normally.
bool read_points(const fs::path& results, LabGrade& g) {
    try {
        const json r = json::parse(read_file(results));
        g.score = g.max_score = 0;
        for (const json& t : r.at("tests")) {
            g.score += t.value("score", 0.0);
            g.max_score += t.value("max_score", 0.0);
        }
        // The lab's own status: "ok", else what stopped it ("timed out after 20 s").
        for (const json& lab : r.at("extra_data").at("labs"))
            if (lab.at("status") != "ok") g.status = lab.at("status").get<std::string>();
        return true;
    } catch (const std::exception&) {
        return false;
    }
}

json lab_json(const LabGrade& g, const std::string& hash, const std::string& first_error) {
    return {{"hash", hash},       {"status", g.status},
            {"score", g.score},   {"max_score", g.max_score},
            {"reason", g.reason}, {"first_error", first_error}};
}

// Every file under `dir`, relative to it.
std::vector<std::string> files_under(const fs::path& dir) {
    std::vector<std::string> found;
    for (const auto& e : fs::recursive_directory_iterator(dir))
        if (e.is_regular_file()) found.push_back(e.path().lexically_relative(dir).string());
    std::sort(found.begin(), found.end());
    return found;
}

// The reports of a lab that could not be graded: every check failed with `reason`.
void not_graded(const std::string& lab, const fs::path& dir, const std::string& reason,
                const std::string& log, LabGrade& g) {
    std::error_code ec;
    fs::remove_all(dir, ec);
    not_graded_command(reason, log, dir.string(), ResultsFormat::Gradescope, {lab},
                       HiddenAs::AfterDueDate, /*print=*/false);
    const std::string status = g.status;
    read_points(dir / "results.json", g);
    g.status = status;
    g.score = 0;
    g.reason = reason;
}

class Grader {
public:
    Grader(const ClassContext& c, const Submission& s)
        : c_(c),
          submission_(s),
          work_(c.out / ".class" / "work" / s.key),
          reports_(c.out / "students" / s.key) {
        row_.submission = s;
    }

    ClassRow run() {
        const auto start = std::chrono::steady_clock::now();
        grade();
        row_.seconds =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        std::error_code ec;
        fs::remove_all(work_, ec);
        return row_;
    }

private:
    void grade() {
        Unpacked ahead;
        const std::string source = source_key(row_.submission, c_.deadline, ahead);
        const std::string key = source.empty() ? "" : content_hash(source + '\n' + c_.take_hash);
        if (!key.empty() && resume_all(key, ahead)) return;
        row_ = ClassRow{};
        row_.submission = submission_;
        file_hash_.clear();
        const Unpacked u = unpack(row_.submission, work_ / "submitted", c_.deadline);
        row_.late = u.late_commits;
        if (!u.ok) {
            row_.error = u.error;
            for (const auto& [id, dir] : c_.labs) {
                LabGrade& g = row_.labs[id];
                g.status = "not graded";
                not_graded(id, reports_ / id, "the submission could not be read: " + u.error, "",
                           g);
            }
            return;
        }
        take_files();
        row_.graded = u.commit.empty() ? content_hash(taken_text_) : u.commit;
        if (!key.empty())
            write_taken(taken_file(),
                        {key, row_.graded, row_.missing, row_.extra, file_hash_, files_txt_});
        std::vector<std::string> pending;
        for (const auto& [id, dir] : c_.labs)
            if (!resumed(id, dir)) pending.push_back(id);
        if (pending.empty() || (c_.stop && *c_.stop)) {
            row_.interrupted = !pending.empty();
            return;
        }
        if (!build()) return;
        for (const std::string& id : pending)
            if (!row_.labs.count(id)) grade_lab(id);
    }

    // Chooses each student file as the autograders do, and notes what is
    // missing and what is extra.
    void take_files() {
        const fs::path submitted = work_ / "submitted";
        const SubmittedFiles chooser(submitted, c_.versions, c_.files);
        std::set<std::string> used;
        for (const std::string& rel : c_.files) {
            const Chosen chosen = chooser.choose(rel);
            chosen_[rel] = chosen.from;
            if (chosen.from.string().rfind(c_.versions.string() + "/", 0) == 0)
                row_.missing.push_back(rel);
            else
                used.insert(chosen.from.lexically_relative(submitted).string());
            const std::string text = read_file(chosen.from);
            file_hash_[rel] = content_hash(text);
            taken_text_ += rel + '\0' + file_hash_[rel] + '\n';
        }
        for (const std::string& rel : files_under(submitted))
            if (!used.count(rel)) row_.extra.push_back(rel);
        std::string text = "What grade-class took from this submission.\n";
        for (const std::string& rel : c_.files)
            text += "  " + rel + ": " +
                    (std::count(row_.missing.begin(), row_.missing.end(), rel)
                         ? "missing: the release's starting version graded"
                         : "from " + chosen_[rel].lexically_relative(submitted).string()) +
                    "\n";
        text += row_.extra.empty()
                    ? "No other files.\n"
                    : std::to_string(row_.extra.size()) + " other files, not graded (first 20):\n";
        for (size_t i = 0; i < row_.extra.size() && i < 20; ++i)
            text += "  " + row_.extra[i] + "\n";
        fs::create_directories(reports_);
        write_atomically(reports_ / "files.txt", text);
        files_txt_ = text;
    }

    fs::path taken_file() const {
        return c_.out / ".class" / "taken" / (row_.submission.key + ".json");
    }

    // Every lab taken from an earlier run, without unpacking: when what was
    // taken from the submission then is kept under the same key (the same
    // files, chosen from the same student files) and every lab's hash is
    // the same.
    bool resume_all(const std::string& key, const Unpacked& u) {
        const std::optional<Taken> t = read_taken(taken_file());
        if (!t || t->key != key) return false;
        file_hash_ = t->hashes;
        for (const auto& [id, dir] : c_.labs)
            if (!resumed(id, dir)) return false;
        row_.late = u.late_commits;
        row_.graded = t->graded;
        row_.missing = t->missing;
        row_.extra = t->extra;
        std::string kept;
        try {
            kept = read_file(reports_ / "files.txt");
        } catch (const std::exception&) {
            kept.clear();
        }
        if (kept != t->files_txt) {
            fs::create_directories(reports_);
            write_atomically(reports_ / "files.txt", t->files_txt);
        }
        return true;
    }

    std::string lab_hash(const std::string& id, const std::string& dir) const {
        std::string all = c_.course_hash.at(id);
        for (const auto& [rel, hash] : file_hash_)
            if (is_lab_file(rel, dir)) all += rel + '\0' + hash + '\n';
        return content_hash(all);
    }

    bool resumed(const std::string& id, const std::string& dir) {
        const fs::path kept = reports_ / id / "class.json";
        hashes_[id] = lab_hash(id, dir);
        try {
            const json j = json::parse(read_file(kept));
            if (j.at("hash") != hashes_[id]) return false;
            const LabGrade& g = row_.labs[id] = lab_grade_of(j);
            if (g.status == "not built" && row_.first_error.empty())
                row_.first_error = j.value("first_error", "");
            return true;
        } catch (const std::exception&) {
            return false;
        }
    }

    // Builds `lab`; a lab whose C++ does not compile is not built, the
    // others are graded with its starting code. False when `lab` was not
    // linked: then no lab is graded.
    bool build() {
        std::map<std::string, fs::path> cpp;
        for (const auto& [rel, from] : chosen_)
            if (fs::path(rel).extension() == ".cpp" && c_.builder->knows(rel)) cpp[rel] = from;
        const BuiltLab b = c_.builder->build(cpp, c_.versions, work_ / "build", work_ / "lab");
        row_.build_cpu = b.cpu_seconds;
        if (b.ok) {
            for (const auto& [id, dir] : c_.labs) {
                const auto said = b.not_built.find(dir);
                if (said == b.not_built.end() || (row_.labs.count(id) && row_.labs[id].resumed))
                    continue;
                const fs::path log = work_ / ("build-" + id + ".log");
                report::write_text_file(log.string(), said->second);
                if (row_.first_error.empty()) row_.first_error = first_error(said->second);
                not_built(id,
                          "this lab does not build: its C++ does not compile (the compiler's "
                          "message is below); the other labs were graded with its starting code",
                          log, first_error(said->second));
            }
            return true;
        }
        row_.first_error = b.first_error;
        const fs::path log = work_ / "build" / "build.log";
        for (const auto& [id, dir] : c_.labs) {
            if (row_.labs.count(id) && row_.labs[id].resumed) continue;
            // Graded again next time: what failed the build may be another lab's.
            hashes_[id] = "";
            not_built(id, "the submission does not build (the compiler's message is below)",
                      fs::exists(log) ? log : fs::path(), b.first_error);
        }
        return false;
    }

    void not_built(const std::string& id, const std::string& reason, const fs::path& log,
                   const std::string& first) {
        LabGrade& g = row_.labs[id];
        g.status = "not built";
        not_graded(id, reports_ / id, reason, log.string(), g);
        save(id, g, first);
    }

    void grade_lab(const std::string& id) {
        if (c_.stop && *c_.stop) {
            row_.interrupted = true;
            return;
        }
        // The course's shaders with the student's in place.
        const fs::path shaders = work_ / "shaders";
        if (!fs::exists(shaders)) {
            fs::copy(c_.root / "shaders", shaders, fs::copy_options::recursive);
            for (const auto& [rel, from] : chosen_)
                if (rel.rfind("shaders/", 0) == 0)
                    fs::copy_file(from, work_ / rel, fs::copy_options::overwrite_existing);
        }
        const fs::path dir = reports_ / id, log = work_ / ("grade-" + id + ".log");
        std::error_code ec;
        fs::remove_all(dir, ec);
        std::vector<std::string> argv = {"env",
                                         "LAB_SHADER_DIR=" + shaders.string(),
                                         "LAB_ROOT=" + c_.root.string(),
                                         c_.course,
                                         "grade",
                                         id,
                                         "--lab",
                                         (work_ / "lab").string(),
                                         "--out",
                                         dir.string(),
                                         "--timeout",
                                         c_.timeout,
                                         "--jobs",
                                         "1"};
        if (!c_.backend.empty()) argv.insert(argv.end(), {"--backend", c_.backend});
        const int status = run_logged(argv, log, false);
        LabGrade& g = row_.labs[id];
        if (c_.stop && *c_.stop && status > 1) {
            row_.interrupted = true;
            row_.labs.erase(id);
            return;
        }
        if (status > 1 || !read_points(dir / "results.json", g)) {
            g.status = "not graded";
            not_graded(id, dir,
                       "course grade failed (exit status " + std::to_string(status) +
                           "); please tell the course staff",
                       log.string(), g);
        }
        save(id, g, "");
    }

    // `first`: the compiler's first error, for a lab not built.
    void save(const std::string& id, const LabGrade& g, const std::string& first) {
        write_atomically(reports_ / id / "class.json",
                         lab_json(g, hashes_.at(id), first).dump(2) + "\n");
    }

    const ClassContext& c_;
    const Submission& submission_;
    fs::path work_, reports_;
    ClassRow row_;
    std::map<std::string, fs::path> chosen_;
    std::map<std::string, std::string> file_hash_, hashes_;
    std::string taken_text_, files_txt_;
};

}  // namespace

ClassRow grade_submission(const ClassContext& context, const Submission& submission) {
    return Grader(context, submission).run();
}

}  // namespace grading::cls
