// Work spread over threads: the labs of `course grade --jobs N`, the
// checkpoints of one lab while course judges them, and a lab's judging while
// its child goes on with the next.
#pragma once

#include <algorithm>
#include <atomic>
#include <condition_variable>
#include <cstddef>
#include <deque>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <thread>
#include <utility>
#include <vector>

namespace grading {

// Calls `fn(i)` for every i below `count` on up to `threads` threads (the
// calling one among them), each taking the next i in order; once all are
// done, rethrows the exception of the lowest i that threw: the same one on
// every run, whichever thread failed first.
inline void parallel_for(size_t count, int threads, const std::function<void(size_t)>& fn) {
    std::atomic<size_t> next{0};
    std::mutex failure_mutex;
    std::exception_ptr failure;
    size_t failed_at = count;
    auto worker = [&] {
        for (size_t i; (i = next++) < count;) {
            try {
                fn(i);
            } catch (...) {
                std::lock_guard<std::mutex> lock(failure_mutex);
                if (i < failed_at) {
                    failure = std::current_exception();
                    failed_at = i;
                }
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

// A thread of its own that calls `fn` on each item given to push(), in that
// order, while the thread that pushes goes on: a lab's judging while its
// child renders the next lab. finish() waits until every item is done and
// rethrows the first exception `fn` threw; the destructor waits too.
template <class Item>
class Pipeline {
public:
    explicit Pipeline(std::function<void(Item&)> fn)
        : fn_(std::move(fn)), thread_([this] { run(); }) {}
    ~Pipeline() { stop(); }
    Pipeline(const Pipeline&) = delete;
    Pipeline& operator=(const Pipeline&) = delete;

    void push(Item item) {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            items_.push_back(std::move(item));
        }
        wake_.notify_one();
    }
    void finish() {
        stop();
        if (failure_) std::rethrow_exception(failure_);
    }

private:
    void stop() {
        {
            std::lock_guard<std::mutex> lock(mutex_);
            done_ = true;
        }
        wake_.notify_one();
        if (thread_.joinable()) thread_.join();
    }
    void run() {
        for (;;) {
            std::unique_lock<std::mutex> lock(mutex_);
            wake_.wait(lock, [this] { return done_ || !items_.empty(); });
            if (items_.empty()) return;
            Item item = std::move(items_.front());
            items_.pop_front();
            lock.unlock();
            try {
                if (!failure_) fn_(item);
            } catch (...) {
                failure_ = std::current_exception();
            }
        }
    }

    std::function<void(Item&)> fn_;
    std::mutex mutex_;
    std::condition_variable wake_;
    std::deque<Item> items_;
    bool done_ = false;
    std::exception_ptr failure_;  // written by the thread, read after join
    std::thread thread_;          // last: started once the rest is ready
};

// What is no longer needed but takes time to free (a run's plans: thousands
// of unit cases), freed each on a thread of its own while the caller goes
// on; the destructor waits for every one.
class FreeLater {
public:
    template <class T>
    void free(T garbage) {
        auto held = std::make_shared<T>(std::move(garbage));
        std::lock_guard<std::mutex> lock(mutex_);
        freeing_.push_back(std::thread([held] { *held = T(); }));
    }
    ~FreeLater() {
        for (std::thread& t : freeing_) t.join();
    }

private:
    std::mutex mutex_;
    std::vector<std::thread> freeing_;
};

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
