#include "framework/runner/grade_child.hpp"

#include <fcntl.h>
#include <malloc.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <fstream>
#include <future>
#include <map>
#include <memory>
#include <sstream>
#include <vector>

#include "framework/error.hpp"
#include "framework/gl/shader.hpp"
#include "framework/image.hpp"
#include "framework/lab.hpp"
#include "framework/lab_buffers.hpp"
#include "framework/render.hpp"
#include "framework/runner/output_queue.hpp"
#include "framework/runner/unit_calls.hpp"
#include "framework/trace/calls.hpp"
#include "framework/trace/record.hpp"
#include "framework/trace/usage.hpp"

namespace fw {

namespace {

using nlohmann::json;

// Where a lab's outputs go: files, or with --output-fd records on that
// descriptor ("OUTPUT SIZE PATH\n" and SIZE bytes; PATH the file it stands
// for), which course keeps in memory: no file, and no page of a file, is made
// for a frame. child.json is a file either way: its rename ends the lab.
int output_fd = -1;

// With several labs in the child, the records go through a queue
// (output_queue.hpp); with one, each is written before the lab goes on.
OutputQueue* output_queue = nullptr;
// The records a queue holds at most: a few frames of 512 x 512.
constexpr size_t kQueued = 8 << 20;

// Where a job's wall time went, for child.json's "seconds" (course grade
// --verbose prints it per lab): the unit calls, the context and the lab's
// init, the renders, and within them the per-draw record and the usage checks.
struct Seconds {
    double units = 0.0, start = 0.0, render = 0.0, record = 0.0, usage = 0.0;
};
Seconds seconds;

using Clock = std::chrono::steady_clock;
double since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

std::string record_line(size_t size, const std::string& path) {
    return "OUTPUT " + std::to_string(size) + " " + path + "\n";
}

// A record for course: queued, or written before the lab goes on.
void send(OutputRecord record) {
    if (output_queue) return output_queue->push(std::move(record));
    send_record(output_fd, record);
}

void put_output(const std::string& path, std::string bytes) {
    if (output_fd >= 0) {
        std::string line = record_line(bytes.size(), path);
        return send({path, std::move(line), std::move(bytes), Image()});
    }
    std::ofstream out(path, std::ios::binary);
    if (!out.write(bytes.data(), static_cast<std::streamsize>(bytes.size())))
        throw Error("cannot write '" + path + "'");
}

// A frame as encode_pam writes it. Sent, its rows go from the image to the
// pipe as they are: no copy of the frame is made.
void put_pam(const std::string& path, Image image) {
    if (output_fd < 0) return put_output(path, encode_pam(image));
    const std::string header = pam_header(image);
    const size_t pixels = static_cast<size_t>(image.width) * image.height * sizeof(Rgba8);
    send({path, record_line(header.size() + pixels, path) + header, "", std::move(image)});
}

void write_json(const std::string& path, const json& value) {
    // Compact: course reads it, not a person.
    put_output(path, value.dump() + "\n");
}

void write_file(const std::string& path, const json& value) {
    std::ofstream out(path);
    if (!(out << value.dump() << "\n")) throw Error("cannot write '" + path + "'");
}

json read_job(const std::string& path) {
    std::ifstream in(path);
    if (!in) throw Error("cannot read job file '" + path + "'");
    // Parsed from memory: nlohmann's stream input reads a character at a time.
    std::ostringstream text;
    text << in.rdbuf();
    try {
        return json::parse(text.str());
    } catch (const json::parse_error& e) {
        throw Error("job file '" + path + "': " + e.what());
    }
}

// One render: the checkpoint's parameters over the defaults, then the frame.
void render_one(LabRenderer& renderer, const RegisteredLab& lab, const json& job,
                const std::string& base, gl_record::Recorder* recorder) {
    ParamValues params = default_params(lab);
    const json given = job.value("params", json::object());
    for (const auto& [key, value] : given.items()) params.set_json(key, value);
    const ReadBack read{job.value("depth", false), job.value("buffers", false)};
    // "record": what each draw was told (framework/trace/record.hpp).
    const bool record = recorder && job.value("record", false);
    if (record) recorder->begin();
    const int width = job.value("width", 512), height = job.value("height", 512);
    RenderOutput out;
    try {
        // The lab's draws and the frame's colour, as `course bless` records
        // them; the grader's own reads (depth, buffers) after the record.
        out = renderer.render(params, width, height, 0.0, ReadBack{false, false});
    } catch (...) {
        if (record) recorder->end();
        throw;
    }
    if (record) {
        const Clock::time_point start = Clock::now();
        std::string text = gl_record::record_text(recorder->end());
        seconds.record += since(start);
        put_output(base + ".record.json", std::move(text));
    }
    renderer.read_back(params, width, height, 0.0, read, out);
    // Raw pixels: course judges them and encodes only what a report shows.
    put_pam(base + ".pam", std::move(out.color));
    if (read.depth) put_output(base + ".pfm", encode_pfm(out.depth));
    if (read.buffers) put_output(base + ".buffers.json", buffers_json(out.buffers));
    write_json(base + ".stats.json", out.stats);
}

// The job's "shader_overrides" ({"NN_name/file.frag": "its text"}), in
// force while the job's programs are built: the course's file in place of
// the student's (docs/contract.md, Which file is wrong). Ended with the job.
class ShaderOverrides {
public:
    ShaderOverrides(const json& job, const std::string& path) {
        const json given = job.value("shader_overrides", json::object());
        if (!given.is_object())
            throw Error("job file '" + path + "': \"shader_overrides\" must be an object");
        std::map<std::string, std::string> texts;
        for (const auto& [file, text] : given.items()) {
            if (!text.is_string())
                throw Error("job file '" + path + "': \"shader_overrides\" of '" + file +
                            "' must be the file's text, a string");
            texts[file] = text.get<std::string>();
        }
        set_shader_overrides(std::move(texts));
    }
    ~ShaderOverrides() { set_shader_overrides({}); }
    ShaderOverrides(const ShaderOverrides&) = delete;
    ShaderOverrides& operator=(const ShaderOverrides&) = delete;
};

// The job's offscreen context and the lab's renderer in it (the renderer
// ends first); where either cannot be made, `init_error` says why.
struct Rendering {
    std::unique_ptr<OffscreenContext> context;
    std::unique_ptr<LabRenderer> renderer;
    json context_json = nullptr;
    std::string init_error;
};

Rendering start_rendering(const RegisteredLab& lab, const std::string& backend) {
    Rendering out;
    try {
        out.context =
            create_offscreen_context(backend.empty() ? backend_from_env() : parse_backend(backend));
        const ContextInfo& info = out.context->info();
        out.context_json = {{"backend", info.backend},
                            {"platform", info.platform},
                            {"gl_version", info.gl_version},
                            {"gl_renderer", info.gl_renderer}};
        out.renderer = std::make_unique<LabRenderer>(lab, info);
    } catch (const Error& e) {
        out.init_error = e.what();
    }
    return out;
}

// Each render in turn (none renders without `renderer`: `init_error` says
// why): its outputs or NAME.error.txt, and NAME.usage.json where it asks
// (framework/trace/usage.hpp).
void render_all(LabRenderer* renderer, const std::string& init_error, const RegisteredLab& lab,
                const json& renders, const std::string& out_dir, gl_record::Recorder* recorder,
                gl_usage::Checker* usage) {
    for (const json& r : renders) {
        std::string base = out_dir + "/" + r.value("name", "unnamed");
        if (usage) usage->begin_render();
        try {
            if (!renderer) throw Error(init_error);
            render_one(*renderer, lab, r, base, recorder);
        } catch (const std::exception& e) {
            put_output(base + ".error.txt", std::string(e.what()) + "\n");
        }
        // Also for a render that failed: what it did up to there.
        if (usage && r.value("usage", false))
            put_output(base + ".usage.json", gl_usage::findings_json(usage->end_render()));
    }
}

bool any_render_asks(const json& renders, const char* output) {
    for (const json& r : renders)
        if (r.value(output, false)) return true;
    return false;
}

// The observers of the lab's GL calls that its renders ask for, each passed
// every call by one Fanout from the lab's start (before its programs are
// made) to its end.
struct Observers {
    gl_calls::Fanout fanout;
    std::unique_ptr<gl_record::Recorder> recorder;
    std::unique_ptr<gl_usage::Checker> usage;

    explicit Observers(const json& renders) {
        if (any_render_asks(renders, "record")) {
            recorder = std::make_unique<gl_record::Recorder>();
            fanout.add(recorder.get(), &seconds.record);
        }
        if (any_render_asks(renders, "usage")) {
            usage = std::make_unique<gl_usage::Checker>();
            fanout.add(usage.get(), &seconds.usage);
        }
        if (!fanout.empty()) gl_calls::observe(&fanout);
    }
    ~Observers() { gl_calls::observe(nullptr); }
    Observers(const Observers&) = delete;
    Observers& operator=(const Observers&) = delete;
};

}  // namespace

namespace {

// The lab of `job` (read from `job_path`) into `out_dir`; returns the job,
// for the caller to free.
json grade_job(json job, const std::string& job_path, const std::string& out_dir,
               const std::string& backend) {
    // A frame, its readback and its file are a megabyte each, made and freed
    // for every checkpoint: keep them in the heap, not in fresh zeroed pages.
    mallopt(M_MMAP_THRESHOLD, 64 << 20);
    mallopt(M_TRIM_THRESHOLD, 256 << 20);
    seconds = Seconds();
    Clock::time_point start = Clock::now();
    const RegisteredLab& lab = find_lab(job.value("lab", ""));
    const ShaderOverrides overrides(job, job_path);

    // Unit calls first: they need no context, so a broken shader costs them nothing.
    const auto units = job.find("units");  // not copied: a lab's thousands of cases
    put_output(out_dir + "/units.json",
               units_text(lab, units != job.end() ? *units : json::array()));
    seconds.units = since(start);

    const json renders = job.value("renders", json::array());
    const Observers observers(renders);

    start = Clock::now();
    auto [context, renderer, context_json, init_error] = start_rendering(lab, backend);
    seconds.start = since(start);
    start = Clock::now();
    render_all(renderer.get(), init_error, lab, renders, out_dir, observers.recorder.get(),
               observers.usage.get());
    seconds.render = since(start);
    // Programs that failed to build: the renders that drew with them failed
    // with the compiler's message; course names the files in the lab's status.
    json shader_errors = json::array();
    if (renderer)
        for (const ShaderError* e : renderer->programs().build_errors())
            shader_errors.push_back({{"file", e->file()}, {"message", e->what()}});
    // What the lab sent and printed is in the pipes before course sees the lab done.
    if (output_queue) output_queue->drain();
    std::fflush(stdout);
    std::fflush(stderr);
    // Written whole, then renamed: course takes the name as the lab's end.
    const std::string done = out_dir + "/child.json";
    write_file(done + ".part", {{"complete", true},
                                {"context", context_json},
                                {"init_error", init_error},
                                {"shader_errors", shader_errors},
                                {"seconds",
                                 {{"units", seconds.units},
                                  {"start", seconds.start},
                                  {"render", seconds.render},
                                  {"record", seconds.record},
                                  {"usage", seconds.usage}}}});
    if (std::rename((done + ".part").c_str(), done.c_str()) != 0)
        throw Error("cannot rename '" + done + ".part' to '" + done + "'");
    return job;
}

// The byte course sends on --job-gate-fd once the job file `job` is whole.
void await_job(int fd, const std::string& job) {
    char byte = 0;
    ssize_t n;
    while ((n = read(fd, &byte, 1)) < 0 && errno == EINTR) {
    }
    if (n != 1)
        throw Error("grade-child: course sent no job '" + job +
                    "': --job-gate-fd ended before it (course stopped planning)");
}

}  // namespace

void grade_child(const std::string& job_path, const std::string& out_dir,
                 const std::string& backend) {
    grade_job(read_job(job_path), job_path, out_dir, backend);
}

void grade_children(const std::vector<std::string>& jobs, const std::vector<std::string>& outs,
                    const std::string& backend, int outputs_fd, int job_gate_fd) {
    for (const auto& [option, fd] :
         {std::pair{"--output-fd", outputs_fd}, {"--job-gate-fd", job_gate_fd}})
        if (fd >= 0 && fcntl(fd, F_GETFD) < 0)
            throw UsageError(std::string("grade-child: ") + option + " " + std::to_string(fd) +
                             " is not an open descriptor");
    output_fd = outputs_fd;
    if (jobs.size() != outs.size())
        throw UsageError("grade-child: " + std::to_string(jobs.size()) + " --job but " +
                         std::to_string(outs.size()) + " --out; give one --out per --job");
    // In turn, each in a context of its own; the first that throws ends the
    // child, and course grades it and the labs after it again.
    std::unique_ptr<OutputQueue> queue;
    if (output_fd >= 0 && jobs.size() > 1)
        queue = std::make_unique<OutputQueue>(output_fd, kQueued);
    output_queue = queue.get();
    struct Forget {
        ~Forget() { output_queue = nullptr; }  // before the queue ends, a throw too
    } forget;
    // Job i + 1 is read and parsed on a thread of its own while lab i runs
    // (a unit-heavy job is thousands of numbers), and the job of the lab
    // before freed there; a job that cannot be read throws as lab i + 1
    // begins, as it would read there.
    const auto fetch = [&](size_t i, json done) {
        return std::async(std::launch::async, [&, i, done = std::move(done)]() mutable {
            done = json();  // freed here
            if (job_gate_fd >= 0) await_job(job_gate_fd, jobs[i]);
            return read_job(jobs[i]);
        });
    };
    std::future<json> next = fetch(0, json());
    json ended;  // the job of the lab that ended last
    for (size_t i = 0; i < jobs.size(); ++i) {
        json job = next.get();
        if (i + 1 < jobs.size()) next = fetch(i + 1, std::move(ended));
        ended = grade_job(std::move(job), jobs[i], outs[i], backend);
    }
}

}  // namespace fw
