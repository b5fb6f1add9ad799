// The jobs of a child started before they are planned (run_lab_children):
// course writes each lab's JOB.json as its plan is made and then sends the
// child one byte on the gate, which `lab grade-child --job-gate-fd` reads
// before it opens that job (docs/contract.md, `course grade`).
#pragma once

#include <sys/types.h>

#include <mutex>
#include <string>
#include <vector>

#include "grading/sandbox/limits.hpp"

namespace grading {

// The gate's descriptor in the child.
constexpr int kJobGateFd = 4;

class JobGate {
public:
    // Lab i's job goes into lab_dirs[i] (course's directories, not yet
    // handed over: each is opened here, so that a job is written into that
    // directory whatever is later put at its path); the files are given to
    // `user` when there is one.
    JobGate(const std::vector<std::string>& lab_dirs, const RunAsUser* user);
    ~JobGate();
    JobGate(const JobGate&) = delete;
    JobGate& operator=(const JobGate&) = delete;

    // The child's end, for run_child (close-on-exec here).
    int child_end() const { return fds_[1]; }
    // Job i's text, from any thread: written, with the jobs before it, and
    // the child let through, as soon as each job before it is given too. A
    // job that cannot be written (something of the child's is at its path)
    // ends the gate there: the child stops at that lab.
    void give(size_t i, std::string text);
    // No more jobs: the child reads the end of the gate after the last one
    // written.
    void end();
    // What a thread that calls this after give(i) returned sees of what the
    // giver made before give(i).
    void sync();
    // Every job given, by index (empty for one never given).
    std::vector<std::string> texts();

private:
    bool write_job(size_t i);
    void close_all();
    std::mutex mutex_;
    std::vector<int> dirs_;
    std::vector<std::string> texts_;
    std::vector<char> given_;
    size_t next_ = 0;
    int fds_[2] = {-1, -1};  // course's end, the child's
    const RunAsUser* user_;
    bool ended_ = false;
};

}  // namespace grading
