// Lab children run side by side (grading/run/child.hpp, sandbox.hpp), as under
// `course grade --jobs 2`: after each child, run_child() kills whatever no
// running lab started; a child that another thread is starting at that
// moment is a running lab, never a stray. Real processes, no GL.
#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
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
    // A daemon (setsid, its parent gone): course adopts it and kills it. The
    // child ends only once the daemon is one (in a session of its own), since
    // what is still in the child's process group when it ends dies with it,
    // uncounted (killpg), and would leave nothing for course to find.
    const std::string mark = fw::test::out_dir() + "/children-daemon",
                      ready = fw::test::out_dir() + "/children-daemon-ready";
    std::remove(mark.c_str());
    std::remove(ready.c_str());
    grading::ChildLimits limits;
    limits.timeout_seconds = 30;
    const grading::ChildRun run = grading::run_child(
        {"/bin/sh", "-c",
         "setsid sh -c 'touch " + ready + "; sleep 1; touch " + mark +
             "' >/dev/null 2>&1 & while [ ! -e " + ready + " ]; do sleep 0.01; done"},
        work_dir(), limits, nullptr);
    CHECK(run.ok());
    CHECK(run.log.find("process(es) the lab left running") != std::string::npos);
    MESSAGE(run.log);
    std::this_thread::sleep_for(std::chrono::milliseconds(1500));
    CHECK(access(mark.c_str(), F_OK) != 0);
}

namespace {

// The state letter of /proc/PID/status ('Z': a zombie), '?' when it is gone.
char process_state(pid_t pid) {
    std::ifstream status("/proc/" + std::to_string(pid) + "/status");
    for (std::string line; std::getline(status, line);)
        if (line.rfind("State:", 0) == 0) {
            const size_t at = line.find_first_not_of(" \t", 6);
            return at == std::string::npos ? '?' : line[at];
        }
    return '?';
}

// Waits (up to 5 s) until `pid` is in state `state`.
bool becomes(pid_t pid, char state) {
    for (int i = 0; i < 500; ++i) {
        if (process_state(pid) == state) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return false;
}

// A process that ends at once as `uid`, and `parent`, which never reaps it.
struct Unreaped {
    pid_t parent = -1, zombie = -1;
    int release[2] = {-1, -1};
};

Unreaped unreaped_zombie(uid_t uid) {
    Unreaped u;
    int ids[2];
    REQUIRE(pipe(u.release) == 0);
    REQUIRE(pipe(ids) == 0);
    u.parent = fork();
    REQUIRE(u.parent >= 0);
    if (u.parent == 0) {
        close(u.release[1]);
        const pid_t child = fork();
        if (child == 0) _exit(setuid(uid) == 0 ? 0 : 1);
        (void)!write(ids[1], &child, sizeof child);
        char byte;
        (void)!read(u.release[0], &byte, 1);  // until the test lets go; no wait()
        _exit(0);
    }
    close(u.release[0]);
    close(ids[1]);
    REQUIRE(read(ids[0], &u.zombie, sizeof u.zombie) == sizeof u.zombie);
    close(ids[0]);
    becomes(u.zombie, 'Z');
    return u;
}

}  // namespace

// In a child of the test (course's part, not a subreaper): a zombie of its own,
// which it reaps without counting, and a live process of `user`, which it
// kills. Exits with how many kill_strays() killed, 100 more when its own
// zombie was not reaped.
[[noreturn]] void seek_strays(const grading::RunAsUser& user) {
    const pid_t own = fork();
    if (own == 0) _exit(0);
    int ready[2];
    if (own < 0 || !becomes(own, 'Z') || pipe(ready) != 0) _exit(200);
    const pid_t live = fork();
    if (live == 0) {
        close(ready[0]);
        if (setuid(user.uid) != 0) _exit(1);
        close(ready[1]);  // now of the user
        pause();
        _exit(1);
    }
    close(ready[1]);
    char byte;
    if (live < 0 || read(ready[0], &byte, 1) != 0) _exit(201);
    const int killed = grading::kill_strays(&user);
    _exit(killed + (process_state(own) == '?' ? 0 : 100));
}

TEST_CASE("children: a zombie is not a stray: course reaps its own and leaves another's") {
    if (geteuid() != 0) {
        std::printf("SKIP: processes of another user need root; this test runs as uid %u\n",
                    unsigned(geteuid()));
        return;
    }
    // A user of its own, which no other test's process has: kill_strays kills
    // every process of it.
    grading::RunAsUser user;
    user.name = "children-test";
    user.uid = user.gid = 3999999;
    // A zombie of the user whose parent never reaps it (as a container's init
    // may never), outside the tree of the process that seeks strays.
    Unreaped z = unreaped_zombie(user.uid);
    REQUIRE(process_state(z.zombie) == 'Z');
    const pid_t seeker = fork();
    REQUIRE(seeker >= 0);
    if (seeker == 0) seek_strays(user);
    int status = 0;
    REQUIRE(waitpid(seeker, &status, 0) == seeker);
    REQUIRE(WIFEXITED(status));
    // The live process, once: a zombie taken for a stray would count again
    // every round (kill() succeeds on it), 50 rounds.
    CHECK(WEXITSTATUS(status) == 1);
    CHECK(process_state(z.zombie) == 'Z');  // left to its parent
    close(z.release[1]);
    waitpid(z.parent, nullptr, 0);
    waitpid(z.zombie, nullptr, 0);  // reparented to this process (a subreaper) or init
}

namespace {

// Writes `parts` into a pipe one at a time, each followed by a read of all
// that is there, as course's watcher does; then closes it and reads its end.
struct Fed {
    bool ok = true;
    std::string why;
};
Fed feed(grading::StreamedOutputs& streamed, const std::vector<std::string>& parts,
         const grading::ChildLimits& limits = {}) {
    int fds[2];
    REQUIRE(pipe(fds) == 0);
    fcntl(fds[0], F_SETFL, O_NONBLOCK);
    Fed fed;
    for (const std::string& part : parts) {
        REQUIRE(write(fds[1], part.data(), part.size()) == static_cast<ssize_t>(part.size()));
        if (fed.ok) fed.ok = streamed.read(fds[0], limits, true, fed.why);
    }
    close(fds[1]);
    if (fed.ok) fed.ok = streamed.read(fds[0], limits, true, fed.why);
    close(fds[0]);
    return fed;
}

}  // namespace

TEST_CASE("children: outputs sent on the output descriptor are taken apart, record by record") {
    const std::string dir = "/tmp/course-x";
    grading::StreamedOutputs streamed(dir);
    // Pieces cut anywhere: inside a header, inside a body, two records in one.
    const Fed fed = feed(streamed, {"OUTPUT 5 " + dir + "/a.p", "am\nhel",
                                    "lo"
                                    "OUTPUT 0 " +
                                        dir + "/empty.txt\nOUTPUT 3 " + dir + "/0/b.json\n{}\n",
                                    "OUTPUT 9 " + dir + "/cut.pam\nshort"});
    REQUIRE_MESSAGE(fed.ok, fed.why);
    CHECK(streamed.eof());
    const std::map<std::string, std::string> top = streamed.take(dir);
    CHECK(top == std::map<std::string, std::string>{{"a.pam", "hello"}, {"empty.txt", ""}});
    CHECK(streamed.take(dir + "/0") == std::map<std::string, std::string>{{"b.json", "{}\n"}});
    CHECK(streamed.take(dir).empty());  // taken once; the record cut short never was one
    // Each record is at least 4 KiB of the work directory's cap.
    CHECK(streamed.lab_bytes() == 4 * 4096);  // the one cut short too
}

TEST_CASE("children: each record is told as it completes, once, and a record cut short never") {
    const std::string dir = "/tmp/course-x";
    std::vector<std::pair<std::string, std::string>> told;
    grading::StreamedOutputs streamed(dir, [&](const std::string& path, const std::string& bytes) {
        told.emplace_back(path, bytes);
    });
    // A body over three reads, one complete with its header, an empty one,
    // and one cut short by the end.
    const Fed fed = feed(streamed, {"OUTPUT 10 " + dir + "/0/units.json\n{\"u0\"", ":{}",
                                    "}\nOUTPUT 2 " + dir + "/a.json\n[]OUTPUT 0 " + dir + "/e\n",
                                    "OUTPUT 9 " + dir + "/cut.pam\nshort"});
    REQUIRE_MESSAGE(fed.ok, fed.why);
    const std::vector<std::pair<std::string, std::string>> want = {
        {dir + "/0/units.json", "{\"u0\":{}}\n"}, {dir + "/a.json", "[]"}, {dir + "/e", ""}};
    CHECK(told == want);
}

TEST_CASE(
    "children: anything on the output descriptor but a record of the work directory stops the "
    "child") {
    const std::string dir = "/tmp/course-x";
    grading::ChildLimits small;
    small.file_cap = 100;
    small.work_dir_cap = 10000;
    const std::vector<std::pair<std::string, std::string>> cases = {
        {"garbage\n", "not an output record (a line \"OUTPUT SIZE PATH\")"},
        {"OUTPUT x " + dir + "/a\n", "not an output record"},
        {"OUTPUT 1 /etc/a\nx", "outside its work directory ('/etc/a')"},
        {"OUTPUT 1 " + dir + "/../a\nx", "outside its work directory"},
        {"OUTPUT 1 " + dir + "/x/a\nx", "outside its work directory"},
        {"OUTPUT 1 " + dir + "x/a\nx", "outside its work directory"},
        {"OUTPUT 101 " + dir + "/a\n", "101 bytes, '" + dir + "/a': over the 0 MiB limit per file"},
        {"OUTPUT 9 " + dir + "/a\n123456789OUTPUT 9 " + dir + "/b\n123456789OUTPUT 9 " + dir +
             "/c\n",
         "more than 0 MiB of outputs on its output descriptor, the limit of its work directory"},
        {std::string(5000, 'x'), "no end of line in 4096 bytes"},
    };
    for (const auto& [sent, why] : cases) {
        CAPTURE(sent.substr(0, 80));
        grading::StreamedOutputs streamed(dir);
        const Fed fed = feed(streamed, {sent}, small);
        CHECK_FALSE(fed.ok);
        CHECK_MESSAGE(fed.why.find(why) != std::string::npos, fed.why);
        CHECK(streamed.eof());  // never read again
    }
}

TEST_CASE("children: a child's descriptor 3 is the output pipe, and what it sends is kept") {
    const std::string dir = work_dir();
    grading::StreamedOutputs streamed(dir);
    grading::ChildLimits limits;
    limits.timeout_seconds = 20;
    // A megabyte, past any pipe's default capacity, then a small record.
    const std::string script =
        "head -c 1048576 /dev/zero > big.bin; "
        "{ printf 'OUTPUT 1048576 %s/big.pam\\n' \"$PWD\"; cat big.bin; "
        "printf 'OUTPUT 2 %s/s.json\\n{}' \"$PWD\"; } >&3; rm big.bin";
    const grading::ChildRun run =
        grading::run_child({"/bin/sh", "-c", script}, dir, limits, nullptr, {}, nullptr, &streamed);
    const std::string how = run.status.text() + "\n" + run.log;
    REQUIRE_MESSAGE(run.ok(), how);
    std::map<std::string, std::string> got = streamed.take(dir);
    REQUIRE(got.size() == 2);
    CHECK(got["big.pam"] == std::string(1 << 20, '\0'));
    CHECK(got["s.json"] == "{}");
}

TEST_CASE("children: a lab's seconds end at its mark's time, not when course looks for it") {
    // Under load course can look for the marks after two labs have ended;
    // the labs' seconds are still each lab's own. Here the marks' times
    // say so: lab 0 ended 0.4 s before lab 1, though both marks appear at
    // once, 0.6 s after the child's start. A mark whose time lies outside
    // the child's run (set by the child: before its start, or in 2100)
    // counts as the nearest time within it.
    const std::string dir = work_dir() + "/marks";
    fs::remove_all(dir);
    fs::create_directories(dir);
    grading::LabMarks marks;
    for (int i = 0; i < 4; ++i) marks.files.push_back(dir + "/m" + std::to_string(i));
    const std::string script =
        "sleep 0.6; t=$(date +%s.%N); "
        "touch -d \"@$(awk -v t=\"$t\" 'BEGIN { printf \"%.6f\", t - 0.4 }')\" m0.tmp; "
        "touch m1.tmp; touch -d @0 m2.tmp; touch -d @4102444800 m3.tmp; "
        "mv m0.tmp m0; mv m1.tmp m1; mv m2.tmp m2; mv m3.tmp m3";
    grading::ChildLimits limits;
    limits.timeout_seconds = 20;
    const grading::ChildRun run =
        grading::run_child({"/bin/sh", "-c", script}, dir, limits, nullptr, {}, &marks);
    const std::string how = run.status.text() + "\n" + run.log;
    REQUIRE_MESSAGE(run.ok(), how);
    REQUIRE(marks.ended.size() == 4);
    const double s0 = marks.ended[0].seconds, s1 = marks.ended[1].seconds;
    // Lab 1's mark was stamped 0.4 s after lab 0's, and a little more on a
    // busy machine; lab 0 ended 0.4 s before the child ended, at least.
    CHECK_MESSAGE((s0 > 0.12 && s0 < run.seconds - 0.35), "lab 0: " << s0 << " s");
    CHECK_MESSAGE((s1 > 0.35 && s1 < 1.5), "lab 1: " << s1 << " s");
    CHECK(marks.ended[2].seconds == 0.0);
    CHECK(marks.ended[3].seconds >= 0.0);
    double sum = 0.0;
    for (const grading::LabMarks::Ended& e : marks.ended) sum += e.seconds;
    CHECK_MESSAGE(sum <= run.seconds + 0.01, sum << " s of labs in a child of " << run.seconds);
}
