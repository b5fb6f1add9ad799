#include "grading/diagnosis/file_isolation.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "framework/error.hpp"
#include "grading/diagnosis/frame_guesses.hpp"

namespace grading {

namespace fs = std::filesystem;
using nlohmann::json;

namespace {

bool is_stage_file(const fs::path& path) {
    static const std::set<std::string> stages = {".vert", ".tesc", ".tese",
                                                 ".geom", ".frag", ".comp"};
    return stages.count(path.extension().string()) > 0;
}

// Whether `text` holds a release marker's opening line (docs/conventions.md,
// Student parts).
bool has_solution_block(const std::string& text) {
    std::istringstream lines(text);
    for (std::string line; std::getline(lines, line);) {
        const size_t start = line.find_first_not_of(" \t");
        const size_t end = line.find_last_not_of(" \t\r");
        if (start != std::string::npos &&
            line.compare(start, end - start + 1, "// BEGIN SOLUTION") == 0)
            return true;
    }
    return false;
}

// The kinds of check whose failure starts the search: what the shaders drew
// or wrote, and how they used GL (a compute shader that writes past its
// count). A stat alone (a count, the lab's own figures) is mostly C++'s.
bool starts_search(CheckKind kind) {
    return kind == CheckKind::Image || kind == CheckKind::Probe || kind == CheckKind::Buffer ||
           kind == CheckKind::Portable;
}

// The job of the lab's own child, cut to the renders whose checkpoint has a
// failed check that starts the search, with no unit calls.
json job_for(const json& lab_job, const std::vector<CheckResult>& checks) {
    std::set<std::string> failed;
    for (const CheckResult& c : checks)
        if (!c.passed && starts_search(c.kind)) failed.insert(c.checkpoint);
    json job = {
        {"lab", lab_job.value("lab", "")}, {"renders", json::array()}, {"units", json::array()}};
    // Read in place: a copy of the lab's renders would cost every lab, failed or not.
    const auto renders = lab_job.find("renders");
    if (failed.empty() || renders == lab_job.end() || !renders->is_array()) return job;
    for (const json& r : *renders)
        if (failed.count(r.value("name", ""))) job["renders"].push_back(r);
    return job;
}

}  // namespace

std::map<std::string, std::string> student_shaders(const LabFiles& lab) {
    std::map<std::string, std::string> files;
    // An autograder's LAB_ROOT holds the student's shaders: the course's are aside.
    const fs::path aside = fs::path(lab.root) / kSolutionShaders;
    const fs::path folder =
        (fs::is_directory(aside) ? aside : fs::path(lab.root) / "shaders") / lab.dir;
    std::error_code ec;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        if (!is_stage_file(it->path()) || !fs::is_regular_file(fs::symlink_status(it->path())))
            continue;
        std::ifstream in(it->path(), std::ios::binary);
        std::ostringstream text;
        if (!(text << in.rdbuf())) throw fw::Error("cannot read '" + it->path().string() + "'");
        if (has_solution_block(text.str()))
            files[lab.dir + "/" + it->path().filename().string()] = text.str();
    }
    return files;
}

std::string file_isolation_sentence(const std::string& file) {
    return "The frame is right with the course's `" + fs::path(file).filename().string() +
           "` in place of yours: the mistake is in shaders/" + file + ".";
}

void isolate_shader_mistakes(const LabFiles& lab, const json& job, const FrameVerdict& frame_passes,
                             std::vector<CheckResult>& checks, const ChildSpawn& spawn) {
    // Job 0 renders the student's files as they are: a checkpoint that
    // passes there (its frame depended on a checkpoint rendered before it
    // in the lab's own child) says nothing of its files. Job i replaces the
    // i-th file.
    std::vector<json> jobs = {job_for(job, checks)};
    if (jobs.front()["renders"].empty()) return;
    const std::map<std::string, std::string> files = student_shaders(lab);
    if (files.empty()) return;
    std::vector<std::string> names;
    for (const auto& [file, text] : files) {
        names.push_back(file);
        jobs.push_back(jobs.front());
        jobs.back()["shader_overrides"] = {{file, text}};
    }
    std::vector<LabChild> children(jobs.size());
    run_lab_children(spawn.lab_binary, jobs, spawn.backend, spawn.limits, spawn.user, spawn.cache,
                     [&](size_t i, LabChild&& child) { children[i] = std::move(child); });
    // A job whose child did not end normally restores nothing.
    auto passes = [&](size_t i, const std::string& checkpoint) {
        const LabChild& child = children[i];
        return child.run.ok() && child.outputs && frame_passes(checkpoint, *child.outputs);
    };
    if (!children.front().run.ok()) return;

    FrameIsolations found;
    for (const json& render : jobs.front()["renders"]) {
        const std::string checkpoint = render.value("name", "");
        if (passes(0, checkpoint)) continue;
        std::vector<std::string> restoring;
        for (size_t i = 1; i < jobs.size(); ++i)
            if (passes(i, checkpoint)) restoring.push_back(names[i - 1]);
        // Only a child that ended normally replaced its file.
        FrameIsolation& here = found[checkpoint];
        for (size_t i = 1; i < jobs.size(); ++i)
            if (children[i].run.ok()) here.replaced.insert(names[i - 1]);
        if (restoring.size() == 1) here.puts_right = restoring.front();
        if (restoring.size() != 1) continue;
        // Once, under the checkpoint's first failed check that started the search.
        const auto first = std::find_if(checks.begin(), checks.end(), [&](const CheckResult& c) {
            return c.checkpoint == checkpoint && !c.passed && starts_search(c.kind);
        });
        const std::string sentence = file_isolation_sentence(restoring.front());
        first->diagnosis += (first->diagnosis.empty() ? "" : "\n") + sentence;
        first->output += (first->output.empty() ? "" : "\n") + sentence;
    }
    // The guesses from the frames, weighed again with what was found here.
    say_frame_guesses(lab, checks, &found);
}

}  // namespace grading
