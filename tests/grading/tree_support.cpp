// The helpers of tree_support.hpp.
#include "tests/grading/tree_support.hpp"

#include <algorithm>
#include <cstdio>
#include <thread>

#include "framework/text.hpp"
#include "tests/grading/grade_support.hpp"

namespace tree_test {

using fw::shell_quote;
using fw::test::read_text;

double seconds_since(std::chrono::steady_clock::time_point start) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

fw::test::CommandResult run(const std::string& command, bool may_fail) {
    auto start = std::chrono::steady_clock::now();
    fw::test::CommandResult r = fw::test::run_command(command);
    std::printf("[%5.1f s] exit %d: %s\n", seconds_since(start), r.exit_code, command.c_str());
    std::fflush(stdout);
    if (r.exit_code != 0 && !(may_fail && r.exit_code == 1))
        MESSAGE("output (tail):\n"
                << r.output.substr(r.output.size() > 6000 ? r.output.size() - 6000 : 0));
    return r;
}

std::string jobs() { return std::to_string(std::max(1u, std::thread::hardware_concurrency())); }

void build_tree(const fs::path& source, const std::string& targets) {
    const std::string build = (source / "build").string();
    // The suite's own build type, flags and LAB_WERROR (LAB_TEST_*), so that a
    // copy's objects are the ones the suite's build put in the cache wherever
    // the sources are the same (under the ci preset, warnings are errors in
    // the copies too); the copy's CMakeLists.txt compiles through ccache
    // itself (LAB_CCACHE).
    const std::string type = LAB_TEST_FLAGS_SUFFIX;  // RELWITHDEBINFO for RelWithDebInfo
    const std::string configure =
        "cmake -S " + shell_quote(source.string()) + " -B " + shell_quote(build) +
        " -DCMAKE_BUILD_TYPE=" + LAB_TEST_BUILD_TYPE + " -DLAB_WERROR=" + LAB_TEST_WERROR +
        (type.empty() ? ""
                      : " -DCMAKE_C_FLAGS_" + type + "=" + shell_quote(LAB_TEST_C_FLAGS) +
                            " -DCMAKE_CXX_FLAGS_" + type + "=" + shell_quote(LAB_TEST_CXX_FLAGS));
    REQUIRE_MESSAGE(run(configure).exit_code == 0, "configuring " << source);
    REQUIRE_MESSAGE(rebuild_tree(source, targets), "building " << targets << " in " << source);
}

bool rebuild_tree(const fs::path& source, const std::string& targets) {
    return run("cmake --build " + shell_quote((source / "build").string()) + " -j" + jobs() +
               " --target " + targets)
               .exit_code == 0;
}

Grade grade(const std::string& course, const std::string& lab, const std::string& labs,
            const fs::path& out, const std::string& env) {
    fs::remove_all(out);
    Grade g;
    auto r = run("env -u LAB_ROOT -u LAB_SHADER_DIR " + env + " " + shell_quote(course) +
                     " grade " + labs + " --lab " + shell_quote(lab) + " --out " +
                     shell_quote(out.string()) + " --jobs " + jobs(),
                 /*may_fail=*/true);
    g.exit_code = r.exit_code;
    g.output = r.output;
    if (!fs::exists(out / "results.json")) return g;
    g.results = nlohmann::json::parse(read_text(out / "results.json"));
    for (const auto& t : grade_test::checks_of(g.results)) {
        const std::string name = t["name"].get<std::string>();
        (t["status"] == "passed" ? g.passed : g.failed).insert(name);
        Entry& e = g.entries[name];
        e.score += t["score"].get<double>();
        e.max_score += t["max_score"].get<double>();
        e.visibility = t.value("visibility", "");
        e.output += t.value("output", "");
    }
    for (const std::vector<std::string>& w :
         grade_test::summary_rows(read_text(out / "summary.txt")))
        if (w.size() >= 5) g.status[w[0]] = fw::join(std::vector(w.begin() + 3, w.end() - 1), " ");
    return g;
}

namespace {

// "LAB / " of an entry's name "LAB / CHECKPOINT / CHECK" (or "LAB / CHECKPOINT").
std::string lab_prefix(const std::string& name) { return name.substr(0, name.find(" / ") + 3); }

}  // namespace

std::vector<Loss> visible_losses(const Grade& solution, const Grade& changed) {
    std::set<std::string> graded;  // the labs `changed` graded
    for (const auto& entry : changed.entries) graded.insert(lab_prefix(entry.first));
    std::vector<Loss> losses;
    for (const auto& [name, before] : solution.entries) {
        if (!graded.count(lab_prefix(name)) || before.visibility != "visible" ||
            before.max_score <= 0.0 || before.score < before.max_score)
            continue;
        auto it = changed.entries.find(name);
        const double after = it == changed.entries.end() ? 0.0 : it->second.score;
        if (after < before.score) losses.push_back({name, before.score - after});
    }
    return losses;
}

std::vector<std::string> lab_dirs(const fs::path& root) {
    std::vector<std::string> dirs;
    for (const auto& e : fs::directory_iterator(root / "labs"))
        if (fs::exists(e.path() / "checkpoints.json")) dirs.push_back(e.path().filename().string());
    std::sort(dirs.begin(), dirs.end());
    return dirs;
}

std::string lab_of(const std::string& file) {
    fs::path p(file);
    auto it = p.begin();
    if (it == p.end() || (*it != "labs" && *it != "shaders") || ++it == p.end()) return "";
    return it->string();
}

bool is_shader(const std::string& file) { return fs::path(file).begin()->string() == "shaders"; }

void sync_tree(const fs::path& source, const fs::path& copy,
               const std::vector<std::string>& files) {
    std::set<std::string> wanted(files.begin(), files.end());
    if (fs::exists(copy))
        for (auto it = fs::recursive_directory_iterator(copy);
             it != fs::recursive_directory_iterator(); ++it) {
            std::string rel = fs::relative(it->path(), copy).string();
            if (rel == "build")
                it.disable_recursion_pending();
            else if (it->is_regular_file() && !wanted.count(rel))
                fs::remove(it->path());
        }
    for (const std::string& rel : files) {
        if (!fs::is_regular_file(source / rel)) continue;
        std::string text = read_text(source / rel);
        if (fs::exists(copy / rel) && read_text(copy / rel) == text) continue;
        fs::create_directories((copy / rel).parent_path());
        fs::copy_file(source / rel, copy / rel, fs::copy_options::overwrite_existing);
    }
}

}  // namespace tree_test
