#include "framework/runner/output_queue.hpp"

#include <limits.h>
#include <sys/uio.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <vector>

#include "framework/error.hpp"

namespace fw {

namespace {

size_t record_bytes(const OutputRecord& r) {
    return r.head.size() + r.body.size() + r.rows.pixels.size() * sizeof(Rgba8);
}

}  // namespace

void send_record(int fd, OutputRecord& record) {
    std::vector<iovec> parts = {{record.head.data(), record.head.size()}};
    if (!record.body.empty()) parts.push_back({record.body.data(), record.body.size()});
    const size_t row = static_cast<size_t>(record.rows.width) * sizeof(Rgba8);
    for (int y = record.rows.height - 1; y >= 0; --y)  // bottom-first storage, top row first
        parts.push_back({&record.rows.at(0, y), row});
    size_t first = 0;
    while (first < parts.size()) {
        const int count = static_cast<int>(std::min<size_t>(parts.size() - first, IOV_MAX));
        const ssize_t n = ::writev(fd, &parts[first], count);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0)
            throw Error("cannot send '" + record.path + "' to course on descriptor " +
                        std::to_string(fd) + ": " + std::strerror(errno));
        size_t done = static_cast<size_t>(n);
        while (first < parts.size() && done >= parts[first].iov_len) done -= parts[first++].iov_len;
        if (done > 0) {
            parts[first].iov_base = static_cast<char*>(parts[first].iov_base) + done;
            parts[first].iov_len -= done;
        }
    }
}

OutputQueue::OutputQueue(int fd, size_t max_bytes)
    : fd_(fd), max_bytes_(max_bytes), writer_([this] { run(); }) {}

OutputQueue::~OutputQueue() {
    {
        const std::lock_guard<std::mutex> lock(mutex_);
        stopping_ = true;
    }
    changed_.notify_all();
    writer_.join();
}

void OutputQueue::throw_if_failed() const {
    if (!error_.empty()) throw Error(error_);
}

void OutputQueue::push(OutputRecord record) {
    const size_t bytes = record_bytes(record);
    std::unique_lock<std::mutex> lock(mutex_);
    // One record larger than the room is let in alone.
    changed_.wait(lock, [&] {
        return !error_.empty() || queued_bytes_ == 0 || queued_bytes_ + bytes <= max_bytes_;
    });
    throw_if_failed();
    queued_bytes_ += bytes;
    queue_.push_back(std::move(record));
    lock.unlock();
    changed_.notify_all();
}

void OutputQueue::drain() {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return !error_.empty() || (queue_.empty() && !writing_); });
    throw_if_failed();
}

void OutputQueue::run() {
    std::unique_lock<std::mutex> lock(mutex_);
    for (;;) {
        changed_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
        if (queue_.empty()) return;  // stopping, and all written
        OutputRecord record = std::move(queue_.front());
        queue_.pop_front();
        writing_ = true;
        lock.unlock();
        std::string error;
        try {
            send_record(fd_, record);
        } catch (const Error& e) {
            error = e.what();
        }
        const size_t bytes = record_bytes(record);
        record = OutputRecord();  // freed outside the lock
        lock.lock();
        writing_ = false;
        queued_bytes_ -= bytes;
        if (!error.empty() && error_.empty()) error_ = error;
        if (!error_.empty()) {
            queue_.clear();  // nothing after a failed write is sent
            queued_bytes_ = 0;
        }
        changed_.notify_all();
    }
}

}  // namespace fw
