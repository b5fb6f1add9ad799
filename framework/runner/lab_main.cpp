// `lab`: the labs themselves (docs/contract.md, `lab`). Lists labs and their
// checkpoints, renders one frame offscreen, or opens a window.
#include <CLI/CLI.hpp>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include "framework/checkpoints.hpp"
#include "framework/cli.hpp"
#include "framework/context.hpp"
#include "framework/error.hpp"
#include "framework/image.hpp"
#include "framework/lab.hpp"
#include "framework/lab_buffers.hpp"
#include "framework/render.hpp"
#include "framework/runner/grade_child.hpp"
#include "framework/serve/server.hpp"
#if LAB_HAVE_WINDOW
#include "framework/window/window.hpp"
#endif

namespace {

using nlohmann::json;

void print_list(bool as_json) {
    json labs = json::array();
    for (const fw::RegisteredLab& lab : fw::registered_labs()) {
        json params = json::array();
        for (const fw::Param& p : lab.info.params) params.push_back(fw::describe_param(p));
        labs.push_back({{"number", lab.info.number},
                        {"name", lab.info.id},
                        {"title", lab.info.title},
                        {"params", params}});
    }
    if (as_json) {
        std::cout << labs.dump(2) << "\n";
        return;
    }
    for (const json& lab : labs)
        std::printf("%02d  %-15s %s\n", lab["number"].get<int>(),
                    lab["name"].get<std::string>().c_str(),
                    lab["title"].get<std::string>().c_str());
}

void print_checkpoints(const fw::RegisteredLab& lab, bool as_json) {
    std::vector<fw::Checkpoint> all = fw::load_checkpoints(lab);
    if (as_json) {
        json out = json::array();
        for (const fw::Checkpoint& cp : all)
            out.push_back({{"name", cp.name},
                           {"visibility", cp.visibility},
                           {"description", cp.description},
                           {"params", fw::checkpoint_params(lab, cp).to_json()},
                           {"checks", cp.checks.size()}});
        std::cout << out.dump(2) << "\n";
        return;
    }
    for (const fw::Checkpoint& cp : all) {
        std::string sets;
        for (const auto& [key, value] : cp.params.items())
            sets += " " + key + "=" + (value.is_string() ? value.get<std::string>() : value.dump());
        std::printf("%-28s %-8s%s\n", cp.name.c_str(), cp.visibility.c_str(), sets.c_str());
    }
}

fw::ParamValues resolve_params(const fw::RegisteredLab& lab, const std::string& checkpoint,
                               const std::vector<std::string>& sets) {
    fw::ParamValues values = fw::default_params(lab);
    if (!checkpoint.empty()) {
        std::vector<fw::Checkpoint> all = fw::load_checkpoints(lab);
        values = fw::checkpoint_params(lab, fw::find_checkpoint(all, checkpoint, lab.info.id));
    }
    for (const std::string& s : sets) values.set_assignment(s);
    return values;
}

void write_text(const std::string& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    if (!(out << text))
        throw fw::Error("cannot write '" + path +
                        "'; check that its directory exists and is writable");
}

struct RenderArgs {
    std::string lab, checkpoint, size = "512x512", backend, output, depth_out, stats, buffers;
    std::vector<std::string> sets;
};

void render(const RenderArgs& a) {
    const fw::RegisteredLab& lab = fw::find_lab(a.lab);
    fw::ParamValues params = resolve_params(lab, a.checkpoint, a.sets);
    int width = 0, height = 0;
    fw::parse_size(a.size, width, height);
    fw::Backend backend = a.backend.empty() ? fw::backend_from_env() : fw::parse_backend(a.backend);
    auto context = fw::create_offscreen_context(backend);
    fw::LabRenderer renderer(lab, context->info());
    const fw::ReadBack read{!a.depth_out.empty(), !a.buffers.empty()};
    fw::RenderOutput out = renderer.render(params, width, height, 0.0, read);
    fw::write_png(a.output, out.color);
    if (read.depth) fw::write_pfm(a.depth_out, out.depth);
    if (!a.stats.empty()) write_text(a.stats, out.stats.dump(2) + "\n");
    if (read.buffers) fw::write_buffers(a.buffers, out.buffers);
}

// Renders every checkpoint of the given labs (all labs when none) in one
// context into DIR/<lab>/<checkpoint>.{png,pfm,json}.
void render_checkpoints(const std::vector<std::string>& lab_ids, const std::string& dir,
                        const std::string& backend_name) {
    std::vector<const fw::RegisteredLab*> labs;
    for (const std::string& id : lab_ids) labs.push_back(&fw::find_lab(id));
    if (labs.empty())
        for (const fw::RegisteredLab& lab : fw::registered_labs()) labs.push_back(&lab);
    fw::Backend backend =
        backend_name.empty() ? fw::backend_from_env() : fw::parse_backend(backend_name);
    auto context = fw::create_offscreen_context(backend);
    for (const fw::RegisteredLab* lab : labs) {
        std::string lab_dir = dir + "/" + lab->info.id;
        std::error_code ec;
        std::filesystem::create_directories(lab_dir, ec);
        if (ec) throw fw::Error("cannot create '" + lab_dir + "': " + ec.message());
        fw::LabRenderer renderer(*lab, context->info());
        for (const fw::Checkpoint& cp : fw::load_checkpoints(*lab)) {
            fw::RenderOutput out = renderer.render(fw::checkpoint_params(*lab, cp), 512, 512);
            std::string base = lab_dir + "/" + cp.name;
            fw::write_png(base + ".png", out.color);
            fw::write_pfm(base + ".pfm", out.depth);
            write_text(base + ".json", out.stats.dump(2) + "\n");
            std::printf("%-12s %-28s %s.png\n", lab->info.id.c_str(), cp.name.c_str(),
                        base.c_str());
        }
    }
}

// A subcommand and what runs it once its options are parsed.
using fw::cli::Command;

// A command that returns when it has done its work: exit status 0.
template <class F>
std::function<int()> done(F f) {
    return [f] {
        f();
        return 0;
    };
}

const char* const kBackendHelp = "auto|osmesa|egl (default $LAB_BACKEND or auto)";

Command add_list(CLI::App& app, bool& as_json) {
    auto* list = app.add_subcommand("list", "List the labs");
    list->add_flag("--json", as_json, "Print JSON with every parameter");
    return {list, done([&as_json] { print_list(as_json); })};
}

struct CheckpointsArgs {
    std::string lab;
    bool json = false;
};

Command add_checkpoints(CLI::App& app, CheckpointsArgs& a) {
    auto* checkpoints = app.add_subcommand("checkpoints", "List a lab's checkpoints");
    checkpoints->add_option("LAB", a.lab, "Lab name")->required();
    checkpoints->add_flag("--json", a.json, "Print JSON");
    return {checkpoints, done([&a] { print_checkpoints(fw::find_lab(a.lab), a.json); })};
}

Command add_render(CLI::App& app, RenderArgs& a) {
    auto* render_cmd = app.add_subcommand("render", "Draw one frame offscreen into a PNG");
    render_cmd->add_option("LAB", a.lab, "Lab name")->required();
    render_cmd->add_option("--set", a.sets, "Set a parameter: name=value (repeatable)");
    render_cmd->add_option("--checkpoint", a.checkpoint, "Start from this checkpoint's parameters");
    render_cmd->add_option("--size", a.size, "Frame size WxH (default 512x512)");
    render_cmd->add_option("--backend", a.backend, kBackendHelp);
    render_cmd->add_option("-o,--output", a.output, "PNG file to write")->required();
    render_cmd->add_option("--depth-out", a.depth_out, "Write window-space depth as PFM");
    render_cmd->add_option("--stats", a.stats, "Write frame statistics as JSON");
    render_cmd->add_option("--buffers", a.buffers,
                           "Write the buffers the lab's shaders wrote as JSON");
    return {render_cmd, done([&a] { render(a); })};
}

struct RenderCheckpointsArgs {
    std::vector<std::string> labs;
    std::string out = "renders", backend;
};

Command add_render_checkpoints(CLI::App& app, RenderCheckpointsArgs& a) {
    auto* render_cps = app.add_subcommand(
        "render-checkpoints", "Render every checkpoint of the labs (all when none) in one context");
    render_cps->add_option("LAB", a.labs, "Lab names");
    render_cps->add_option("--out", a.out, "Directory to write into (default ./renders)");
    render_cps->add_option("--backend", a.backend, kBackendHelp);
    return {render_cps, done([&a] { render_checkpoints(a.labs, a.out, a.backend); })};
}

struct GradeChildArgs {
    std::vector<std::string> jobs, outs;
    std::string backend;
    int output_fd = -1, job_gate_fd = -1;
};

Command add_grade_child(CLI::App& app, GradeChildArgs& a) {
    auto* grade_child = app.add_subcommand(
        "grade-child", "Used by 'course grade': render and evaluate what a job file lists");
    grade_child->group("");  // not listed in --help: course's interface, not the user's
    // One --out per --job, in the same order: the labs are graded in turn.
    grade_child->add_option("--job", a.jobs, "Job file (JSON); repeated for several labs")
        ->required()
        ->take_all();
    grade_child->add_option("--out", a.outs, "Directory for each job's outputs")
        ->required()
        ->take_all();
    grade_child->add_option("--backend", a.backend, "auto|osmesa|egl");
    grade_child->add_option("--output-fd", a.output_fd,
                            "Send every output but child.json as records on this descriptor");
    grade_child->add_option("--job-gate-fd", a.job_gate_fd,
                            "Read a byte on this descriptor before each job file: course "
                            "writes a job once this process is running");
    return {grade_child, done([&a] {
                fw::grade_children(a.jobs, a.outs, a.backend, a.output_fd, a.job_gate_fd);
            })};
}

struct RunArgs {
    std::string lab, size = "512x512";
    std::vector<std::string> sets;
    int frames = 0;
    std::string screenshot;
    bool no_ui = false;
};

void run_in_window(const RunArgs& a) {
    const fw::RegisteredLab& lab = fw::find_lab(a.lab);
    fw::ParamValues params = resolve_params(lab, "", a.sets);
#if LAB_HAVE_WINDOW
    fw::WindowOptions options;
    fw::parse_size(a.size, options.width, options.height);
    options.frames = a.frames;
    options.screenshot = a.screenshot;
    options.show_ui = !a.no_ui;
    fw::run_window(lab, params, options);
#else
    throw fw::EnvironmentError(
        "this build has no window: GLFW or Dear ImGui (libglfw3-dev, libimgui-dev) was "
        "missing when CMake ran; install them and rebuild, or use 'lab render'");
#endif
}

Command add_run(CLI::App& app, RunArgs& a) {
    auto* run = app.add_subcommand("run", "Open the lab in a window with a parameter panel");
    run->add_option("LAB", a.lab, "Lab name")->required();
    run->add_option("--set", a.sets, "Set a parameter: name=value (repeatable)");
    run->add_option("--size", a.size, "Window size WxH (default 512x512)");
    run->add_option("--frames", a.frames, "Quit after N frames")->check(CLI::NonNegativeNumber);
    run->add_option("--screenshot", a.screenshot, "Save the last frame to this PNG");
    run->add_flag("--no-ui", a.no_ui, "Hide the parameter panel");
    return {run, done([&a] { run_in_window(a); })};
}

struct ServeArgs {
    fw::ServeOptions options;
    std::string size = "800x600";
};

Command add_serve(CLI::App& app, ServeArgs& a) {
    auto* serve = app.add_subcommand(
        "serve", "Serve the lab live in a browser page, rendered offscreen (no window needed)");
    serve->add_option("LAB", a.options.lab, "Lab name")->required();
    serve->add_option("--port", a.options.port, "TCP port (default 8080; 0: any free port)");
    serve->add_option("--host", a.options.host,
                      "Address to listen on (default 127.0.0.1: this machine only)");
    serve->add_option("--size", a.size, "Frame size WxH until the page sets it (default 800x600)");
    serve->add_option("--backend", a.options.backend, kBackendHelp);
    return {serve, done([&a] {
                fw::parse_size(a.size, a.options.width, a.options.height);
                fw::serve(a.options);
            })};
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{
        "lab: the OpenGL labs. Render offscreen, open a window or a browser page, list labs and "
        "checkpoints."};
    app.require_subcommand(1);
    bool list_json = false;
    CheckpointsArgs checkpoints;
    RenderArgs render_args;
    RenderCheckpointsArgs render_checkpoints_args;
    GradeChildArgs grade_child_args;
    RunArgs run_args;
    ServeArgs serve_args;
    const std::vector<Command> commands = {add_list(app, list_json),
                                           add_checkpoints(app, checkpoints),
                                           add_render(app, render_args),
                                           add_render_checkpoints(app, render_checkpoints_args),
                                           add_grade_child(app, grade_child_args),
                                           add_run(app, run_args),
                                           add_serve(app, serve_args)};

    return fw::cli::run(app, argc, argv, commands, "lab", {fw::exit_code_for, 1});
}
