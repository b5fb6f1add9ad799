// The mistake suite: realistic student mistakes (mistakes.hpp beside this
// file), each applied alone to the solution inside a solution block, built
// and graded on its lab. Each must lose points on a check of a visible
// checkpoint that the solution passes, so a student sees it before the
// deadline; a mistake in a unit-checked function that names its kind
// ("named") must be named in the grader's output: "Likely mistake (ID)", or,
// for "frame:NAME", "Your frame is the one checkpoint NAME expects" (a frame
// that is another checkpoint's expected image). The table counts, besides,
// the caught mistakes the grader diagnoses at all, whether named or not.
//
// The list, kMistakesJson in mistakes.hpp: {"mistakes": [{"id", "lab"
// (folder, NN_name), "file" (repository path), "find" (exact text: once in
// the file, inside a solution block), "replace", "why" (the misconception,
// one line), "named" (optional, the ID)}, ...]}, `//` comments allowed. It
// quotes the solution, so it sits in a solution block of its own, which
// `course release` leaves out; with the student version's empty list there
// is nothing to try.
//
// Shader mistakes need no rebuild (the built `lab` reads LAB_SHADER_DIR);
// C++ mistakes go into one copy of the tree, built once and rebuilt
// incrementally per mistake.
//
// Environment: MISTAKES_SKIP_NAMED=1 leaves out the "Likely mistake" check;
// MISTAKES_ONLY=WORD,... runs only the mistakes whose id or lab contains one
// of the words.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <map>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "framework/text.hpp"
#include "grading/release/release.hpp"
#include "tests/grading/tree_support.hpp"
#include "tests/mistakes/mistakes.hpp"
#include "tests/support/test_support.hpp"

namespace fs = std::filesystem;
using fw::shell_quote;
using fw::test::read_text;
using fw::test::write_text;
using namespace tree_test;

namespace {

// The kinds of mistake the grader names for a failing unit check.
const std::set<std::string> kNamedIds = {"transpose",
                                         "inverse",
                                         "reversed-product",
                                         "radians-for-degrees",
                                         "degrees-for-radians",
                                         "flipped-angle",
                                         "translation-in-bottom-row",
                                         "not-normalised",
                                         "flipped-axis",
                                         "last-column-for-diagonal",
                                         "length-squared"};

constexpr size_t kMinMistakes = 40, kMinPerLab = 4;
constexpr const char* kFramePrefix = "frame:";

// What the grader's output says for the named mistake `named`.
std::string named_sentence(const std::string& named) {
    if (named.rfind(kFramePrefix, 0) == 0)
        return "Your frame is the one checkpoint " + named.substr(std::strlen(kFramePrefix)) +
               " expects";
    return "Likely mistake (" + named + ")";
}

// The sentences with which the grader diagnoses a failed check.
const char* const kDiagnoses[] = {"Likely mistake (", "Your frame is the one checkpoint",
                                  "Your function returned"};

struct Mistake {
    std::string id, lab, file, find, replace, why, named;
};

std::vector<Mistake> read_mistakes(const std::string& text) {
    const nlohmann::json doc = nlohmann::json::parse(text, nullptr, true, /*ignore_comments=*/true);
    std::vector<Mistake> out;
    for (const nlohmann::json& m : doc.at("mistakes"))
        out.push_back({m.at("id").get<std::string>(), m.at("lab").get<std::string>(),
                       m.at("file").get<std::string>(), m.at("find").get<std::string>(),
                       m.at("replace").get<std::string>(), m.at("why").get<std::string>(),
                       m.value("named", std::string())});
    return out;
}

size_t count_of(const std::string& text, const std::string& needle) {
    size_t n = 0;
    for (size_t at = text.find(needle); at != std::string::npos; at = text.find(needle, at + 1))
        ++n;
    return n;
}

// 1-based line of text[at].
int line_at(const std::string& text, size_t at) {
    return 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
}

// Why `m` cannot be applied to the solution as it stands ("" when it can).
std::string stale(const Mistake& m, const fs::path& source, const std::vector<std::string>& labs) {
    if (m.id.empty() || m.why.empty()) return "an id and a why are required";
    if (!std::count(labs.begin(), labs.end(), m.lab)) return "no lab folder labs/" + m.lab;
    if (lab_of(m.file) != m.lab) return m.file + " is not a file of lab " + m.lab;
    if (!m.named.empty() && !kNamedIds.count(m.named) && m.named.rfind(kFramePrefix, 0) != 0)
        return "unknown named ID " + m.named;
    if (m.find.empty() || m.find == m.replace) return "find is empty or equal to replace";
    if (!fs::is_regular_file(source / m.file)) return m.file + " does not exist";
    const std::string text = read_text(source / m.file);
    const size_t n = count_of(text, m.find);
    if (n != 1) return "find occurs " + std::to_string(n) + " times in " + m.file + ", not once";
    const size_t at = text.find(m.find);
    const int first = line_at(text, at), last = line_at(text, at + m.find.size() - 1);
    for (const grading::SolutionBlock& b : grading::solution_blocks(text, m.file))
        if (b.begin_line < first && last < b.end_line) return "";
    return "find (lines " + std::to_string(first) + "-" + std::to_string(last) + " of " + m.file +
           ") is not inside a solution block";
}

bool selected(const Mistake& m) {
    const char* only = std::getenv("MISTAKES_ONLY");
    if (!only || !*only) return true;
    std::stringstream words(only);
    std::string w;
    while (std::getline(words, w, ','))
        if (!w.empty() && (m.id.find(w) != std::string::npos || m.lab.find(w) != std::string::npos))
            return true;
    return false;
}

std::string points_text(double p) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%g", p);
    return buf;
}

// Whether some entry of `lab` (its id, as results.json names it) in `g`
// says "Likely mistake (ID)".
bool names_mistake(const Grade& g, const std::string& lab, const std::string& id) {
    const std::string needle = named_sentence(id);
    for (const auto& [name, e] : g.entries)
        if (name.rfind(lab + " / ", 0) == 0 && e.output.find(needle) != std::string::npos)
            return true;
    return false;
}

// Whether some entry of `lab` in `g` carries a diagnosis (kDiagnoses).
bool diagnosed(const Grade& g, const std::string& lab) {
    for (const auto& [name, e] : g.entries)
        if (name.rfind(lab + " / ", 0) == 0)
            for (const char* d : kDiagnoses)
                if (e.output.find(d) != std::string::npos) return true;
    return false;
}

// The lab id (`pipeline`, ...) of a folder `NN_name`.
std::string lab_id(const std::string& dir) {
    std::string id = dir.substr(dir.find('_') + 1);
    std::replace(id.begin(), id.end(), '_', '-');
    return id;
}

struct LabTally {
    size_t mistakes = 0, caught = 0, named = 0, named_found = 0, diagnosed = 0;
    double points = 0.0;
};

}  // namespace

TEST_CASE("mistakes: every realistic mistake loses points on a visible check") {
    const fs::path source = fw::test::source_dir(), dir = fw::test::out_dir();
    const std::string course = fw::test::bin_dir() + "/course", lab = fw::test::bin_dir() + "/lab";
    const bool skip_named = std::getenv("MISTAKES_SKIP_NAMED") &&
                            std::string(std::getenv("MISTAKES_SKIP_NAMED")) == "1";
    const std::vector<std::string> labs = lab_dirs(source);
    const std::vector<Mistake> all = read_mistakes(kMistakesJson);
    if (all.empty()) {
        MESSAGE("no mistakes to try: a student release leaves the list out");
        return;
    }

    // The list itself: enough mistakes for every lab, each one applicable.
    CHECK(all.size() >= kMinMistakes);
    std::map<std::string, size_t> per_lab;
    std::set<std::string> ids;
    bool applicable = true;
    for (const Mistake& m : all) {
        ++per_lab[m.lab];
        CHECK_MESSAGE(ids.insert(m.id).second, "mistake id " << m.id << " is used twice");
        const std::string why = stale(m, source, labs);
        CHECK_MESSAGE(why.empty(), "mistake " << m.id << ": " << why);
        applicable = applicable && why.empty();
    }
    for (const std::string& l : labs)
        CHECK_MESSAGE(per_lab[l] >= kMinPerLab,
                      "lab " << l << " has " << per_lab[l] << " mistakes; at least " << kMinPerLab);
    REQUIRE_MESSAGE(applicable, "each mistake's find must occur once, inside a solution block");

    std::vector<Mistake> mistakes;
    std::copy_if(all.begin(), all.end(), std::back_inserter(mistakes), selected);
    // C++ mistakes of one file next to each other: each rebuild then
    // compiles one file.
    std::stable_sort(mistakes.begin(), mistakes.end(), [](const Mistake& a, const Mistake& b) {
        return std::make_pair(a.lab, a.file) < std::make_pair(b.lab, b.file);
    });
    if (mistakes.empty()) return;
    auto total = std::chrono::steady_clock::now();

    // What the solution scores: a mistake is caught when a visible entry
    // with full marks here loses points.
    std::set<std::string> graded_labs;
    for (const Mistake& m : mistakes) graded_labs.insert(m.lab);
    std::string lab_ids;
    for (const std::string& l : graded_labs) lab_ids += " " + lab_id(l);
    Grade solution = grade(course, lab, lab_ids, dir / "solution");
    REQUIRE(solution.results.is_object());
    CHECK_MESSAGE(solution.exit_code == 0, "the solution itself fails a check:\n"
                                               << solution.output);

    const fs::path shaders = dir / "shaders", tree = dir / "tree";
    fs::remove_all(shaders);
    fs::copy(source / "shaders", shaders, fs::copy_options::recursive);
    if (std::any_of(mistakes.begin(), mistakes.end(),
                    [](const Mistake& m) { return !is_shader(m.file); })) {
        sync_tree(source, tree, grading::project_files(source.string()));
        build_tree(tree, "lab");
    }

    std::map<std::string, LabTally> tally;
    std::string report;
    for (const Mistake& m : mistakes) {
        auto start = std::chrono::steady_clock::now();
        const bool shader = is_shader(m.file);
        const std::string original = read_text(source / m.file);
        const fs::path target =
            shader ? shaders / fs::path(m.file).lexically_relative("shaders") : tree / m.file;
        std::string changed = original;
        changed.replace(changed.find(m.find), m.find.size(), m.replace);
        write_text(target, changed);

        std::string result;
        double lost = 0.0;
        bool caught = false, named_found = false, diagnosis = false;
        if (!shader && !rebuild_tree(tree, "lab")) {
            result = "DOES NOT BUILD";
        } else {
            const std::string env = shader ? "LAB_SHADER_DIR=" + shell_quote(shaders.string()) : "";
            const std::string child = shader ? lab : (tree / "build" / "bin" / "lab").string();
            Grade g = grade(course, child, lab_id(m.lab), dir / "mistake", env);
            const std::vector<Loss> losses = visible_losses(solution, g);
            for (const Loss& l : losses) lost += l.points;
            caught = !losses.empty();
            size_t hidden = 0;
            for (const auto& [name, e] : solution.entries) {
                auto it = g.entries.find(name);
                if (e.visibility == "hidden" && it != g.entries.end() && it->second.score < e.score)
                    ++hidden;
            }
            if (g.exit_code == 2 || !g.results.is_object())
                result = "GRADING FAILED (exit " + std::to_string(g.exit_code) + ")";
            else if (caught)
                result = std::to_string(losses.size()) + " visible entries lose " +
                         points_text(lost) + " points";
            else
                result = hidden ? "SLIPPED: only " + std::to_string(hidden) + " hidden entries lose"
                                : "SLIPPED: full marks";
            if (caught && !m.named.empty()) named_found = names_mistake(g, lab_id(m.lab), m.named);
            diagnosis = caught && diagnosed(g, lab_id(m.lab));
            for (const auto& [id, status] : g.status)
                if (status != "ok") result += " [" + id + ": " + status + "]";
        }
        write_text(target, original);

        LabTally& t = tally[m.lab];
        ++t.mistakes;
        t.caught += caught;
        t.diagnosed += diagnosis;
        t.points += lost;
        if (!m.named.empty()) {
            ++t.named;
            t.named_found += named_found;
            result += named_found ? "; named " + m.named : "; NOT named " + m.named;
        } else if (diagnosis) {
            result += "; diagnosed";
        }
        char line[1024];
        std::snprintf(line, sizeof line, "%-34s %-18s %s (%.1f s)\n", m.id.c_str(), m.lab.c_str(),
                      result.c_str(), seconds_since(start));
        std::printf("%s", line);
        std::fflush(stdout);
        report += line;
        CHECK_MESSAGE(caught, m.id << " (" << m.why << "): " << result
                                   << "; add a visible checkpoint or probe that it fails");
        if (!m.named.empty() && !skip_named)
            CHECK_MESSAGE(named_found, m.id << ": no check of lab " << m.lab << " says \""
                                            << named_sentence(m.named) << "\"");
    }

    // The table: per lab, the mistakes tried, those caught by a visible
    // check, the visible points they lost in all, the named ones found and
    // the caught ones the grader diagnoses (a named mistake, a frame that is
    // another checkpoint's, a NaN: image-only mistakes included).
    char line[256];
    std::string table;
    std::snprintf(line, sizeof line, "%-18s %8s %6s %11s %6s %9s\n", "lab", "mistakes", "caught",
                  "points lost", "named", "diagnosed");
    table += line;
    LabTally sum;
    auto row = [&](const std::string& name, const LabTally& t) {
        std::snprintf(line, sizeof line, "%-18s %8zu %6zu %11s %6s %9s\n", name.c_str(), t.mistakes,
                      t.caught, points_text(t.points).c_str(),
                      (std::to_string(t.named_found) + "/" + std::to_string(t.named)).c_str(),
                      (std::to_string(t.diagnosed) + "/" + std::to_string(t.caught)).c_str());
        table += line;
    };
    for (const auto& [l, t] : tally) {
        row(l, t);
        sum.mistakes += t.mistakes, sum.caught += t.caught, sum.points += t.points;
        sum.named += t.named, sum.named_found += t.named_found, sum.diagnosed += t.diagnosed;
    }
    row("total", sum);
    std::printf("\n%s%s", report.c_str(), table.c_str());
    MESSAGE("mistakes, each alone on the solution:\n"
            << report << "\n"
            << table << mistakes.size() << " mistakes in " << seconds_since(total) << " s"
            << std::string(skip_named ? " (MISTAKES_SKIP_NAMED=1: names not checked)" : ""));
}
