// bench_context: how long creating and destroying an offscreen context takes
// on each backend this build has (it is paid once per `lab render` and per
// graded lab). Prints figures; it is not a test.
//
//   bench_context [N]     N create/destroy cycles per backend (default 5)
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "framework/context.hpp"
#include "framework/error.hpp"

namespace {

struct Result {
    std::vector<double> ms;
    std::string renderer;
    std::string error;  // non-empty: the backend is unavailable
};

Result time_backend(fw::Backend backend, int runs) {
    Result r;
    std::string why;
    if (!fw::backend_compiled_in(backend, &why)) {
        r.error = why;
        return r;
    }
    for (int i = 0; i < runs; ++i) {
        const auto start = std::chrono::steady_clock::now();
        try {
            auto context = fw::create_offscreen_context(backend);
            if (r.renderer.empty()) r.renderer = context->info().gl_renderer;
        } catch (const fw::Error& e) {
            r.error = e.what();
            return r;
        }
        const auto end = std::chrono::steady_clock::now();
        r.ms.push_back(std::chrono::duration<double, std::milli>(end - start).count());
    }
    return r;
}

}  // namespace

int main(int argc, char** argv) {
    int runs = 5;
    if (argc > 1) {
        runs = std::atoi(argv[1]);
        if (runs < 1) {
            std::fprintf(stderr, "bench_context: N must be a positive integer, got '%s'\n",
                         argv[1]);
            return 2;
        }
    }
    std::printf("create + destroy an offscreen GL 4.3 core context, %d runs per backend\n", runs);
    for (fw::Backend backend : {fw::Backend::EGL, fw::Backend::OSMesa}) {
        Result r = time_backend(backend, runs);
        const char* name = fw::backend_name(backend);
        if (!r.error.empty()) {
            std::printf("%s: unavailable: %s\n", name, r.error.c_str());
            continue;
        }
        // The first run also loads the driver; min shows the steady state.
        std::vector<double> sorted = r.ms;
        std::sort(sorted.begin(), sorted.end());
        const size_t n = sorted.size();
        const double median = n % 2 ? sorted[n / 2] : (sorted[n / 2 - 1] + sorted[n / 2]) / 2;
        std::printf("%-7s median %8.2f ms  min %8.2f ms  first %8.2f ms  (%s)\n",
                    (std::string(name) + ":").c_str(), median, sorted.front(), r.ms.front(),
                    r.renderer.c_str());
    }
    return 0;
}
