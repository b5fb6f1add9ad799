// fw::OutputQueue (framework/runner/output_queue.hpp): a grading child's
// records written by a thread of their own. Every byte arrives, in the
// order pushed; drain() returns only once all of it is in the descriptor;
// a failed write is reported, not lost. No GL.
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <string>
#include <thread>
#include <vector>

#include "framework/error.hpp"
#include "framework/runner/output_queue.hpp"
#include "tests/support/test_support.hpp"

namespace {

struct Pipe {
    int read = -1, write = -1;
    Pipe() {
        int fds[2];
        REQUIRE(pipe(fds) == 0);
        read = fds[0];
        write = fds[1];
    }
    ~Pipe() {
        if (read >= 0) close(read);
        if (write >= 0) close(write);
    }
    // Everything in the pipe now, without waiting for more.
    std::string read_available() const {
        const int flags = fcntl(read, F_GETFL);
        fcntl(read, F_SETFL, flags | O_NONBLOCK);
        std::string got;
        char buf[65536];
        ssize_t n;
        while ((n = ::read(read, buf, sizeof buf)) > 0) got.append(buf, static_cast<size_t>(n));
        fcntl(read, F_SETFL, flags);
        return got;
    }
};

// Record i: a body, or an image of `side` x `side` whose every pixel names
// its row and the record, so that a row out of place or a record out of
// order shows in the bytes.
fw::OutputRecord record(int i, int side) {
    fw::OutputRecord r;
    r.path = "out/" + std::to_string(i);
    r.head = "OUTPUT record " + std::to_string(i) + "\n";
    if (i % 3 == 0) {
        r.body.assign(static_cast<size_t>(side) * 7 + 1, static_cast<char>('a' + i % 26));
    } else {
        r.rows = fw::Image(side, side);
        for (int y = 0; y < side; ++y)
            for (int x = 0; x < side; ++x)
                r.rows.at(x, y) = {static_cast<std::uint8_t>(y), static_cast<std::uint8_t>(i),
                                   static_cast<std::uint8_t>(x), 255};
    }
    return r;
}

// What record i is on the wire, worked out apart from the queue: the head,
// then the body, or the image's rows top row first.
std::string wire(int i, int side) {
    const fw::OutputRecord r = record(i, side);
    std::string bytes = r.head + r.body;
    for (int y = r.rows.height - 1; y >= 0; --y)
        for (int x = 0; x < r.rows.width; ++x) {
            const fw::Rgba8 p = r.rows.at(x, y);
            bytes += {static_cast<char>(p.r), static_cast<char>(p.g), static_cast<char>(p.b),
                      static_cast<char>(p.a)};
        }
    return bytes;
}

}  // namespace

TEST_CASE("output queue: every record whole and in order, past a full queue and a full pipe") {
    Pipe p;
    std::string got;
    std::thread reader([&] {
        char buf[4096];
        ssize_t n;
        while ((n = ::read(p.read, buf, sizeof buf)) > 0) got.append(buf, static_cast<size_t>(n));
    });
    std::string expected;
    {
        // Room for about two records; some records larger than the room.
        fw::OutputQueue queue(p.write, 64 * 1024);
        for (int i = 0; i < 60; ++i) {
            const int side = 40 + (i * 37) % 200;
            queue.push(record(i, side));
            expected += wire(i, side);
        }
        queue.drain();
    }
    close(p.write);
    p.write = -1;
    reader.join();
    CHECK(got.size() == expected.size());
    CHECK(got == expected);
}

TEST_CASE("output queue: drain() returns with every record in the pipe") {
    Pipe p;
    REQUIRE(fcntl(p.write, F_SETPIPE_SZ, 1 << 20) >= (1 << 20));
    fw::OutputQueue queue(p.write, 1 << 20);
    std::string expected;
    for (int i = 0; i < 12; ++i) {
        queue.push(record(i, 100));
        expected += wire(i, 100);
    }
    REQUIRE(expected.size() < (1u << 20));  // all of it fits in the pipe
    queue.drain();
    CHECK(p.read_available() == expected);  // nothing read before: nothing still on its way
}

TEST_CASE("output queue: what is pushed and not drained is written when the queue ends") {
    Pipe p;
    REQUIRE(fcntl(p.write, F_SETPIPE_SZ, 1 << 20) >= (1 << 20));
    std::string expected;
    {
        fw::OutputQueue queue(p.write, 1 << 20);
        for (int i = 0; i < 5; ++i) {
            queue.push(record(i, 64));
            expected += wire(i, 64);
        }
    }
    CHECK(p.read_available() == expected);
}

TEST_CASE("output queue: a failed write is reported by drain() and every push after it") {
    signal(SIGPIPE, SIG_IGN);  // a write to a pipe nobody reads: EPIPE, not a signal
    Pipe p;
    close(p.read);
    p.read = -1;
    fw::OutputQueue queue(p.write, 1 << 20);
    queue.push(record(1, 32));
    try {
        queue.drain();
        FAIL("drain() returned after a failed write");
    } catch (const fw::Error& e) {
        CHECK(std::string(e.what()).find("cannot send 'out/1' to course") != std::string::npos);
    }
    CHECK_THROWS_AS(queue.push(record(2, 32)), fw::Error);
    CHECK_THROWS_AS(queue.drain(), fw::Error);
}

TEST_CASE("output queue: drain() waits for a record the pipe has taken only part of") {
    Pipe p;
    fw::OutputQueue queue(p.write, 1 << 20);
    // 256 KiB of pixels: more than a pipe holds, so its write waits for a reader.
    queue.push(record(1, 256));
    // Its first bytes in the pipe: the queue's thread has taken it and is writing it.
    pollfd ready = {p.read, POLLIN, 0};
    REQUIRE(poll(&ready, 1, 10000) == 1);
    std::atomic<bool> drained{false};
    std::thread drainer([&] {
        queue.drain();
        drained = true;
    });
    std::this_thread::sleep_for(std::chrono::milliseconds(200));
    CHECK_FALSE(drained.load());  // nothing has read the rest: it cannot all be written
    std::string got;
    while (got.size() < wire(1, 256).size()) {
        char buf[65536];
        const ssize_t n = ::read(p.read, buf, sizeof buf);
        REQUIRE(n > 0);
        got.append(buf, static_cast<size_t>(n));
    }
    drainer.join();
    CHECK(drained.load());
    CHECK(got == wire(1, 256));
}
