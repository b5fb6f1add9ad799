// Helpers for the `course grade` tests: running course, small repository
// trees for LAB_ROOT, and reading the reports back.
#pragma once

#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "framework/text.hpp"
#include "tests/support/test_support.hpp"

namespace grade_test {

namespace fs = std::filesystem;
using nlohmann::json;

inline std::string course() { return fw::test::bin_dir() + "/course"; }
inline std::string fake_lab() { return fw::test::bin_dir() + "/fake_lab"; }

struct Graded {
    int exit_code = -1;
    std::string output;
    json results;  // results.json, null when missing
    double seconds = 0.0;
};

// `env... [wrapper] course grade ARGS --out OUT` into whatever OUT holds
// already, then results.json.
inline Graded grade_into(const std::string& env, const std::string& args, const std::string& out,
                         const std::string& wrapper = "") {
    const auto start = std::chrono::steady_clock::now();
    fw::test::CommandResult r = fw::test::run_command(env + " " + wrapper + " " + course() +
                                                      " grade " + args + " --out " + out);
    Graded g;
    g.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    g.exit_code = r.exit_code;
    g.output = r.output;
    MESSAGE("course grade " << args << ": exit " << r.exit_code << " after " << g.seconds << " s\n"
                            << r.output);
    std::ifstream in(out + "/results.json");
    if (in) g.results = json::parse(in, nullptr, false);
    return g;
}

// grade_into a fresh OUT. The wrapper is a command line that runs the rest
// (a sandbox profile's).
inline Graded grade(const std::string& env, const std::string& args, const std::string& out,
                    const std::string& wrapper = "") {
    fs::remove_all(out);
    return grade_into(env, args, out, wrapper);
}

// The rows of a summary.txt, each as its words: "lab  score  checks
// status...  seconds" under a header line, up to a blank line.
inline std::vector<std::vector<std::string>> summary_rows(const std::string& summary) {
    std::istringstream table(summary);
    std::string line;
    std::getline(table, line);
    std::vector<std::vector<std::string>> rows;
    while (std::getline(table, line) && !line.empty()) {
        std::istringstream words(line);
        rows.emplace_back(std::istream_iterator<std::string>(words),
                          std::istream_iterator<std::string>());
    }
    return rows;
}

// Text from a report's HTML: the character references it writes, undone.
inline std::string unescape_markup(const std::string& html) {
    std::string out;
    for (size_t i = 0; i < html.size();) {
        bool replaced = false;
        for (const auto& [ref, c] : {std::pair<const char*, char>{"&amp;", '&'},
                                     {"&lt;", '<'},
                                     {"&gt;", '>'},
                                     {"&quot;", '"'},
                                     {"&#39;", '\''}}) {
            const std::string r = ref;
            if (html.compare(i, r.size(), r) == 0) {
                out += c;
                i += r.size();
                replaced = true;
                break;
            }
        }
        if (!replaced) out += html[i++];
    }
    return out;
}

// The checks of results.json, one entry each: a test there is a checkpoint,
// its extra_data lists the checks in the order its html output shows them,
// each as "<p><strong>PASS|FAIL</strong> TITLE (...)</p>" and its output in
// a <pre>. Each entry: {"name": "LAB / CHECKPOINT / TITLE", "status",
// "score", "max_score", "visibility", "output" (the check's own text),
// "checkpoint_output" (the checkpoint's whole output, markup and all)}.
inline json checks_of(const json& results) {
    json out = json::array();
    if (!results.is_object() || !results.contains("tests")) return out;
    for (const json& t : results["tests"]) {
        const std::string html = t.value("output", "");
        std::vector<size_t> starts;
        for (size_t at = html.find("<p><strong>"); at != std::string::npos;
             at = html.find("<p><strong>", at + 1))
            if (html.compare(at + 11, 4, "PASS") == 0 || html.compare(at + 11, 4, "FAIL") == 0)
                starts.push_back(at);
        const json checks = t.contains("extra_data")
                                ? t["extra_data"].value("checks", json::array())
                                : json::array();
        for (size_t i = 0; i < checks.size(); ++i) {
            std::string output;
            if (i < starts.size()) {
                const size_t end = i + 1 < starts.size() ? starts[i + 1] : html.size();
                const size_t pre = html.find("<pre>", starts[i]);
                if (pre < end)
                    output =
                        unescape_markup(html.substr(pre + 5, html.find("</pre>", pre) - pre - 5));
            }
            out.push_back({{"name", t.value("name", "") + " / " + checks[i].value("title", "")},
                           {"status", checks[i].value("passed", false) ? "passed" : "failed"},
                           {"score", checks[i].value("score", 0.0)},
                           {"max_score", checks[i].value("max_score", 0.0)},
                           {"visibility", t.value("visibility", "")},
                           {"output", output},
                           {"checkpoint_output", unescape_markup(html)}});
        }
    }
    return out;
}

// The checks of one lab in results.json ("<lab> / <checkpoint> / <check>").
inline json lab_tests(const json& results, const std::string& lab) {
    json out = json::array();
    for (const json& t : checks_of(results))
        if (t.value("name", "").rfind(lab + " / ", 0) == 0) out.push_back(t);
    return out;
}

inline void write_file(const std::string& path, const std::string& text) {
    fs::create_directories(fs::path(path).parent_path());
    std::ofstream(path) << text;
}

// A repository for LAB_ROOT: lab 0's data file and references copied from
// the source tree and, with `hostile`, a lab "hostile" of two 64 x 64
// checkpoints (image, probe, stat each, 3 points) with black references.
inline std::string make_tree(const std::string& dir, bool hostile) {
    fs::remove_all(dir);
    const fs::path src = fs::path(fw::test::source_dir()) / "labs/00_pipeline";
    fs::create_directories(dir + "/labs/00_pipeline");
    fs::copy_file(src / "checkpoints.json", dir + "/labs/00_pipeline/checkpoints.json");
    if (fs::exists(src / "reference"))
        fs::copy(src / "reference", dir + "/labs/00_pipeline/reference");
    if (!hostile) return dir;
    std::vector<std::string> checkpoints;
    for (const char* name : {"frame", "frame2"}) {
        checkpoints.push_back(R"(  {"name": ")" + std::string(name) +
                              R"(", "visibility": "visible", "params": {}, "checks": [
     {"kind": "image", "size": [64, 64], "points": 1},
     {"kind": "probe", "at": [1, 1], "color": [0, 0, 0], "points": 1},
     {"kind": "stat", "stat": "primitives_generated", "equals": 0, "points": 1}]})");
        fs::create_directories(dir + "/labs/01_hostile/reference");
        fw::write_png(dir + "/labs/01_hostile/reference/" + name + ".png",
                      fw::Image(64, 64, {0, 0, 0, 255}));
    }
    write_file(
        dir + "/labs/01_hostile/checkpoints.json",
        "{\"lab\": \"hostile\", \"checkpoints\": [\n" + fw::join(checkpoints, ",\n") + "]}\n");
    return dir;
}

// Where the user can reach what it runs. The build may sit below a folder
// only root can enter (a clone in a mktemp directory is 0700), so the test
// stages `lab`, the fake and the shaders in a fresh world-searchable folder
// and points LAB_SHADER_DIR there; LAB_ROOT trees are made inside it too.
struct Staged {
    std::string dir, lab, fake, env;
};

inline Staged stage_for_run_as() {
    char name[] = "/tmp/course-run-as-XXXXXX";
    REQUIRE(mkdtemp(name) != nullptr);
    fw::test::remove_when_passed(name);
    Staged s{name, std::string(name) + "/lab", std::string(name) + "/fake_lab", ""};
    chmod(name, 0755);
    fs::copy_file(fw::test::bin_dir() + "/lab", s.lab);
    fs::copy_file(fake_lab(), s.fake);
    fs::copy(fw::test::source_dir() + "/shaders", s.dir + "/shaders", fs::copy_options::recursive);
    for (const auto& e : fs::recursive_directory_iterator(s.dir))
        chmod(e.path().c_str(),
              e.is_directory() ? 0755 : (e.path() == s.lab || e.path() == s.fake ? 0755 : 0644));
    s.env = "LAB_SHADER_DIR=" + s.dir + "/shaders";
    return s;
}

// Every report file is there and whole; results.json has `checks` checks.
inline void check_reports(const std::string& out, size_t checks) {
    for (const char* file : {"summary.txt", "results.json", "junit.xml", "index.html"}) {
        CAPTURE(file);
        CHECK(fs::exists(out + "/" + file));
    }
    std::ifstream html(out + "/index.html"), junit(out + "/junit.xml");
    std::string h((std::istreambuf_iterator<char>(html)), {}),
        j((std::istreambuf_iterator<char>(junit)), {});
    CHECK(h.find("</html>") != std::string::npos);
    CHECK(j.find("</testsuites>") != std::string::npos);
    std::ifstream in(out + "/results.json");
    json results = json::parse(in, nullptr, false);
    REQUIRE(results.is_object());
    CHECK(checks_of(results).size() == checks);
}

// Every check of lab 0, from its data file (read here, not by course).
inline json lab0_checks() {
    std::ifstream in(fw::test::source_dir() + "/labs/00_pipeline/checkpoints.json");
    const json doc = json::parse(in, nullptr, true, /*ignore_comments=*/true);
    json checks = json::array();
    for (const json& cp : doc["checkpoints"])
        for (const json& check : cp.value("checks", json::array())) checks.push_back(check);
    return checks;
}

inline double points(const json& checks) {
    double sum = 0.0;
    for (const json& c : checks) sum += c["points"].get<double>();
    return sum;
}

// Whether `lab` can render on `backend` here; `why` gets the reason if not.
// (usable_backend below is what a test case normally wants.)
inline bool backend_available(const std::string& backend, std::string& why) {
    const std::string png = fw::test::out_dir() + "/probe_" + backend + ".png";
    fw::test::CommandResult r = fw::test::run_command(
        fw::test::bin_dir() + "/lab render pipeline --backend " + backend + " -o " + png);
    why = r.output;
    return r.exit_code == 0;
}

// For the part of a test case that `what` names and that needs `backend`:
// true when it renders here, else the part is skipped with the reason (or
// fails, when LAB_REQUIRE_BACKENDS asks for the backend).
inline bool usable_backend(const std::string& backend, const std::string& what) {
    std::string why;
    if (backend_available(backend, why)) return true;
    fw::test::skip_part_without(backend, what, why);
    return false;
}

}  // namespace grade_test
