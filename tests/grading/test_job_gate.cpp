// A child of several labs started before its labs are planned
// (grading/run/child.hpp: run_lab_children with a JobFeed, job_gate.hpp):
// it opens each job only once course has written it, a job file the child
// put in place first is never written through, and a feed that fails ends
// the child. The child is a shell script that speaks `lab grade-child`'s
// arguments; real processes, no GL.
#include <sys/stat.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "grading/run/child.hpp"
#include "tests/support/test_support.hpp"

namespace {

namespace fs = std::filesystem;

// A stand-in for `lab grade-child`: for each --job/--out pair, a byte from
// the gate first (when there is one), then a copy of the job (seen.json)
// and child.json, its mark, in its --out. It touches $GATE_TEST_STARTED when it begins and,
// with $GATE_TEST_PLANT, links its second job's path to that file first;
// it prints $GATE_TEST_TAIL after its last lab (once course has seen it end).
std::string script() {
    const std::string path = fw::test::out_dir() + "/gate_lab.sh";
    std::ofstream(path) << R"SH(#!/bin/sh
shift
jobs=; outs=; gate=
while [ $# -gt 0 ]; do
  case "$1" in
    --job) jobs="$jobs $2"; shift 2 ;;
    --out) outs="$outs $2"; shift 2 ;;
    --job-gate-fd) gate=$2; shift 2 ;;
    *) shift 2 ;;
  esac
done
set -- $outs
if [ -n "$GATE_TEST_PLANT" ] && [ $# -gt 1 ]; then ln -s "$GATE_TEST_PLANT" "$2/JOB.json"; fi
touch "$GATE_TEST_STARTED"
for job in $jobs; do
  out=$1; shift
  if [ -n "$gate" ]; then
    got=$(dd bs=1 count=1 <&"$gate" 2>/dev/null | wc -c)
    [ "$got" = 1 ] || { echo "no job $job"; exit 3; }
  fi
  cp "$job" "$out/seen.json"
  echo '{"complete": true}' > "$out/child.json.part" && mv "$out/child.json.part" "$out/child.json"
done
if [ -n "$GATE_TEST_TAIL" ]; then sleep 0.5; echo "$GATE_TEST_TAIL"; fi
)SH";
    chmod(path.c_str(), 0755);
    return path;
}

// Waits (at most 20 s) until `path` exists: true when it does.
bool appears(const std::string& path) {
    for (int i = 0; i < 2000; ++i) {
        if (fs::exists(fs::symlink_status(path))) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return false;
}

struct Graded {
    std::map<size_t, grading::LabChild> labs;  // the last result for each index
    int calls = 0;
};

Graded run(const grading::JobFeed& feed, size_t count) {
    std::vector<std::string> ids;
    for (size_t i = 0; i < count; ++i) ids.push_back("lab" + std::to_string(i));
    grading::ChildLimits limits;
    limits.timeout_seconds = 30;
    Graded graded;
    grading::run_lab_children(script(), ids, feed, "", limits, nullptr, {},
                              [&](size_t i, grading::LabChild&& child) {
                                  ++graded.calls;
                                  graded.labs[i] = std::move(child);
                              });
    return graded;
}

std::string job_text(size_t i) { return "{\"lab\":\"lab" + std::to_string(i) + "\"}"; }

// The job lab i's child read (the child of several labs' DIR/i, or the
// work directory of a lab graded alone).
std::string seen(const grading::LabChild& child, size_t i) {
    std::string path = child.dir->path() + "/" + std::to_string(i) + "/seen.json";
    if (!fs::exists(path)) path = child.dir->path() + "/seen.json";
    std::ifstream in(path);
    std::string line;
    std::getline(in, line);
    return line;
}

// Every one of `count` labs ended normally, having read its own job.
void each_read_its_job(const Graded& graded, size_t count) {
    REQUIRE(graded.labs.size() == count);
    for (size_t i = 0; i < count; ++i) {
        INFO("lab " << i << ": " << graded.labs.at(i).run.log);
        CHECK(graded.labs.at(i).run.ok());
        CHECK(seen(graded.labs.at(i), i) == job_text(i));
    }
}

struct Env {
    Env(const char* name, const std::string& value) : name_(name) {
        setenv(name, value.c_str(), 1);
    }
    ~Env() { unsetenv(name_); }
    const char* name_;
};

}  // namespace

TEST_CASE("job gate: the child starts before its jobs and reads each once it is written") {
    const std::string started = fw::test::out_dir() + "/gate_started_1";
    fs::remove(started);
    const Env env("GATE_TEST_STARTED", started);
    bool waited = false;
    // Given only once the child runs, last job first: the child must wait
    // at each job until it and those before it are written.
    const Graded graded = run(
        [&](const grading::JobGive& give) {
            waited = appears(started);
            for (size_t i = 3; i-- > 0;) {
                std::this_thread::sleep_for(std::chrono::milliseconds(30));
                give(i, job_text(i));
            }
        },
        3);
    CHECK(waited);
    CHECK(graded.calls == 3);
    each_read_its_job(graded, 3);
}

TEST_CASE("job gate: a job file the child put there first is never written through") {
    const std::string started = fw::test::out_dir() + "/gate_started_2";
    const std::string victim = fw::test::out_dir() + "/gate_victim.txt";
    fs::remove(started);
    std::ofstream(victim) << "course's own file\n";
    const Env env_started("GATE_TEST_STARTED", started);
    const Env env_plant("GATE_TEST_PLANT", victim);
    bool planted = false;
    const Graded graded = run(
        [&](const grading::JobGive& give) {
            planted = appears(started);  // the link is in place
            for (size_t i = 0; i < 3; ++i) give(i, job_text(i));
        },
        3);
    CHECK(planted);
    std::ifstream in(victim);
    std::stringstream text;
    text << in.rdbuf();
    CHECK(text.str() == "course's own file\n");
    // Lab 0 ran in the child; lab 1 found no job there and was graded again
    // alone (with its job), and lab 2 in a child of its own after it.
    each_read_its_job(graded, 3);
}

TEST_CASE("job gate: a feed that fails ends the child, and its error is thrown") {
    const std::string started = fw::test::out_dir() + "/gate_started_3";
    fs::remove(started);
    const Env env("GATE_TEST_STARTED", started);
    const auto begin = std::chrono::steady_clock::now();
    CHECK_THROWS_WITH(run(
                          [&](const grading::JobGive& give) {
                              give(0, job_text(0));
                              throw std::runtime_error("planning failed");
                          },
                          3),
                      "planning failed");
    // Not the 30 s timeout: the child read the gate's end and stopped.
    CHECK(std::chrono::steady_clock::now() - begin < std::chrono::seconds(20));
}

TEST_CASE("job gate: what the child prints after its last lab joins that lab's log") {
    const std::string started = fw::test::out_dir() + "/gate_started_4";
    fs::remove(started);
    const Env env_started("GATE_TEST_STARTED", started);
    const Env env_tail("GATE_TEST_TAIL", "the child's last words");
    const Graded graded = run(
        [&](const grading::JobGive& give) {
            for (size_t i = 0; i < 3; ++i) give(i, job_text(i));
        },
        3);
    // The last lab twice: as it ended, and again with the words, on the
    // same outputs.
    CHECK(graded.calls == 4);
    REQUIRE(graded.labs.size() == 3);
    const grading::LabChild& last = graded.labs.at(2);
    CHECK(last.run.ok());
    CHECK(last.run.log.find("course: after the last lab of a child that graded lab0, lab1, "
                            "lab2 in turn:\nthe child's last words") != std::string::npos);
    CHECK(seen(last, 2) == job_text(2));
    REQUIRE(last.outputs);
    std::string bytes, why;
    CHECK(last.outputs->read("seen.json", 1024, bytes, why));
    CHECK(bytes == job_text(2) + "\n");
    CHECK(graded.labs.at(1).run.log.find("last words") == std::string::npos);
}
