// Lab children run side by side (grading/run/child.hpp, sandbox.hpp), as under
// `course grade --jobs 2`: after each child, run_child() kills whatever no
// running lab started; a child that another thread is starting at that
// moment is a running lab, never a stray. Real processes, no GL.
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <map>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "grading/run/child.hpp"
#include "grading/sandbox/sandbox.hpp"
#include "tests/support/test_support.hpp"

namespace {

namespace fs = std::filesystem;

// The children's work directory (run_child sizes it while they run): empty.
std::string work_dir() {
    const std::string dir = fw::test::out_dir() + "/children-work";
    fs::create_directories(dir);
    return dir;
}

// Runs `count` children of `argv` in each of `threads` threads at once, and
// counts every status but "ok" (with one log for the report).
std::map<std::string, int> run_side_by_side(const std::vector<std::string>& argv, int threads,
                                            int count, std::string& a_log) {
    const std::string dir = work_dir();
    std::map<std::string, int> statuses;
    std::mutex mutex;
    std::vector<std::thread> workers;
    for (int t = 0; t < threads; ++t)
        workers.emplace_back([&] {
            for (int i = 0; i < count; ++i) {
                grading::ChildLimits limits;
                limits.timeout_seconds = 30;
                const grading::ChildRun run = grading::run_child(argv, dir, limits, nullptr);
                if (run.ok()) continue;
                std::lock_guard<std::mutex> lock(mutex);
                ++statuses[run.status.text()];
                a_log = run.log;
            }
        });
    for (std::thread& w : workers) w.join();
    return statuses;
}

}  // namespace

TEST_CASE("children: a child started while another thread seeks strays is not one") {
    REQUIRE(grading::become_subreaper());
    // Short children, so that one thread's start falls again and again into
    // the other's search for strays (it reads every process in /proc).
    std::string log;
    const std::map<std::string, int> failed =
        run_side_by_side({"/bin/sh", "-c", "exit 0"}, 2, 300, log);
    for (const auto& [status, n] : failed) MESSAGE(n << " children ended: " << status);
    if (!failed.empty()) MESSAGE("one of their logs:\n" << log);
    CHECK(failed.empty());
}

TEST_CASE("children: what a child leaves running is still killed when it ends") {
    REQUIRE(grading::become_subreaper());
    // A daemon (setsid, its parent gone): course adopts it and kills it.
    const std::string mark = fw::test::out_dir() + "/children-daemon";
    std::remove(mark.c_str());
    grading::ChildLimits limits;
    limits.timeout_seconds = 30;
    const grading::ChildRun run = grading::run_child(
        {"/bin/sh", "-c", "setsid sh -c 'sleep 1; touch " + mark + "' >/dev/null 2>&1 &"},
        work_dir(), limits, nullptr);
    CHECK(run.ok());
    CHECK(run.log.find("process(es) the lab left running") != std::string::npos);
    MESSAGE(run.log);
    std::this_thread::sleep_for(std::chrono::milliseconds(1500));
    CHECK(access(mark.c_str(), F_OK) != 0);
}
