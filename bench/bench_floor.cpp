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
// process, which grading never renders). Prints figures; not a test.
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
        for (const fw::RegisteredLab* lab : labs) {
            const std::vector<fw::Checkpoint> checkpoints = fw::load_checkpoints(*lab);
            double first = 0, best = 1e30;
            for (int r = 0; r < rounds; ++r) {
                const Clock::time_point t = Clock::now();
                fw::LabRenderer renderer(*lab, context->info());
                for (const fw::Checkpoint& cp : checkpoints) {
                    const auto [w, h] = frame_size(cp);
                    renderer.render(fw::checkpoint_params(*lab, cp), w, h);
                }
                const double s = seconds_since(t);
                if (r == 0) first = s;
                best = std::min(best, s);
            }
            once_total += first;
            warm_total += best;
            frames_total += static_cast<int>(checkpoints.size());
            std::printf("%-18s %8zu %10.3f %10.3f %10.2f\n", lab->info.id.c_str(),
                        checkpoints.size(), first, best,
                        1000 * best / std::max<size_t>(1, checkpoints.size()));
        }
        std::printf("%-18s %8s %10.3f %10.3f\n", "(context)", "", context_seconds, context_seconds);
        std::printf("%-18s %8d %10.3f %10.3f\n", "all labs", frames_total, once_total, warm_total);
        std::printf("floor_once_seconds %.3f\n", once_total);
        std::printf("floor_seconds %.3f\n", warm_total);
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_floor: %s\n", e.what());
        return 1;
    }
}
