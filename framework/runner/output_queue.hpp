// The records a grading child sends course on its output descriptor
// (grade_child.hpp, --output-fd), written in order by a thread of their own
// while the lab draws its next frame. A pipe holds 1 MiB, about one frame:
// written from the drawing thread, each frame waited for course to take the
// one before it: 0.30 to 0.33 s of an all-labs run of 1.2 to 1.3 s, all
// but a tenth of a second of it waiting.
//
// A child of several labs queues its records; course takes a lab's outputs
// only once its child.json appears, and drain() returns only when every
// record pushed before it is in the pipe. A lab that does not get that far
// (a crash, a timeout) is graded again alone, and a child of one lab writes
// each record before it goes on: what course receives from a lab never
// depends on how far a queue had got.
#pragma once

#include <condition_variable>
#include <cstddef>
#include <deque>
#include <mutex>
#include <string>
#include <thread>

#include "framework/image.hpp"

namespace fw {

// One record: `head` (its "OUTPUT SIZE PATH" line and any header of its
// own) and then `body`, or `rows`' rows top first (a PAM's pixels, sent
// from the image as they are).
struct OutputRecord {
    std::string path;
    std::string head;
    std::string body;
    Image rows;
};

// Writes `record` to `fd` whole, whatever share of it each writev takes;
// throws fw::Error naming its path when the descriptor fails.
void send_record(int fd, OutputRecord& record);

class OutputQueue {
public:
    // At most `max_bytes` of records waiting; push() waits for room.
    OutputQueue(int fd, size_t max_bytes);
    // Writes what is queued, then ends the thread; an error is dropped.
    ~OutputQueue();
    OutputQueue(const OutputQueue&) = delete;
    OutputQueue& operator=(const OutputQueue&) = delete;

    // Queues `record`; throws the writer's fw::Error if a write failed.
    void push(OutputRecord record);
    // Returns when every record pushed so far is written; throws the
    // writer's fw::Error if a write failed.
    void drain();

private:
    void run();
    void throw_if_failed() const;  // with mutex_ held

    int fd_;
    size_t max_bytes_;
    std::mutex mutex_;
    std::condition_variable changed_;
    std::deque<OutputRecord> queue_;
    size_t queued_bytes_ = 0;
    bool writing_ = false, stopping_ = false;
    std::string error_;
    std::thread writer_;
};

}  // namespace fw
