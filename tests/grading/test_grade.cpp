// `course grade` and `course bless` on the real lab 0 (docs/contract.md, `course`),
// and the usage errors that stop a run before any child starts (Errors).
// Expected scores come from lab 0's data file, read here.
#include <sched.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <regex>
#include <set>
#include <thread>

#include "framework/image.hpp"
#include "tests/grading/grade_support.hpp"

using namespace grade_test;

namespace {

const json* find_named(const json& tests, const std::string& part) {
    for (const json& t : tests)
        if (t.value("name", "").find(part) != std::string::npos) return &t;
    return nullptr;
}

// Checks that each checkpoint of `lab` with an image check has its rendered
// and expected images in the report, and a difference image exactly where
// the check's Observed line counts pixels beyond the tolerance; returns how
// many difference images there are.
int check_report_images(const json& results, const std::string& out, const std::string& lab) {
    const std::regex observed("Observed: ([0-9]+) of [0-9]+ pixels");
    int differences = 0, images = 0;
    for (const json& t : results["tests"]) {
        const std::string name = t.value("name", ""), output = t.value("output", "");
        std::smatch m;
        if (name.rfind(lab + " / ", 0) != 0 || !std::regex_search(output, m, observed)) continue;
        const std::string base = out + "/" + lab + "/" + name.substr(lab.size() + 3);
        CAPTURE(base);
        ++images;
        CHECK(fs::exists(base + ".png"));
        CHECK(fs::exists(base + ".expected.png"));
        const bool differs = std::stol(m[1]) > 0;
        CHECK(fs::exists(base + ".diff.png") == differs);
        differences += differs;
    }
    CHECK(images > 0);
    return differences;
}

// The keys of the Mesa caches `course warm-cache` makes in a fresh `dir`
// for lab 0, run by `wrapper` (a command line that runs the rest).
std::vector<std::string> warm_keys(const std::string& dir, const std::string& wrapper) {
    fs::remove_all(dir);
    const fw::test::CommandResult r =
        fw::test::run_command(wrapper + " " + course() + " warm-cache " + dir + " pipeline");
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    std::vector<std::string> keys;
    for (const auto& e : fs::directory_iterator(dir + "/mesa_shader_cache_sf"))
        keys.push_back(e.path().filename().string());
    std::sort(keys.begin(), keys.end());
    return keys;
}

// summary.txt's CPU line: course's seconds and its children's, each more
// than none and at most the run's wall time on every core.
void check_cpu_line(const std::string& summary, double wall_seconds) {
    const size_t at = summary.find("\nCPU: ");
    REQUIRE(at != std::string::npos);
    const std::string line = summary.substr(at + 1, summary.find('\n', at + 1) - at - 1);
    INFO(line);
    double course = -1, children = -1;
    REQUIRE(std::sscanf(line.c_str(),
                        "CPU: %lf s in course (judging, the report's images), %lf s in the "
                        "labs' children (rendering)",
                        &course, &children) == 2);
    const double most = wall_seconds * std::max(1u, std::thread::hardware_concurrency()) + 0.05;
    CHECK(course > 0.0);
    CHECK(course <= most);
    // A child that started Mesa and rendered frames: never nothing.
    CHECK(children >= 0.01);
    CHECK(children <= most);
}

// A copy of the repository's shaders in out_dir()/shaders with `code` put
// at the start of main() in `file` (under shaders/); returns the copy's
// folder and sets `line` to main()'s line in the file.
std::string shaders_with(const std::string& file, const std::string& code, int& line) {
    const std::string shaders = fw::test::out_dir() + "/shaders";
    fs::remove_all(shaders);
    fs::copy(fw::test::source_dir() + "/shaders", shaders, fs::copy_options::recursive);
    std::string text = fw::test::read_text(shaders + "/" + file);
    const size_t main_at = text.find("void main() {");
    REQUIRE(main_at != std::string::npos);
    text.insert(main_at + 13, code);
    line = static_cast<int>(std::count(text.begin(), text.begin() + main_at, '\n')) + 1;
    write_file(shaders + "/" + file, text);
    return shaders;
}

}  // namespace

TEST_CASE("course grade pipeline: full marks on each backend") {
    const json checks = lab0_checks();
    int graded = 0;
    for (const std::string backend : {"osmesa", "egl"}) {
        CAPTURE(backend);
        if (!usable_backend(backend, "grading lab 0 on " + backend)) continue;
        ++graded;
        const std::string out = fw::test::out_dir() + "/" + backend;
        Graded g = grade("", "pipeline --backend " + backend, out);
        MESSAGE("grade wall time for lab 0 on " << backend << ": " << g.seconds << " s");
        CHECK(g.exit_code == 0);
        REQUIRE(g.results.is_object());
        MESSAGE("Expected max_score " << points(checks) << ", observed "
                                      << g.results["extra_data"]["max_score"]);
        CHECK(g.results["extra_data"]["max_score"].get<double>() == points(checks));
        CHECK(g.results["score"].get<double>() ==
              g.results["extra_data"]["max_score"].get<double>());
        check_reports(out, checks.size());
        check_cpu_line(fw::test::read_text(out + "/summary.txt"), g.seconds);
        for (const json& t : g.results["tests"]) {
            CAPTURE(t.dump());
            CHECK(t["status"] == "passed");
        }
        const json checks_seen = checks_of(g.results);
        const json* unit = find_named(checks_seen, "unit expand_quad");
        REQUIRE(unit);
        CHECK((*unit)["output"].get<std::string>().find("102 of 102 cases passed") !=
              std::string::npos);
        if (check_report_images(g.results, out, "pipeline") == 0)
            CHECK(fw::test::read_text(out + "/index.html")
                      .find("no pixel differs beyond the tolerance") != std::string::npos);
        CHECK(g.output.find("pipeline") != std::string::npos);
    }
    if (graded == 0) {
        std::printf("SKIP: neither osmesa nor egl renders here\n");
        std::exit(77);
    }
}

TEST_CASE("course grade's CPU line counts only its own grading, not what ran before an exec") {
    // A shell that burns 3 s of CPU in a child (its CPU limit ends it, so
    // it is 3 s however busy the machine is), then execs course, as
    // scripts/grade.sh execs it after its build: getrusage's counts carry
    // over exec(), and the line must not show those seconds.
    if (!usable_backend("egl", "grading lab 0 after an exec on egl")) return;
    const std::string out = fw::test::out_dir() + "/after-exec";
    Graded g = grade("", "pipeline --backend egl", out,
                     "sh -c '(ulimit -t 3; while :; do :; done); exec \"$@\"' burn");
    CHECK(g.exit_code == 0);
    REQUIRE(g.results.is_object());
    const std::string summary = fw::test::read_text(out + "/summary.txt");
    // course's own wall time: the bound is what its cores could spend in it.
    check_cpu_line(summary, g.results["execution_time"].get<double>());
    // On any number of cores: lab 0's child needs a fraction of a second
    // (0.1 s on 2 cores), far from the 3 s before the exec.
    const std::string before = " s in course (judging, the report's images), ";
    const size_t at = summary.find(before);
    REQUIRE(at != std::string::npos);
    CHECK(std::stod(summary.substr(at + before.size())) < 2.0);
}

TEST_CASE("course grade: a difference image for each frame whose pixels differ") {
    const std::string out = fw::test::out_dir() + "/liar";
    // Black frames where lab 0 draws triangles on a grey background.
    Graded g =
        grade("FAKE_LAB_TARGET=pipeline FAKE_LAB_MODE=liar", "pipeline --lab " + fake_lab(), out);
    CHECK(g.exit_code == 1);
    REQUIRE(g.results.is_object());
    CHECK(check_report_images(g.results, out, "pipeline") > 0);
}

TEST_CASE("course grade again into the same folder: files written in place, nothing left over") {
    const std::string out = fw::test::out_dir() + "/again";
    Graded first = grade("COURSE_SEED=1234", "pipeline", out);
    REQUIRE(first.exit_code == 0);
    const std::string lab_dir = out + "/pipeline";
    // Whether this filesystem has hard links (else a frame equal to its
    // reference is a copy of it).
    const bool links = ::link((out + "/results.json").c_str(), (out + "/probe").c_str()) == 0;
    fs::remove(out + "/probe");
    struct Expected {
        std::string bytes;
        ino_t inode;
    };
    std::map<std::string, Expected> expected;  // by the rendered frame's path
    auto inode = [](const std::string& path) {
        struct stat st;
        REQUIRE(::stat(path.c_str(), &st) == 0);
        return st.st_ino;
    };
    for (const fs::directory_entry& e : fs::directory_iterator(lab_dir)) {
        const std::string name = e.path().string();
        const size_t at = name.rfind(".expected.png");
        if (at == std::string::npos) continue;
        const std::string rendered = name.substr(0, at) + ".png";
        CAPTURE(rendered);
        CHECK(fw::test::read_text(rendered) == fw::test::read_text(name));
        if (links) CHECK(fs::equivalent(rendered, name));
        expected[rendered] = {fw::test::read_text(name), inode(name)};
    }
    REQUIRE(expected.size() > 5);
    fw::test::write_text(lab_dir + "/left_over.diff.png", "from an older grading");
    fs::create_directories(lab_dir + "/left_over/inside");

    // Black frames: every frame differs from its reference, and writing it
    // must not change the reference's copy that was its second name.
    Graded liar = grade_into("FAKE_LAB_TARGET=pipeline FAKE_LAB_MODE=liar",
                             "pipeline --lab " + fake_lab(), out);
    CHECK(liar.exit_code == 1);
    REQUIRE(liar.results.is_object());
    CHECK(check_report_images(liar.results, out, "pipeline") > 0);
    CHECK_FALSE(fs::exists(lab_dir + "/left_over.diff.png"));
    CHECK_FALSE(fs::exists(lab_dir + "/left_over"));
    for (const auto& [rendered, e] : expected) {
        CAPTURE(rendered);
        const std::string copy = rendered.substr(0, rendered.size() - 4) + ".expected.png";
        CHECK(fw::test::read_text(copy) == e.bytes);
        CHECK(fw::test::read_text(rendered) != e.bytes);
        CHECK(fw::read_png(rendered).pixels.at(0).r == 0);
    }

    // The lab's own frames again: the difference images go, each frame is
    // its reference's copy again, and that copy is the file it was.
    Graded again = grade_into("COURSE_SEED=1234", "pipeline", out);
    CHECK(again.exit_code == 0);
    REQUIRE(again.results.is_object());
    CHECK(check_report_images(again.results, out, "pipeline") == 0);
    for (const auto& [rendered, e] : expected) {
        CAPTURE(rendered);
        const std::string copy = rendered.substr(0, rendered.size() - 4) + ".expected.png";
        CHECK(fw::test::read_text(copy) == e.bytes);
        CHECK(fw::test::read_text(rendered) == e.bytes);
        CHECK(inode(copy) == e.inode);
        if (links) CHECK(fs::equivalent(rendered, copy));
    }
    CHECK(again.results["tests"] == first.results["tests"]);
}

TEST_CASE("course grade --jobs 2, and more jobs than labs, give the same results as --jobs 1") {
    const std::string tree = make_tree(fw::test::out_dir() + "/tree", /*hostile=*/true);
    const std::string env =
        "LAB_ROOT=" + tree + " COURSE_SEED=1234 FAKE_LAB_TARGET=hostile FAKE_LAB_MODE=liar";
    Graded one = grade(env, "--lab " + fake_lab() + " --jobs 1", fw::test::out_dir() + "/jobs1");
    Graded two = grade(env, "--lab " + fake_lab() + " --jobs 2", fw::test::out_dir() + "/jobs2");
    // A child for each of the two labs, none more.
    Graded many = grade(env, "--lab " + fake_lab() + " --jobs 8", fw::test::out_dir() + "/jobs8");
    CHECK(one.exit_code == 0);  // the liar's black frames are exactly what "hostile" expects
    REQUIRE(one.results.is_object());
    CHECK(checks_of(one.results).size() == lab0_checks().size() + 6);
    for (const Graded* other : {&two, &many}) {
        CHECK(other->exit_code == one.exit_code);
        REQUIRE(other->results.is_object());
        CHECK(one.results["tests"] == other->results["tests"]);
        CHECK(one.results["score"] == other->results["score"]);
    }
}

TEST_CASE("course warm-cache: a warning when the driver wrote no cache, none when it did") {
    // A lab child that compiles nothing leaves the cache empty: said on
    // stderr, since --shader-cache would then spare nothing.
    const std::string empty = fw::test::out_dir() + "/cache-empty";
    fs::remove_all(empty);
    const std::string mark = fw::test::out_dir() + "/warm_ran";
    fs::remove(mark);
    fw::test::CommandResult r = fw::test::run_command(
        "FAKE_LAB_TARGET=pipeline FAKE_LAB_MODE=quick FAKE_LAB_MARK=" + mark + " " + course() +
        " warm-cache " + empty + " pipeline --lab " + fake_lab());
    INFO(r.output);
    CHECK(r.exit_code == 0);
    fw::test::check_mentions(
        r.output, {"warmed pipeline", "warning: the driver wrote no shader cache into " + empty});
    // Each lab runs twice: the second run is the one a graded submission
    // resembles (it loads the programs the first one cached).
    std::ifstream ran(mark);
    std::string runs((std::istreambuf_iterator<char>(ran)), {});
    CHECK(runs == "ran: pipeline\nran: pipeline\n");

    // The real lab's shaders fill it, and nothing is said.
    const std::string filled = fw::test::out_dir() + "/cache-filled";
    fs::remove_all(filled);
    r = fw::test::run_command(course() + " warm-cache " + filled + " pipeline");
    INFO(r.output);
    CHECK(r.exit_code == 0);
    fw::test::check_mentions(r.output, {"warmed pipeline", "then", "from the cached programs",
                                        "shader cache in " + filled});
    CHECK(r.output.find("wrote no shader cache") == std::string::npos);
    int files = 0;
    for (const auto& e : fs::recursive_directory_iterator(filled)) files += e.is_regular_file();
    CHECK(files > 0);
}

TEST_CASE("course grade --shader-cache: a note when the seed was warmed for other CPUs") {
    // llvmpipe keys its cache by the CPUs: a seed warmed for others serves
    // nothing, and the autograder's log says so once, after the report.
    const std::string seed = fw::test::out_dir() + "/cache-seed";
    const std::vector<std::string> keys = warm_keys(seed, "");
    REQUIRE(keys.size() == 1);
    const std::string note = "was warmed on a machine whose CPUs differ";
    const std::string out = fw::test::out_dir() + "/report-seeded";
    // The seed of these CPUs: no note, with one lab (a child of its own) or
    // two (one child), though the seed holds only the first one's shaders.
    for (const std::string labs : {"pipeline", "pipeline transforms"}) {
        Graded g = grade("", labs + " --jobs 1 --shader-cache " + seed, out);
        CHECK(g.exit_code == 0);
        CHECK(g.output.find(note) == std::string::npos);
    }
    // The same seed under another key, as other CPUs would have made it.
    const std::string other = fw::test::out_dir() + "/cache-other-cpus";
    fs::remove_all(other);
    fs::copy(seed, other, fs::copy_options::recursive);
    fs::rename(fs::path(other) / "mesa_shader_cache_sf" / keys[0],
               fs::path(other) / "mesa_shader_cache_sf" / std::string(40, '0'));
    for (const std::string labs : {"pipeline", "pipeline transforms"}) {
        Graded g = grade("", labs + " --jobs 1 --shader-cache " + other, out);
        CHECK(g.exit_code == 0);
        fw::test::check_mentions(g.output, {"course: note: the shader cache " + other, note,
                                            "course warm-cache where grading runs"});
        CHECK(g.output.find(note) == g.output.rfind(note));
    }
    // The seed of these CPUs, graded on one of them: a note if Mesa keys a
    // cache warmed on that one CPU otherwise (Mesa 22.3's llvmpipe does).
    cpu_set_t cpus;
    if (sched_getaffinity(0, sizeof cpus, &cpus) != 0 || CPU_COUNT(&cpus) < 2) {
        MESSAGE("SKIP the one-CPU case: this process may use only one CPU");
        return;
    }
    const bool keyed = warm_keys(fw::test::out_dir() + "/cache-one-cpu", "taskset -c 0") != keys;
    MESSAGE("Mesa keys its cache by the CPUs this process may use: " << keyed);
    Graded g = grade("", "pipeline --shader-cache " + seed, out, "taskset -c 0");
    CHECK(g.exit_code == 0);
    CHECK((g.output.find(note) != std::string::npos) == keyed);
}

TEST_CASE("course grade --not-built: the lab is not run, every check fails with the first error") {
    const std::string out = fw::test::out_dir() + "/report",
                      file = fw::test::out_dir() + "/not-built.json";
    const std::string first = "labs/00_pipeline/pipeline.cpp:3:1: error: 'x' was not declared";
    // The compiler's output for lab 0's files; a folder of no graded lab is ignored.
    const std::string said =
        "labs/00_pipeline/pipeline.cpp: In function 'f':\n" + first + "\n    3 | x = 1;\n";
    fw::test::write_text(file, json{{"00_pipeline", said}, {"99_no_such_lab", "ignored"}}.dump());
    Graded g = grade("", "pipeline --not-built " + file, out);
    CHECK(g.exit_code == 1);
    REQUIRE(g.results.is_object());
    CHECK(g.results["score"].get<double>() == 0.0);
    CHECK(checks_of(g.results).size() == lab0_checks().size());
    for (const json& t : g.results["tests"]) {
        CHECK(t["status"] == "failed");
        CHECK(unescape_markup(t.value("output", "")).find("does not build: " + first) !=
              std::string::npos);
    }
    fw::test::check_mentions(unescape_markup(g.results.value("output", "")),
                             {"does not build: " + first, "3 | x = 1;"});
    fw::test::check_mentions(g.output, {"does not build: " + first});
    // Anything but an object of lab folders and texts is a usage error.
    fw::test::write_text(file, "[\"00_pipeline\"]");
    g = grade("", "pipeline --not-built " + file, out);
    CHECK(g.exit_code == 2);
    fw::test::check_mentions(g.output, {"--not-built", file});
}

TEST_CASE("course grade: usage and set-up errors exit 2 and say what would fix them") {
    const std::string out = fw::test::out_dir() + "/report";
    Graded g = grade("", "nosuch", out);
    CHECK(g.exit_code == 2);
    fw::test::check_mentions(g.output, {"unknown lab 'nosuch'", "pipeline"});

    g = grade("", "pipeline --lab /nonexistent/lab", out);
    CHECK(g.exit_code == 2);
    fw::test::check_mentions(g.output, {"/nonexistent/lab", "--lab"});

    g = grade("", "pipeline --shader-cache /nonexistent/cache", out);
    CHECK(g.exit_code == 2);
    fw::test::check_mentions(g.output, {"/nonexistent/cache", "course warm-cache"});

    if (geteuid() == 0) {
        g = grade("", "pipeline --run-as no_such_user_here", out);
        CHECK(g.exit_code == 2);
        fw::test::check_mentions(g.output, {"no user 'no_such_user_here'"});
    } else {
        g = grade("", "pipeline --run-as nobody", out);
        CHECK(g.exit_code == 2);
        fw::test::check_mentions(g.output, {"needs root"});
    }
}

TEST_CASE(
    "course grade: a malformed check stops the run before any child, naming file, checkpoint and "
    "field") {
    const std::string good =
        R"({"kind": "probe", "at": [256, 256], "color": [0, 0, 1], "tolerance": 0.01, "points": 2})";
    struct Case {
        std::string check;
        std::vector<std::string> needles;
    };
    const Case cases[] = {
        {R"({"kind": "histogram", "points": 2})",
         {"\"kind\"", "histogram", "image, probe, stat, unit"}},
        {R"({"kind": "probe", "at": [256, 256], "colour": [0, 0, 1], "points": 2})",
         {"\"colour\"", "not a field"}},
        {R"({"kind": "probe", "at": [256, 256], "color": [0, 0, 1], "tolerance": "small", "points": 2})",
         {"\"tolerance\"", "\"small\""}},
        {R"({"kind": "probe", "at": [600, 256], "color": [0, 0, 1], "points": 2})",
         {"\"at\"", "512x512"}},
        {R"({"kind": "probe", "at": [256, 256], "color": [0, 0, 1]})", {"\"points\"", "missing"}},
        {R"({"kind": "stat", "stat": "primitives_generated", "points": 1})",
         {"\"equals\"", "missing"}},
        {R"({"kind": "unit", "function": "expand_quads", "points": 2})",
         {"\"function\"", "expand_quad"}},
        {R"({"kind": "unit", "function": "expand_quad", "edge": [[1, 2]], "points": 2})",
         {"\"edge\"", "[1,2]"}},
    };
    for (const Case& c : cases) {
        CAPTURE(c.check);
        const std::string tree = make_tree(fw::test::out_dir() + "/tree", false);
        const std::string file = tree + "/labs/00_pipeline/checkpoints.json";
        std::ifstream in(file);
        std::string text((std::istreambuf_iterator<char>(in)), {});
        const size_t at = text.find(good);
        REQUIRE(at != std::string::npos);
        write_file(file, text.replace(at, good.size(), c.check));
        const std::string mark = fw::test::out_dir() + "/child_ran";
        fs::remove(mark);
        Graded g = grade("LAB_ROOT=" + tree + " FAKE_LAB_MARK=" + mark, "--lab " + fake_lab(),
                         fw::test::out_dir() + "/report");
        CHECK(g.exit_code == 2);
        std::vector<std::string> needles = c.needles;
        needles.insert(needles.end(), {file, "checkpoint 'order_depth'", "check 2"});
        fw::test::check_mentions(g.output, needles);
        CHECK_MESSAGE(!fs::exists(mark), "a child ran although the data file was rejected");
    }
}

TEST_CASE(
    "course grade: of several labs with a broken file, the first lab's is told on every run") {
    // The labs' files are read in parallel; the hostile lab's, smaller, is
    // read first, but the error told is the one of the first lab in order.
    const std::string tree = make_tree(fw::test::out_dir() + "/tree", true);
    for (const auto& e : fs::directory_iterator(tree + "/labs/00_pipeline/reference"))
        if (e.path().string().find(".record.json") != std::string::npos)
            write_file(e.path().string(), "<<<<<<< HEAD\n");
    write_file(tree + "/labs/01_hostile/reference/frame.record.json", "<<<<<<< HEAD\n");
    for (int run = 0; run < 4; ++run) {
        CAPTURE(run);
        Graded g = grade("LAB_ROOT=" + tree, "--lab " + fake_lab() + " pipeline hostile",
                         fw::test::out_dir() + "/report");
        CHECK(g.exit_code == 2);
        fw::test::check_mentions(g.output,
                                 {"labs/00_pipeline/reference/", "course bless pipeline"});
        CHECK(g.output.find("01_hostile") == std::string::npos);
    }
}

TEST_CASE("lab grade-child: units.json holds each call's result or error, the last of an id kept") {
    const std::string dir = fw::test::out_dir() + "/units_child";
    fs::remove_all(dir);
    fs::create_directories(dir);
    // The calls of one function together: call k of an entry is u<first + k>.
    write_file(dir + "/JOB.json", R"({"lab": "transforms", "renders": [], "units": [
        {"function": "nosuch", "first": 0, "args": [[]]},
        {"function": "translate", "first": 1, "args": [[[1, 2, 3]], ["three numbers"]]},
        {"function": "nosuch_either", "first": 0, "args": [[]]}]})");
    const fw::test::CommandResult r = fw::test::run_command(
        fw::test::bin_dir() + "/lab grade-child --job " + dir + "/JOB.json --out " + dir);
    REQUIRE_MESSAGE(r.exit_code == 0, r.output);
    std::ifstream in(dir + "/units.json");
    const nlohmann::json units = nlohmann::json::parse(in);
    CHECK(units.size() == 3);
    CHECK(units["u0"]["error"].get<std::string>().find("nosuch_either") != std::string::npos);
    // translate(1, 2, 3), GLM's columns: the translation is the last one.
    CHECK(units["u1"]["result"] ==
          nlohmann::json::parse("[[1.0, 0.0, 0.0, 0.0], [0.0, 1.0, 0.0, 0.0],"
                                " [0.0, 0.0, 1.0, 0.0], [1.0, 2.0, 3.0, 1.0]]"));
    CHECK(units["u2"]["error"].get<std::string>().find("3 numbers") != std::string::npos);
}

TEST_CASE("course grade: a unit check fails when the child returns wrong results") {
    const json checks = lab0_checks();
    double unit_points = 0;
    for (const json& c : checks)
        unit_points += c["kind"] == "unit" ? c["points"].get<double>() : 0.0;
    REQUIRE(unit_points > 0);
    Graded g = grade("FAKE_LAB_TARGET=pipeline FAKE_LAB_MODE=wrong_unit",
                     "pipeline --lab " + fake_lab(), fw::test::out_dir() + "/report");
    CHECK(g.exit_code == 1);
    REQUIRE(g.results.is_object());
    CHECK(g.results["score"].get<double>() == points(checks) - unit_points);
    const json checks_seen = checks_of(g.results);
    const json* unit = find_named(checks_seen, "unit expand_quad");
    REQUIRE(unit);
    CHECK((*unit)["status"] == "failed");
    fw::test::check_mentions(
        (*unit)["output"].get<std::string>(),
        {"seed", "0 of 102 cases passed", "expand_quad(", "expected", "observed", "[edge case]"});
}

TEST_CASE(
    "course grade in the terminal: each failed check's likely mistake and first case, the "
    "report's path last, the CPU and the sandbox only with --verbose") {
    const std::string out = fw::test::out_dir() + "/report";
    Graded g = grade("FAKE_LAB_TARGET=transforms FAKE_LAB_MODE=transposed_unit",
                     "transforms --lab " + fake_lab(), out);
    CHECK(g.exit_code == 1);
    fw::test::check_mentions(g.output, {"Failed checks:", "unit translate (",
                                        "    Likely mistake (transpose): your matrix is the "
                                        "transpose of the expected one",
                                        "expected (rows):", "observed (rows):",
                                        "first difference: ", "TODO parts are written"});
    // The summary.txt the run wrote holds the same, and the sandbox's line.
    const std::string summary = fw::test::read_text(out + "/summary.txt");
    CHECK(summary.find("Likely mistake (transpose)") != std::string::npos);
    CHECK(summary.find("\nSandbox: ") != std::string::npos);
    CHECK(g.output.find("Sandbox: ") == std::string::npos);
    CHECK(summary.find("\nCPU: ") != std::string::npos);
    CHECK(g.output.find("\nCPU: ") == std::string::npos);
    const std::string last = "\nReport: " + out + "/index.html\n";
    REQUIRE(g.output.size() > last.size());
    CHECK(g.output.substr(g.output.size() - last.size()) == last);
    // A transposed scale is still right: those checks keep their points.
    REQUIRE(g.results.is_object());
    CHECK(g.results["score"].get<double>() > 0);
    CHECK(g.results["score"].get<double>() < g.results["extra_data"]["max_score"].get<double>());

    Graded verbose = grade("FAKE_LAB_TARGET=transforms FAKE_LAB_MODE=transposed_unit",
                           "transforms --verbose --lab " + fake_lab(), out);
    CHECK(verbose.output.find("\nSandbox: ") != std::string::npos);
    CHECK(verbose.output.find("\nSandbox: ") < verbose.output.find("\nReport: "));
    CHECK(verbose.output.find("\nCPU: ") < verbose.output.find("\nSandbox: "));
}

TEST_CASE("course bless writes the references that course grade then accepts, on every backend") {
    // Blessing follows grade's backend rule: auto is EGL first, so the
    // references come from EGL and OSMesa (where this build has it) must
    // accept them as they are.
    const std::string tree = make_tree(fw::test::out_dir() + "/tree", false);
    fs::remove_all(tree + "/labs/00_pipeline/reference");
    fw::test::CommandResult r = fw::test::run_command("env -u LAB_BACKEND LAB_ROOT=" + tree + " " +
                                                      course() + " bless pipeline");
    MESSAGE(r.output);
    CHECK(r.exit_code == 0);
    int images = 0;
    for (const json& c : lab0_checks()) images += c["kind"] == "image";
    int written = 0;
    for (const auto& e : fs::directory_iterator(tree + "/labs/00_pipeline/reference"))
        written += e.path().extension() == ".png";
    CHECK(written == images);  // one image check per checkpoint in lab 0
    CHECK(r.output.find("wrote labs/00_pipeline/reference/order_depth.png (512x512, egl (") !=
          std::string::npos);
    for (const std::string backend : {"egl", "osmesa"}) {
        CAPTURE(backend);
        if (!usable_backend(backend, "grading EGL's references on " + backend)) continue;
        Graded g = grade("LAB_ROOT=" + tree, "pipeline --backend " + backend,
                         fw::test::out_dir() + "/report-" + backend);
        CHECK(g.exit_code == 0);
    }

    // A child that dies writes nothing and fails the command.
    r = fw::test::run_command("LAB_ROOT=" + tree + " FAKE_LAB_TARGET=pipeline FAKE_LAB_MODE=segv " +
                              course() + " bless pipeline --lab " + fake_lab());
    CHECK(r.exit_code == 2);
    fw::test::check_mentions(r.output, {"crashed (signal 11, SIGSEGV)", "nothing written"});
}

TEST_CASE("course bless: --backend and LAB_BACKEND choose, and a build without OSMesa says so") {
    const std::string tree = make_tree(fw::test::out_dir() + "/tree", false);
    const std::string bless = "LAB_ROOT=" + tree + " " + course() + " bless pipeline";
    const std::string wrote = "wrote labs/00_pipeline/reference/order_depth.png (512x512, ";

    fw::test::CommandResult r = fw::test::run_command("LAB_BACKEND=egl " + bless);
    MESSAGE(r.output);
    CHECK(r.exit_code == 0);
    CHECK(r.output.find(wrote + "egl (") != std::string::npos);

    r = fw::test::run_command("env -u LAB_BACKEND " + bless + " --backend osmesa");
    MESSAGE(r.output);
    std::string why;
    if (!fw::backend_compiled_in(fw::Backend::OSMesa, &why)) {
        // What this build offers instead, and nothing half-written.
        CHECK(r.exit_code == 2);
        fw::test::check_mentions(r.output, {"no OSMesa", "--backend egl", "nothing written"});
    } else if (usable_backend("osmesa", "blessing with --backend osmesa")) {
        CHECK(r.exit_code == 0);
        CHECK(r.output.find(wrote + "osmesa (") != std::string::npos);
    }
}

TEST_CASE("course grade: a silhouette shader that draws no outline fails the image check") {
    // Lab 10's silhouette_cube: the cube's faces with a one-pixel outline on
    // top. Without the outline every pixel of the frame has a reference pixel
    // of its colour next to it; the reference's outline has none in the frame
    // (docs/contract.md, Checks: the comparison runs both ways).
    int line = 0;
    const std::string shaders =
        shaders_with("10_advanced_geometry/silhouette.geom", " return;", line);
    for (const std::string backend : {"egl", "osmesa"}) {
        CAPTURE(backend);
        if (!usable_backend(backend, "grading lab 10 without its outline on " + backend)) continue;
        Graded g = grade("LAB_SHADER_DIR=" + shaders, "advanced-geometry --backend " + backend,
                         fw::test::out_dir() + "/report-" + backend);
        CHECK(g.exit_code == 1);
        REQUIRE(g.results.is_object());
        int images = 0;
        for (const json& t : checks_of(g.results)) {
            const std::string name = t.value("name", ""), output = t.value("output", "");
            if (name.find("/ image vs reference") == std::string::npos) continue;
            CAPTURE(name);
            ++images;
            const bool outline = name.find("silhouette_cube /") != std::string::npos;
            CHECK((t["status"] == "passed") == !outline);
            if (!outline) continue;
            // The rule in words, and the missing outline's colour as expected.
            fw::test::check_mentions(unescape_markup(output),
                                     {"and the reference's pixel there has a rendered pixel in "
                                      "its 3x3 neighbourhood that is within 8/255",
                                      "expected yellow (1, 0.85, 0.2)"});
        }
        CHECK(images >= 4);
    }
}

TEST_CASE("course grade: NDC and depth probes and stat ranges, judged from the sheet's numbers") {
    // Lab 0, scene=order, identity MVP: the blue quad at z = -0.5 covers NDC
    // (0.4, 0.4), the red quad at z = 0.5 pixel (153, 153); window depth is
    // (z + 1) / 2, so 0.25 and 0.75; the background keeps the clear depth 1.
    // The scene draws 4 triangles.
    const std::string tree = make_tree(fw::test::out_dir() + "/tree", false);
    const std::string file = tree + "/labs/00_pipeline/checkpoints.json";
    std::ifstream in(file);
    std::string text((std::istreambuf_iterator<char>(in)), {});
    const std::string anchor = R"({"kind": "image", "points": 2},)";
    const size_t at = text.find(anchor);
    REQUIRE(at != std::string::npos);
    text.insert(at + anchor.size(), R"(
     {"kind": "probe", "ndc": [0, 0], "color": [0, 0, 1], "points": 1},
     {"kind": "probe", "ndc": [0.4, 0.4], "depth": 0.25, "points": 1},
     {"kind": "probe", "at": [153, 153], "depth": 0.75, "points": 1},
     {"kind": "probe", "at": [51, 460], "depth": 0.5, "points": 1},
     {"kind": "stat", "stat": "primitives_generated", "min": 1, "max": 4, "points": 1},
     {"kind": "stat", "stat": "primitives_generated", "max": 3, "points": 1},
     {"kind": "stat", "stat": "lab_stats.nothing", "equals": 1, "points": 1},)");
    write_file(file, text);
    Graded g = grade("LAB_ROOT=" + tree, "pipeline", fw::test::out_dir() + "/report");
    CHECK(g.exit_code == 1);
    REQUIRE(g.results.is_object());
    struct Expect {
        std::string name;
        bool passed;
        std::string output;
    };
    const Expect expected[] = {
        {"order_depth / probe (256, 256) colour", true, "(NDC (0, 0))"},
        {"order_depth / probe (358, 358) depth", true, "Expected: depth 0.25 within 1e-05"},
        {"order_depth / probe (153, 153) depth", true, "Observed: depth 0.75"},
        {"order_depth / probe (51, 460) depth", false, "Observed: depth 1, difference 0.5"},
        {"order_depth / stat primitives_generated in [1, 4]", true,
         "Observed: primitives_generated = 4"},
        {"order_depth / stat primitives_generated <= 3", false,
         "Observed: primitives_generated = 4"},
        {"order_depth / stat lab_stats.nothing == 1", false,
         "the frame's stats have no lab_stats.nothing"},
    };
    const json checks_seen = checks_of(g.results);
    for (const Expect& e : expected) {
        CAPTURE(e.name);
        const json* t = find_named(checks_seen, e.name);
        REQUIRE(t);
        CHECK(((*t)["status"] == "passed") == e.passed);
        fw::test::check_mentions((*t)["output"].get<std::string>(), {e.output});
    }
    CHECK(g.results["score"].get<double>() == points(lab0_checks()) + 4);
}

TEST_CASE("course grade: a shader that does not compile costs only the checkpoints that use it") {
    // Lab 4's explode program gets a compile error; its other programs are
    // whole. The checkpoints that draw in explode mode lose their points with
    // the compiler's message; every other checkpoint still passes.
    int main_line = 0;
    const std::string shaders =
        shaders_with("04_geometry/explode.geom", " undeclared_in_explode = 1;", main_line);
    const std::string line = "explode.geom:" + std::to_string(main_line);

    const std::string out = fw::test::out_dir() + "/report";
    Graded g = grade("LAB_SHADER_DIR=" + shaders, "geometry", out);
    CHECK(g.exit_code == 1);
    REQUIRE(g.results.is_object());
    // The file as the framework shows it: relative to the repository when inside it.
    const std::regex status(R"(shader error in \S*04_geometry/explode\.geom)");
    auto names_file = [&](const std::string& report) { return std::regex_search(report, status); };
    std::ifstream in(fw::test::source_dir() + "/labs/04_geometry/checkpoints.json");
    const json doc = json::parse(in, nullptr, true, /*ignore_comments=*/true);
    std::set<std::string> explode, other;
    for (const json& cp : doc["checkpoints"])
        (cp["params"].value("mode", "") == "explode" ? explode : other)
            .insert("geometry / " + cp["name"].get<std::string>());
    REQUIRE(!explode.empty());
    REQUIRE(!other.empty());
    for (const json& t : g.results["tests"]) {
        const std::string name = t["name"];
        CAPTURE(name);
        if (explode.count(name)) {
            CHECK(t["status"] == "failed");
            CHECK(t["score"] == 0);
            const std::string output = unescape_markup(t["output"]);
            CHECK(names_file(output));
            fw::test::check_mentions(output, {line, "failed to compile", "undeclared_in_explode"});
        } else {
            CHECK(other.count(name) == 1);
            CHECK(t["status"] == "passed");
        }
    }
    // The lab's status names the file in every report.
    for (const char* report : {"summary.txt", "junit.xml", "index.html", "results.json"}) {
        CAPTURE(report);
        CHECK(names_file(fw::test::read_text(out + "/" + report)));
    }
    CHECK(names_file(g.output));
    // index.html's list of failed checkpoints gives the compiler's message as
    // the cause, not only the line that introduces it.
    const std::string html = fw::test::read_text(out + "/index.html");
    const size_t list = html.find("<ul class=\"failed-list\">");
    REQUIRE(list != std::string::npos);
    const std::string failed = html.substr(list, html.find("</ul>", list) - list);
    size_t items = 0;
    for (size_t at = failed.find("<li>"); at != std::string::npos;
         at = failed.find("<li>", at + 1)) {
        const std::string item = failed.substr(at, failed.find("</li>", at) - at);
        CAPTURE(item);
        CHECK(item.find("undeclared_in_explode") != std::string::npos);
        ++items;
    }
    CHECK(items == explode.size());
}
