// Work spread over threads: the labs of `course grade --jobs N`, and the
// checkpoints of one lab while course judges them.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <functional>
#include <mutex>
#include <thread>
#include <vector>

namespace grading {

// Calls `fn(i)` for every i below `count` on up to `threads` threads (the
// calling one among them), each taking the next i in order; rethrows the
// first exception once all are done.
inline void parallel_for(size_t count, int threads, const std::function<void(size_t)>& fn) {
    std::atomic<size_t> next{0};
    std::mutex failure_mutex;
    std::exception_ptr failure;
    auto worker = [&] {
        for (size_t i; (i = next++) < count;) {
            try {
                fn(i);
            } catch (...) {
                std::lock_guard<std::mutex> lock(failure_mutex);
                if (!failure) failure = std::current_exception();
            }
        }
    };
    const size_t n = std::min<size_t>(static_cast<size_t>(std::max(1, threads)), count);
    std::vector<std::thread> helpers;
    for (size_t i = 1; i < n; ++i) helpers.emplace_back(worker);
    worker();
    for (std::thread& t : helpers) t.join();
    if (failure) std::rethrow_exception(failure);
}

// The CPUs this process may run on (its affinity mask, as nproc counts
// them), at least one.
unsigned affinity_cpus();

// The cores this process can keep busy: its CPUs, and fewer where its cgroup
// has a CPU quota (Gradescope's half a core, a container's --cpus), rounded
// up; at least one.
unsigned usable_cores();

// The threads that judging one lab may use while `labs_in_flight` labs (this
// one among them) are being graded: the usable cores' share per lab, at
// least one, at most 8. The last labs of a run, in flight alone, get more.
int judging_threads(int labs_in_flight);

}  // namespace grading
