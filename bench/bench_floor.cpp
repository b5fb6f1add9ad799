// bench_floor: the renderer's own cost of grading. Every checkpoint of every
// lab (the same scenes at the same sizes as `course grade` renders) drawn and
// read back (colour and depth) in one process and one context, with nothing
// encoded or written: what grading would cost if handing frames to course
// and judging them were free. bench/bench_grade.sh prints grading time as a
// ratio of this floor. Per lab: building its programs (Mesa's shader cache
// as it is) and rendering its frames, ROUNDS times in a row. Two floors:
// the first round of each lab ("once": every frame rendered once in one
// process, the labs in order, as a grading child renders them, so what the
// process builds on first use is paid once), and the best round ("warm":
// the lab's second and later builds of the same programs in the same
// process, which grading never renders). Then where the best round's time
// goes, per lab: its set-up (the LabRenderer: the lab's init and programs),
// then in milliseconds a frame the frame drawn and finished (its stats'
// render_ms: the clear, the lab's draw and glFinish), of which the GPU's part
// (gpu_ms, the timer query), the queries' results and the stats after it, and
// the colour and the depth read back. Prints figures; not a test.
//
//   bench_floor [ROUNDS=3] [LAB...]     (backend: $LAB_BACKEND, else auto)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "framework/checkpoints.hpp"
#include "framework/context.hpp"
#include "framework/error.hpp"
#include "framework/gl/framebuffer.hpp"
#include "framework/lab.hpp"
#include "framework/render.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

// The frame size course renders a checkpoint at: a check's "size", else 512 x 512.
std::pair<int, int> frame_size(const fw::Checkpoint& cp) {
    for (const nlohmann::json& check : cp.checks)
        if (check.is_object() && check.contains("size") && check["size"].is_array() &&
            check["size"].size() == 2)
            return {check["size"][0].get<int>(), check["size"][1].get<int>()};
    return {512, 512};
}

// Milliseconds spent in each part of a lab's frames, summed over a round.
struct Phases {
    double setup = 0, frame = 0, gpu = 0, after = 0, color = 0, depth = 0;
};

// One frame as LabRenderer::render draws and reads it (colour and depth),
// each part timed into `p`.
void timed_frame(fw::LabRenderer& renderer, const fw::ParamValues& params, int w, int h,
                 Phases& p) {
    Clock::time_point t = Clock::now();
    const fw::FrameResult drawn = renderer.draw(params, w, h);
    const double draw_ms = 1000 * seconds_since(t);
    const double frame_ms = drawn.stats.value("render_ms", 0.0);
    p.frame += frame_ms;
    p.gpu += drawn.stats.value("gpu_ms", 0.0);
    p.after += draw_ms - frame_ms;
    t = Clock::now();
    const fw::Image color = renderer.framebuffer()->read_color();
    p.color += 1000 * seconds_since(t);
    t = Clock::now();
    const fw::DepthImage depth = renderer.framebuffer()->read_depth();
    p.depth += 1000 * seconds_since(t);
}

// A lab's ROUNDS rounds: the first's seconds, the best's, and the best's parts.
struct LabFloor {
    size_t frames = 0;
    double first = 0, best = 1e30;
    Phases phases;
};

LabFloor measure_lab(const fw::RegisteredLab& lab, const fw::ContextInfo& info, int rounds) {
    const std::vector<fw::Checkpoint> checkpoints = fw::load_checkpoints(lab);
    LabFloor f;
    f.frames = checkpoints.size();
    for (int r = 0; r < rounds; ++r) {
        const Clock::time_point t = Clock::now();
        Phases phases;
        fw::LabRenderer renderer(lab, info);
        phases.setup = 1000 * seconds_since(t);
        for (const fw::Checkpoint& cp : checkpoints) {
            const auto [w, h] = frame_size(cp);
            timed_frame(renderer, fw::checkpoint_params(lab, cp), w, h, phases);
        }
        const double s = seconds_since(t);
        if (r == 0) f.first = s;
        if (s < f.best) f.phases = phases;
        f.best = std::min(f.best, s);
    }
    return f;
}

void print_phases(const std::vector<std::pair<std::string, LabFloor>>& floors) {
    std::printf(
        "\nwhere the best round's time goes: the lab's set-up (LabRenderer: its init and\n"
        "programs), then ms per frame:\n");
    std::printf("%-18s %8s | %8s %8s %8s %8s %8s\n", "lab", "setup ms", "frame", "gpu", "after",
                "colour", "depth");
    for (const auto& [id, f] : floors) {
        const double n = static_cast<double>(std::max<size_t>(1, f.frames));
        const Phases& p = f.phases;
        std::printf("%-18s %8.2f | %8.2f %8.2f %8.2f %8.2f %8.2f\n", id.c_str(), p.setup,
                    p.frame / n, p.gpu / n, p.after / n, p.color / n, p.depth / n);
    }
}

}  // namespace

int main(int argc, char** argv) {
    try {
        const int rounds = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
        std::vector<const fw::RegisteredLab*> labs;
        for (int i = 2; i < argc; ++i) labs.push_back(&fw::find_lab(argv[i]));
        if (labs.empty())
            for (const fw::RegisteredLab& lab : fw::registered_labs()) labs.push_back(&lab);

        const Clock::time_point start = Clock::now();
        auto context = fw::create_offscreen_context(fw::backend_from_env());
        const double context_seconds = seconds_since(start);
        std::printf("bench_floor: %s, %s; best of %d rounds\n", context->info().backend.c_str(),
                    context->info().gl_renderer.c_str(), rounds);
        std::printf("%-18s %8s %10s %10s %10s\n", "lab", "frames", "once (s)", "warm (s)",
                    "warm ms/frame");
        double once_total = context_seconds, warm_total = context_seconds;
        int frames_total = 0;
        std::vector<std::pair<std::string, LabFloor>> floors;
        for (const fw::RegisteredLab* lab : labs) {
            const LabFloor f = measure_lab(*lab, context->info(), rounds);
            once_total += f.first;
            warm_total += f.best;
            frames_total += static_cast<int>(f.frames);
            std::printf("%-18s %8zu %10.3f %10.3f %10.2f\n", lab->info.id.c_str(), f.frames,
                        f.first, f.best,
                        1000 * f.best / static_cast<double>(std::max<size_t>(1, f.frames)));
            floors.emplace_back(lab->info.id, f);
        }
        std::printf("%-18s %8s %10.3f %10.3f\n", "(context)", "", context_seconds, context_seconds);
        std::printf("%-18s %8d %10.3f %10.3f\n", "all labs", frames_total, once_total, warm_total);
        std::printf("floor_once_seconds %.3f\n", once_total);
        std::printf("floor_seconds %.3f\n", warm_total);
        print_phases(floors);
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_floor: %s\n", e.what());
        return 1;
    }
}
