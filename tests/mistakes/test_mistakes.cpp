// The mistake suite: realistic student mistakes (mistakes.hpp beside this
// file), each applied alone to the solution inside a solution block, built
// and graded on its lab. Each must lose points on a check of a visible
// checkpoint that the solution passes, so a student sees it before the
// deadline. What `course grade` prints must name it where the grader can: a
// mistake that names its kind ("named") as "Likely mistake (ID)", or, for
// "frame:NAME", as "Your frame is the one checkpoint NAME expects" (a frame
// that is another checkpoint's expected image); any other that fails a
// visible image check by its own id, as the known mistake whose frame the
// student's frame is ("Your frame is the one a known mistake draws (ID)",
// grading/diagnosis/known_mistakes.hpp). A shader file the grader names as the
// one that holds the mistake (docs/contract.md, Which file is wrong) must be
// the mistake's own, and a mistake in C++ names none. The table counts the
// named ones, and
// among them those only image, probe or stat checks catch, and lists the
// rest (for them the terminal shows a unit check's first failing case, a
// probe's colour or a compiler's message).
//
// MISTAKES_RECORD=1 writes those frames: every frame of a mistake that fails
// a visible image check (mistake_frames.hpp) goes to
// labs/NN_name/reference/mistakes/ of the source tree, for each lab whose
// mistakes all ran; commit them with the change that made them.
//
// The list, kMistakesJson in mistakes.hpp: {"mistakes": [{"id", "lab"
// (folder, NN_name), "file" (repository path), "find" (exact text: once in
// the file, inside a solution block), "replace", "why" (the misconception,
// one line), "named" (optional, the ID), "state" (optional, the state
// diff's words)}, ...]}, `//` comments allowed. It
// quotes the solution, so it sits in a solution block of its own, which
// `course release` leaves out; with the student version's empty list there
// is nothing to try.
//
// Shader mistakes need no rebuild (the built `lab` reads LAB_SHADER_DIR);
// C++ mistakes go into one copy of the tree, built once and rebuilt
// incrementally per mistake.
//
// A mistake in the GL state a draw is told may say "state": the words the
// state diff (grading/diagnosis/state_diff.hpp) must print for it, from the
// records of the draws (named by evidence); the table counts those apart
// from the mistakes named by their frame or kind.
//
// Environment: MISTAKES_SKIP_NAMED=1 leaves out the check that each is named;
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
#include <optional>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "framework/text.hpp"
#include "grading/release/release.hpp"
#include "tests/grading/tree_support.hpp"
#include "tests/mistakes/mistake_frames.hpp"
#include "tests/mistakes/mistakes.hpp"
#include "tests/support/test_support.hpp"

namespace fs = std::filesystem;
using fw::shell_quote;
using fw::test::read_text;
using fw::test::write_text;
using namespace tree_test;

namespace {

// The kinds of mistake the grader names for a failing unit check.
const std::set<std::string> kNamedIds = {
    "transpose", "inverse", "reversed-product", "radians-for-degrees", "degrees-for-radians",
    "flipped-angle", "translation-in-bottom-row", "not-normalised", "flipped-axis",
    "last-column-for-diagonal", "length-squared", "off-by-one", "perspective-depth",
    // buffer references' mistakes (labs/*/grading)
    "no-half-step", "gravity-twice", "never-moved", "groups-rounded-down", "midpoints-not-pushed"};

constexpr size_t kMinMistakes = 40, kMinPerLab = 4;
constexpr const char* kFramePrefix = "frame:";
constexpr const char* kRecordHint =
    "; if its frames changed, record them again: MISTAKES_RECORD=1 ctest --preset default -R "
    "'^mistakes$'";

// What the grader's output says for the named mistake `named`.
std::string named_sentence(const std::string& named) {
    if (named.rfind(kFramePrefix, 0) == 0)
        return "Your frame is the one checkpoint " + named.substr(std::strlen(kFramePrefix)) +
               " expects";
    return "Likely mistake (" + named + ")";
}

bool env_is(const char* name, const char* value) {
    const char* v = std::getenv(name);
    return v && std::string(v) == value;
}

struct Mistake {
    std::string id, lab, file, find, replace, why, named, state;
};

std::vector<Mistake> read_mistakes(const std::string& text) {
    const nlohmann::json doc = nlohmann::json::parse(text, nullptr, true, /*ignore_comments=*/true);
    std::vector<Mistake> out;
    for (const nlohmann::json& m : doc.at("mistakes"))
        out.push_back({m.at("id").get<std::string>(), m.at("lab").get<std::string>(),
                       m.at("file").get<std::string>(), m.at("find").get<std::string>(),
                       m.at("replace").get<std::string>(), m.at("why").get<std::string>(),
                       m.value("named", std::string()), m.value("state", std::string())});
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

// Whether `text` names the known mistake `id`: "draws (ID)", or ID in the
// list of "draw (ID, ID2)".
bool names_known(const std::string& text, const std::string& id) {
    for (const char* lead : {"known mistake draws (", "known mistakes draw ("})
        for (size_t at = text.find(lead); at != std::string::npos; at = text.find(lead, at + 1)) {
            const size_t open = text.find('(', at) + 1, close = text.find(')', open);
            std::stringstream ids(text.substr(open, close - open));
            for (std::string one; std::getline(ids, one, ',');)
                if (one.substr(one.find_first_not_of(' ')) == id) return true;
        }
    return false;
}

// Whether the terminal output of `g` (course grade's, which prints each
// failed check's diagnosis) names mistake `m`: by its kind (named_sentence)
// or by its id.
bool names_mistake(const Grade& g, const std::string& named, const std::string& id) {
    return (!named.empty() && g.output.find(named_sentence(named)) != std::string::npos) ||
           names_known(g.output, id);
}

// The shader files (under shaders/) that `text` names as the one holding
// the mistake (docs/contract.md, Which file is wrong).
std::set<std::string> files_named(const std::string& text) {
    const std::string lead = "the mistake is in shaders/";
    std::set<std::string> files;
    for (size_t at = text.find(lead); at != std::string::npos; at = text.find(lead, at + 1)) {
        const size_t from = at + lead.size(), end = text.find('\n', from);
        const std::string rest = text.substr(from, end == std::string::npos ? end : end - from);
        files.insert(rest.substr(0, rest.size() - (!rest.empty() && rest.back() == '.')));
    }
    return files;
}

// Whether a check of `lab` whose title starts with `kind` ("unit", "image")
// fails in `g` (its entries are named "LAB / CHECKPOINT / TITLE"), and with
// `visible`, on a visible checkpoint.
bool check_fails(const Grade& g, const std::string& lab, const std::string& kind,
                 bool visible = false) {
    for (const std::string& name : g.failed)
        if (name.rfind(lab + " / ", 0) == 0 && name.find(" / " + kind + " ") != std::string::npos &&
            (!visible || g.entries.at(name).visibility == "visible"))
            return true;
    return false;
}

// The lab id (`pipeline`, ...) of a folder `NN_name`.
std::string lab_id(const std::string& dir) {
    std::string id = dir.substr(dir.find('_') + 1);
    std::replace(id.begin(), id.end(), '_', '-');
    return id;
}

// The functions whose unit checks of lab `lab` fail in `g` (entries
// "LAB / CHECKPOINT / unit NAME (N cases)").
std::vector<std::string> failed_units(const Grade& g, const std::string& lab) {
    std::set<std::string> functions;
    const std::string lead = " / unit ";
    for (const std::string& name : g.failed) {
        if (name.rfind(lab + " / ", 0) != 0) continue;
        const size_t at = name.find(lead);
        if (at == std::string::npos) continue;
        const size_t from = at + lead.size(), end = name.find(" (", from);
        functions.insert(name.substr(from, end == std::string::npos ? end : end - from));
    }
    return {functions.begin(), functions.end()};
}

// Per checkpoint of lab `lab`, the state diff's sentence in `g`'s outputs
// (grading/diagnosis/state_diff.hpp: "Draw 2 of scene `x`: ...", "scene `x`:
// your Draw 3 ...", under a failed frame check or as a state check's
// Observed line); none where the records agree.
std::map<std::string, std::string> state_sentences(const Grade& g, const std::string& lab) {
    // Under a failed frame check, or as a failed state check's Observed line.
    static const std::regex sentence(
        "^(Observed: )?(((Draw|Dispatch|Clear|Read-back) [0-9]+ of )?(scene|checkpoint) "
        "`[^`]*`: .*)");
    std::map<std::string, std::string> out;
    for (const auto& [name, entry] : g.entries) {
        if (name.rfind(lab + " / ", 0) != 0) continue;
        const size_t from = lab.size() + 3, end = name.find(" / ", from);
        const std::string checkpoint =
            name.substr(from, end == std::string::npos ? end : end - from);
        std::stringstream lines(entry.output);
        std::smatch m;
        for (std::string line; std::getline(lines, line);)
            if (std::regex_match(line, m, sentence)) out.emplace(checkpoint, m[2].str());
    }
    return out;
}

struct LabTally {
    size_t mistakes = 0, caught = 0, named = 0, image_only = 0, image_only_named = 0;
    size_t state = 0, by_evidence = 0;  // with "state", and those the state diff names
    size_t shaders = 0, by_file = 0;    // caught in a shader, and those localised to it
    double points = 0.0;
    std::vector<std::string> unnamed;  // caught, not named: the terminal says what differs
};

}  // namespace

TEST_CASE("mistakes: every realistic mistake loses points on a visible check") {
    const fs::path source = fw::test::source_dir(), dir = fw::test::out_dir();
    fw::test::remove_when_passed(dir.string());
    const std::string course = fw::test::bin_dir() + "/course", lab = fw::test::bin_dir() + "/lab";
    const bool skip_named = env_is("MISTAKES_SKIP_NAMED", "1");
    const bool record = env_is("MISTAKES_RECORD", "1");
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

    std::optional<mistake_frames::Recorder> recorder;
    if (record) recorder.emplace(source, dir / "frames");
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
        bool caught = false, named = false, image_only = false, image_failed = false;
        bool by_evidence = false, by_file = false;
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
            named = caught && names_mistake(g, m.named, m.id);
            // Named by evidence: the state diff's sentence, from the records.
            by_evidence = caught && !m.state.empty() && g.output.find(m.state) != std::string::npos;
            // Which file is wrong: never another file than the mistake's,
            // and none for a mistake in C++.
            const std::set<std::string> files = files_named(g.output);
            const std::string own = shader ? m.file.substr(std::strlen("shaders/")) : "";
            if (!files.empty()) result += "; file named";
            by_file = caught && shader && files == std::set<std::string>{own};
            CHECK_MESSAGE((files.empty() || (shader && files == std::set<std::string>{own})),
                          m.id << ": the grader names " << fw::join(files, ", ")
                               << " as the file that holds a mistake in " << m.file);
            image_only = caught && !check_fails(g, lab_id(m.lab), "unit");
            // A frame to know it by: a visible image check failed on a
            // frame the lab rendered (not for want of one).
            image_failed = check_fails(g, lab_id(m.lab), "image", /*visible=*/true) &&
                           g.status[lab_id(m.lab)] == "ok";
            if (recorder) {
                // Its frames, with the signature a student's evidence must
                // agree with before it is named (frame_guesses.hpp).
                const grading::KnownMistake signature{m.id, m.why, m.file,
                                                      failed_units(g, lab_id(m.lab)), ""};
                const size_t frames = recorder->add(m.lab, dir / "mistake", signature,
                                                    state_sentences(g, lab_id(m.lab)));
                result += "; " + std::to_string(frames) + " frames kept";
            }
            for (const auto& [id, status] : g.status)
                if (status != "ok") result += " [" + id + ": " + status + "]";
        }
        write_text(target, original);

        LabTally& t = tally[m.lab];
        ++t.mistakes;
        t.caught += caught;
        t.points += lost;
        t.named += named;
        t.image_only += image_only;
        t.image_only_named += image_only && named;
        t.state += !m.state.empty();
        t.by_evidence += by_evidence;
        t.shaders += caught && shader;
        t.by_file += by_file;
        if (caught)
            result += std::string(named ? "; named by frame" : "; not named by frame") +
                      (image_only ? " (image only)" : "") +
                      (m.state.empty() ? ""
                       : by_evidence   ? "; named by evidence"
                                       : "; NOT named by evidence");
        if (caught && !named && !by_evidence && !by_file) t.unnamed.push_back(m.id);
        char line[1024];
        std::snprintf(line, sizeof line, "%-34s %-18s %s (%.1f s)\n", m.id.c_str(), m.lab.c_str(),
                      result.c_str(), seconds_since(start));
        std::printf("%s", line);
        std::fflush(stdout);
        report += line;
        CHECK_MESSAGE(caught, m.id << " (" << m.why << "): " << result
                                   << "; add a visible checkpoint or probe that it fails");
        // A state mistake must be named by the state diff.
        if (caught && !m.state.empty() && !skip_named && !record)
            CHECK_MESSAGE(by_evidence, m.id << ": the terminal of course grade does not say \""
                                            << m.state << "\" (the state diff)");
        // One named by its kind must be; one that fails a visible image
        // check must be, since its frame is known (recorded).
        // A state mistake the state diff names is named by evidence instead.
        if (caught && !skip_named && !record && (!m.named.empty() || image_failed) &&
            !(m.named.empty() && by_evidence))
            CHECK_MESSAGE(named, m.id << ": the terminal of course grade does not say \""
                                      << (m.named.empty() ? "known mistake draws (" + m.id + ")"
                                                          : named_sentence(m.named))
                                      << "\"" << std::string(m.named.empty() ? kRecordHint : ""));
    }
    if (recorder) {
        // Only the labs whose mistakes all ran: a lab's folder is written whole.
        std::set<std::string> complete;
        for (const auto& [l, n] : per_lab)
            if (tally.count(l) && tally[l].mistakes == n) complete.insert(l);
        const size_t images = recorder->write(source, complete);
        MESSAGE("MISTAKES_RECORD=1: " << images << " frames written for " << complete.size()
                                      << " labs under labs/*/reference/mistakes/");
    }

    // The table: per lab, the mistakes tried, those caught by a visible
    // check, the visible points they lost in all, the caught ones the grader
    // names by their frame or their kind, and of those caught only by image,
    // probe or stat checks (no unit check fails) the ones it names; then what
    // names them by evidence from the checkpoint itself: of the state
    // mistakes, those the state diff names ("state"), and of the caught
    // shader mistakes, those it localises to their own file ("file").
    char line[256];
    std::string table;
    std::snprintf(line, sizeof line, "%-18s %8s %6s %11s %6s %10s %6s %6s\n", "lab", "mistakes",
                  "caught", "points lost", "named", "image-only", "state", "file");
    table += line;
    LabTally sum;
    auto fraction = [](size_t a, size_t b) { return std::to_string(a) + "/" + std::to_string(b); };
    auto row = [&](const std::string& name, const LabTally& t) {
        std::snprintf(
            line, sizeof line, "%-18s %8zu %6zu %11s %6s %10s %6s %6s\n", name.c_str(), t.mistakes,
            t.caught, points_text(t.points).c_str(), fraction(t.named, t.caught).c_str(),
            fraction(t.image_only_named, t.image_only).c_str(),
            fraction(t.by_evidence, t.state).c_str(), fraction(t.by_file, t.shaders).c_str());
        table += line;
    };
    for (const auto& [l, t] : tally) {
        row(l, t);
        sum.mistakes += t.mistakes, sum.caught += t.caught, sum.points += t.points;
        sum.named += t.named, sum.image_only += t.image_only;
        sum.image_only_named += t.image_only_named;
        sum.state += t.state, sum.by_evidence += t.by_evidence;
        sum.shaders += t.shaders, sum.by_file += t.by_file;
        sum.unnamed.insert(sum.unnamed.end(), t.unnamed.begin(), t.unnamed.end());
    }
    row("total", sum);
    if (!sum.unnamed.empty())
        table +=
            "not named (the terminal shows where they differ: a unit check's first failing "
            "case, a probe's colour, a compiler's message): " +
            fw::join(sum.unnamed, ", ") + "\n";
    std::printf("\n%s%s", report.c_str(), table.c_str());
    MESSAGE("mistakes, each alone on the solution:\n"
            << report << "\n"
            << table << mistakes.size() << " mistakes in " << seconds_since(total) << " s"
            << std::string(skip_named ? " (MISTAKES_SKIP_NAMED=1: names not checked)" : ""));
}
