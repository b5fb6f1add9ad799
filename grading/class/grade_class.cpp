#include "grading/class/grade_class.hpp"

#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <thread>

#include "framework/error.hpp"
#include "framework/text.hpp"
#include "grading/class/class_page.hpp"
#include "grading/class/class_rows.hpp"
#include "grading/class/class_submission.hpp"
#include "grading/class/content_hash.hpp"
#include "grading/class/gradebook.hpp"
#include "grading/commands/lab_sources.hpp"
#include "grading/judge/checks.hpp"
#include "grading/platforms/autograder.hpp"
#include "grading/release/release.hpp"
#include "grading/run/repository.hpp"

namespace grading::cls {

namespace fs = std::filesystem;

namespace {

std::atomic<bool> g_stop{false};

extern "C" void on_interrupt(int) { g_stop = true; }

// "K/N" as (K, N), 1 <= K <= N.
std::pair<int, int> parse_shard(const std::string& text) {
    int k = 0, n = 0;
    char tail = 0;
    if (std::sscanf(text.c_str(), "%d/%d%c", &k, &n, &tail) != 2 || n < 1 || k < 1 || k > n)
        throw fw::UsageError("--shard '" + text +
                             "': expected K/N with 1 <= K <= N (the K-th of N slices)");
    return {k, n};
}

// Every file under `dir`, sorted, with its hash: what a lab's grade
// depends on in the course's tree.
std::string tree_text(const fs::path& dir) {
    std::vector<fs::path> files;
    if (fs::is_directory(dir))
        for (const auto& e : fs::recursive_directory_iterator(dir))
            if (e.is_regular_file()) files.push_back(e.path());
    std::sort(files.begin(), files.end());
    std::string all;
    for (const fs::path& f : files)
        all += f.lexically_relative(dir).string() + '\0' + content_hash(read_file(f)) + '\n';
    return all;
}

std::string own_path() {
    std::error_code ec;
    const fs::path self = fs::read_symlink("/proc/self/exe", ec);
    if (ec) throw fw::Error("cannot find course's own executable (/proc/self/exe)");
    return self.string();
}

std::string duration_text(double seconds) {
    const long s = std::lround(seconds);
    return s >= 60 ? std::to_string(s / 60) + " min " + std::to_string(s % 60) + " s"
                   : std::to_string(s) + " s";
}

// Done/total, failures so far and the time left: one line kept in place on a
// terminal, a line per submission otherwise.
class Progress {
public:
    explicit Progress(size_t total)
        : total_(total), tty_(isatty(STDERR_FILENO)), start_(std::chrono::steady_clock::now()) {}

    void done(const ClassRow& r) {
        std::lock_guard<std::mutex> lock(mutex_);
        ++done_;
        failed_ += r.failed();
        const double elapsed =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
        const double left = done_ ? elapsed / double(done_) * double(total_ - done_) : 0;
        if (tty_) {
            const int width = 30, filled = int(double(width) * double(done_) / double(total_));
            std::fprintf(stderr, "\r[%s%s] %zu/%zu graded, %zu failed, about %s left   ",
                         std::string(size_t(filled), '#').c_str(),
                         std::string(size_t(width - filled), '.').c_str(), done_, total_, failed_,
                         duration_text(left).c_str());
            if (done_ == total_) std::fputc('\n', stderr);
        } else {
            double score = 0, max = 0;
            for (const auto& [id, lab] : r.labs) {
                score += lab.score;
                max += lab.max_score;
            }
            std::fprintf(stderr, "%zu/%zu %s: %s/%s%s (%.1f s)\n", done_, total_,
                         r.submission.key.c_str(), fw::trimmed_decimals(score, 2).c_str(),
                         fw::trimmed_decimals(max, 2).c_str(),
                         r.failed()       ? ", not all graded"
                         : r.graded_any() ? ""
                                          : ", unchanged",
                         r.seconds);
        }
    }

private:
    size_t total_, done_ = 0, failed_ = 0;
    bool tty_;
    std::chrono::steady_clock::time_point start_;
    std::mutex mutex_;
};

}  // namespace

namespace {

// The course, its labs and what their grades depend on, and the student
// files of those labs (their starting versions written under DIR/.class).
void prepare(ClassContext& c, const GradeClassOptions& o) {
    c.root = fs::absolute(source_root());
    c.course = own_path();
    c.lab = resolve_lab_binary("");
    require_lab_up_to_date(c.lab, true, o.labs);
    c.out = fs::absolute(o.out);
    c.timeout = o.timeout;
    c.backend = o.backend;
    if (!o.deadline.empty()) c.deadline = parse_time(o.deadline);
    const std::vector<LabData> labs = select_labs(discover_labs(c.root.string()), o.labs);
    const std::string binaries = content_hash(read_file(c.course)) + content_hash(read_file(c.lab));
    for (const LabData& lab : labs) {
        c.labs.emplace_back(lab.id, lab.dir);
        c.course_hash[lab.id] =
            content_hash(binaries + c.timeout + '\0' + c.backend + '\0' +
                         tree_text(c.root / "labs" / lab.dir / "reference") +
                         tree_text(c.root / "labs" / lab.dir / "grading") +
                         read_file(c.root / "labs" / lab.dir / "checkpoints.json"));
    }
    StudentFiles students;
    for (const auto& file : student_files(c.root, project_files(c.root.string())))
        for (const LabData& lab : labs)
            if (file.first.rfind("labs/" + lab.dir + "/", 0) == 0 ||
                file.first.rfind("shaders/" + lab.dir + "/", 0) == 0)
                students.push_back(file);
    if (students.empty())
        throw fw::UsageError("the labs chosen have no student files: nothing to grade");
    std::string taken = binaries;
    for (const auto& [rel, text] : students) {
        c.files.push_back(rel);
        taken += rel + '\0' + content_hash(text) + '\n';
    }
    c.take_hash = content_hash(taken);
    const fs::path grader = c.out / ".class";
    fs::create_directories(grader);
    write_student_files(students, grader);
    c.versions = grader / "student_versions";
}

// The submissions of this run's slice; `total` counts the whole class.
std::vector<Submission> slice_of(const GradeClassOptions& o, size_t& total) {
    std::vector<std::string> skipped;
    const std::vector<Submission> all = find_submissions(o.submissions, skipped);
    for (const std::string& s : skipped)
        std::fprintf(stderr, "grade-class: skipped %s\n", s.c_str());
    std::vector<Submission> mine;
    const auto [k, n] = o.shard.empty() ? std::pair<int, int>{1, 1} : parse_shard(o.shard);
    for (size_t i = 0; i < all.size(); ++i)
        if (int(i % size_t(n)) == k - 1) mine.push_back(all[i]);
    if (mine.empty()) throw fw::UsageError("no submissions to grade in '" + o.submissions + "'");
    total = all.size();
    return mine;
}

// Grades `mine`, `jobs` at once, until done or interrupted: the rows of
// those that ended, each kept in DIR as soon as it ends.
std::vector<ClassRow> grade_all(const ClassContext& c, const std::vector<Submission>& mine,
                                size_t jobs) {
    g_stop = false;
    struct sigaction act = {};
    act.sa_handler = on_interrupt;
    sigaction(SIGINT, &act, nullptr);
    sigaction(SIGTERM, &act, nullptr);
    std::vector<ClassRow> rows(mine.size());
    std::vector<bool> finished(mine.size(), false);
    std::atomic<size_t> next{0};
    Progress progress(mine.size());
    std::vector<std::thread> workers;
    for (size_t w = 0; w < jobs; ++w)
        workers.emplace_back([&] {
            for (size_t i; !g_stop && (i = next++) < mine.size();) {
                try {
                    rows[i] = grade_submission(c, mine[i]);
                } catch (const std::exception& e) {
                    rows[i].submission = mine[i];
                    rows[i].error = std::string("grade-class failed on it: ") + e.what();
                }
                finished[i] = !rows[i].interrupted;
                if (finished[i]) write_row(c.out, rows[i]);
                progress.done(rows[i]);
            }
        });
    for (std::thread& t : workers) t.join();
    std::vector<ClassRow> kept;
    for (size_t i = 0; i < rows.size(); ++i)
        if (finished[i]) kept.push_back(rows[i]);
    return kept;
}

std::string lab_names(const ClassContext& c) {
    std::string names;
    for (const auto& l : c.labs) names += (names.empty() ? "" : ",") + l.first;
    return names;
}

}  // namespace

int grade_class_command(const GradeClassOptions& o) {
    if (o.out.empty()) throw fw::UsageError("grade-class needs --out DIR");
    ClassContext c;
    prepare(c, o);
    const LmsExport lms(o.lms, c.labs);
    const LabBuilder builder(c.lab, c.out / ".class" / "objects");
    c.builder = &builder;
    c.stop = &g_stop;
    size_t total = 0;
    const std::vector<Submission> mine = slice_of(o, total);
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    const size_t jobs = std::min(mine.size(), size_t(o.jobs > 0 ? unsigned(o.jobs) : cores));
    const std::string shard =
        o.shard.empty() ? "" : " (shard " + o.shard + " of " + std::to_string(total) + ")";
    std::fprintf(stderr, "grade-class: %zu submissions%s, %zu at once, labs %s\n", mine.size(),
                 shard.c_str(), jobs, lab_names(c).c_str());

    const auto start = std::chrono::steady_clock::now();
    const std::vector<ClassRow> kept = grade_all(c, mine, jobs);
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    write_class_file(c.out, c.labs);
    write_grades_csv(c.out / "grades.csv", kept, c.labs);
    write_class_page(c.out, kept, c.labs, seconds);
    lms.write(c.out, kept,
              kept.size() < mine.size() ? "the run was interrupted"
              : o.shard.empty()         ? ""
                                        : "--shard grades a slice (course merge-class writes it)");
    size_t failed = 0, fresh = 0;
    for (const ClassRow& r : kept) {
        failed += r.failed();
        fresh += r.graded_any();
    }
    std::printf(
        "grade-class: %zu of %zu submissions in %s (%zu graded, %zu unchanged), %zu not "
        "fully graded; %s and %s\n",
        kept.size(), mine.size(), duration_text(seconds).c_str(), fresh, kept.size() - fresh,
        failed, (c.out / "grades.csv").c_str(), (c.out / "class.html").c_str());
    if (g_stop) {
        if (kept.size() < mine.size())
            std::puts("grade-class: interrupted; run the same command again for the rest");
        return 130;
    }
    return failed ? 1 : 0;
}

}  // namespace grading::cls
