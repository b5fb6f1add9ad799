// The sandbox around each lab's child (grading/sandbox.hpp), attacked by real
// submissions (tests/grading/fake_lab.cpp), each graded beside an honest lab:
// the network, ptrace and process_vm_readv on course, a setsid() daemon that
// waits for its lab to be graded, and a fork bomb (bounded by this test).
// The lab at fault loses what it did not earn, the honest lab keeps full
// marks, and when course exits nothing of the run is left running. The
// --run-as cases need root and a user `nobody`; they skip without them.
#include <arpa/inet.h>
#include <dirent.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <pwd.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fstream>
#include <thread>

#include "tests/grading/grade_support.hpp"

using namespace grade_test;

namespace {

// The processes whose name (comm) is `name`.
int processes_named(const std::string& name) {
    int count = 0;
    DIR* proc = opendir("/proc");
    while (dirent* e = proc ? readdir(proc) : nullptr) {
        if (e->d_name[0] < '0' || e->d_name[0] > '9') continue;
        std::ifstream comm(std::string("/proc/") + e->d_name + "/comm");
        std::string text;
        std::getline(comm, text);
        count += text == name;
    }
    if (proc) closedir(proc);
    return count;
}

bool can_run_as_nobody() { return geteuid() == 0 && getpwnam("nobody") != nullptr; }

// A TCP listener on 127.0.0.1 and whether anything connected to it.
struct Listener {
    Listener() {
        fd = socket(AF_INET, SOCK_STREAM | SOCK_NONBLOCK | SOCK_CLOEXEC, 0);
        sockaddr_in addr{};
        addr.sin_family = AF_INET;
        addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        socklen_t len = sizeof addr;
        REQUIRE(bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) == 0);
        REQUIRE(listen(fd, 8) == 0);
        getsockname(fd, reinterpret_cast<sockaddr*>(&addr), &len);
        port = ntohs(addr.sin_port);
    }
    ~Listener() { close(fd); }
    bool connected() const {
        const int c = accept(fd, nullptr, nullptr);
        if (c >= 0) close(c);
        return c >= 0;
    }
    int fd = -1;
    int port = 0;
};

// Where a user other than root may write (the daemon's target).
std::string open_dir(const std::string& name) {
    const std::string dir = fw::test::out_dir() + "/" + name;
    fs::remove_all(dir);
    fs::create_directories(dir);
    chmod(dir.c_str(), 0777);
    chmod(fw::test::out_dir().c_str(), 0755);
    return dir;
}

// The honest lab of the run keeps its full marks.
void check_transforms_full(const Graded& g) {
    REQUIRE(g.results.is_object());
    double earned = 0, max = 0;
    for (const json& t : g.results["tests"])
        if (t.value("name", "").rfind("transforms", 0) == 0 ||
            t.value("name", "").find("01_transforms") != std::string::npos ||
            t.value("name", "").find("transforms/") != std::string::npos) {
            earned += t.value("score", 0.0);
            max += t.value("max_score", 0.0);
        }
    CHECK(max > 0);
    CHECK(earned == max);
}

}  // namespace

TEST_CASE("sandbox: no network for a lab, but for AF_UNIX") {
    Listener listener;
    const std::string out = fw::test::out_dir() + "/report";
    Graded g = grade("FAKE_LAB_TARGET=pipeline FAKE_LAB_MODE=network FAKE_LAB_PORT=" +
                         std::to_string(listener.port),
                     "pipeline transforms --lab " + fake_lab(), out);
    CHECK(g.exit_code == 1);
    fw::test::check_mentions(g.output, {"network: tcp socket: Operation not permitted",
                                        "network: udp6 socket: Operation not permitted",
                                        "network: unix socket: opened"});
    CHECK(g.output.find("CONNECTED") == std::string::npos);
    CHECK(g.output.find("RESOLVED") == std::string::npos);
    CHECK(!listener.connected());
    check_transforms_full(g);
}

TEST_CASE("sandbox: no ptrace or process_vm_readv on course") {
    const std::string out = fw::test::out_dir() + "/report";
    Graded g = grade("FAKE_LAB_TARGET=pipeline FAKE_LAB_MODE=ptrace",
                     "pipeline transforms --lab " + fake_lab(), out);
    CHECK(g.exit_code == 1);
#if !defined(__SANITIZE_ADDRESS__)
    // (LeakSanitizer needs ptrace: sanitized builds leave it allowed.)
    fw::test::check_mentions(g.output, {"ptrace: attach to course: Operation not permitted"});
#endif
    fw::test::check_mentions(g.output,
                             {"ptrace: process_vm_readv of course: Operation not permitted"});
    CHECK(g.output.find("ATTACHED") == std::string::npos);
    check_transforms_full(g);
    if (can_run_as_nobody()) {
        const Staged st = stage_for_run_as();
        const std::string tree = make_tree(st.dir + "/tree", false);
        Graded as =
            grade(st.env + " LAB_ROOT=" + tree + " FAKE_LAB_TARGET=pipeline FAKE_LAB_MODE=ptrace",
                  "pipeline --run-as nobody --lab " + st.fake, st.dir + "/report");
        // Another user may not read course's environment.
        fw::test::check_mentions(as.output, {"/environ: Permission denied"});
    }
}

TEST_CASE("sandbox: a setsid() daemon dies with its lab and writes nothing afterwards") {
    const std::string target = open_dir("daemon-target");
    const std::string out = fw::test::out_dir() + "/report";
    Graded g = grade("FAKE_LAB_TARGET=pipeline FAKE_LAB_MODE=daemon FAKE_LAB_SNOOP_WRITE=" + target,
                     "pipeline transforms --lab " + fake_lab(), out);
    CHECK(g.exit_code == 0);  // the daemon's lab is the real one otherwise
    check_transforms_full(g);
    CHECK(processes_named("lab-daemon") == 0);
    std::this_thread::sleep_for(std::chrono::milliseconds(3500));  // past the daemon's wait
    CHECK(!fs::exists(target + "/daemon-was-here.txt"));
    CHECK(processes_named("lab-daemon") == 0);
}

TEST_CASE("sandbox: a fork bomb is bounded, and nothing of it is left") {
    if (!can_run_as_nobody()) {
        std::printf("SKIP: RLIMIT_NPROC applies under --run-as, which needs root and 'nobody'\n");
        return;
    }
    const Staged st = stage_for_run_as();
    const std::string tree = make_tree(st.dir + "/tree", false);
    // The test's own bound: at most 3000 processes, whatever course does.
    Graded g = grade(st.env + " LAB_ROOT=" + tree +
                         " FAKE_LAB_TARGET=pipeline FAKE_LAB_MODE=forkbomb FAKE_LAB_FORKS=3000",
                     "pipeline --run-as nobody --lab " + st.fake, st.dir + "/report");
    CHECK(g.exit_code == 1);
    fw::test::check_mentions(g.output, {"forkbomb: fork", "Resource temporarily unavailable"});
    CHECK(g.output.find("made 3000 of 3000") == std::string::npos);
    CHECK(processes_named("fake_lab") == 0);
}
