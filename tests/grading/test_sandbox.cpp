// The sandbox around each lab's child (grading/sandbox/sandbox.hpp, isolation.hpp),
// attacked by real submissions (tests/grading/fake_lab.cpp), each graded
// beside an honest lab, under two profiles:
//   - privileged: course as root with CAP_SYS_ADMIN, as on a staff machine
//     or CI: namespaces and cgroups on top of the unprivileged layers;
//   - gradescope: the same root without CAP_SYS_ADMIN (setpriv) and with no
//     cgroup hierarchy (a read-only tmpfs over /sys/fs/cgroup in a mount
//     namespace of the test's), as in Gradescope's container: seccomp,
//     the subreaper, --run-as and rlimits alone.
// Without root only the machine's own (unprivileged) profile runs.
// For each: the lab at fault loses what it did not earn, the honest lab keeps
// full marks, the reports are whole, and when course exits nothing of the
// run is left. The --run-as cases need root and a user `nobody`.
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

// The processes whose real user is `uid`.
int processes_of_uid(uid_t uid) {
    int count = 0;
    DIR* proc = opendir("/proc");
    while (dirent* e = proc ? readdir(proc) : nullptr) {
        if (e->d_name[0] < '0' || e->d_name[0] > '9') continue;
        std::ifstream status(std::string("/proc/") + e->d_name + "/status");
        for (std::string line; std::getline(status, line);)
            if (line.rfind("Uid:", 0) == 0) {
                count += std::stoul(line.substr(4)) == uid;
                break;
            }
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

// A way of running course: its name, the command line put before it, and
// whether namespaces and cgroups are expected on.
struct Profile {
    std::string name;
    std::string wrapper;
    bool privileged = false;
};

const char* const kGradescopeWrapper =
    "unshare --mount sh -c '{ [ ! -d /sys/fs/cgroup ] || mount -t tmpfs -o ro none "
    "/sys/fs/cgroup; } && exec setpriv --bounding-set=-sys_admin -- \"$@\"' sh";

// The profiles this machine can run: privileged where course's strict
// sandbox works; Gradescope's wherever root may make a mount namespace (to
// hide the cgroups in) and drop CAP_SYS_ADMIN; else the machine's own.
const std::vector<Profile>& profiles() {
    static const std::vector<Profile> list = [] {
        std::vector<Profile> found;
        const std::string out = fw::test::out_dir() + "/strict-probe";
        fs::remove_all(out);
        const fw::test::CommandResult strict =
            fw::test::run_command(course() + " grade pipeline --sandbox strict --out " + out);
        if (strict.exit_code == 0)
            found.push_back({"privileged", "", true});
        else
            std::printf("SKIP: the privileged profile: course grade --sandbox strict says:\n%s\n",
                        strict.output.c_str());
        if (geteuid() == 0 &&
            fw::test::run_command("unshare --mount true && setpriv --version").exit_code == 0)
            found.push_back({"gradescope", kGradescopeWrapper, false});
        if (found.empty()) {
            std::printf(
                "SKIP: Gradescope's profile: it needs root, unshare and setpriv; the "
                "attacks run on this machine's own profile\n");
            found.push_back({"unprivileged", "", false});
        }
        return found;
    }();
    return list;
}

// The run's summary names the layers its profile has (on this machine's own
// profile, only those that are there everywhere).
void check_layers(const Graded& g, const Profile& p) {
    fw::test::check_mentions(g.output, {"on: seccomp filter", "on: child subreaper"});
    if (p.wrapper.empty() && !p.privileged) return;
    const std::string state = p.privileged ? "on: " : "off: ";
    fw::test::check_mentions(g.output, {state + "namespaces", state + "cgroup"});
}

// Nothing of the run is left: no fake_lab, no daemon, no process of nobody.
void check_nothing_left(bool run_as) {
    CHECK(processes_named("fake_lab") == 0);
    CHECK(processes_named("lab-daemon") == 0);
    if (run_as) CHECK(processes_of_uid(getpwnam("nobody")->pw_uid) == 0);
}

// `mode` in lab 0 beside an honest lab 1 (as nobody when `run_as`): lab 0
// fails, lab 1 keeps full marks, the reports are whole, nothing is left.
Graded attack(const Profile& p, const std::string& mode, const std::string& env, bool run_as,
              int exit_code = 1, const std::string& options = "") {
    CAPTURE(p.name);
    CAPTURE(mode);
    Graded g;
    if (run_as) {
        const Staged st = stage_for_run_as();
        const std::string tree = make_tree(st.dir + "/tree", false);
        const fs::path transforms = fs::path(fw::test::source_dir()) / "labs/01_transforms";
        fs::create_directories(tree + "/labs/01_transforms");
        fs::copy_file(transforms / "checkpoints.json",
                      tree + "/labs/01_transforms/checkpoints.json");
        fs::copy(transforms / "reference", tree + "/labs/01_transforms/reference");
        // (Its forbidden-name check reads the source.)
        fs::copy_file(transforms / "transforms_math.cpp",
                      tree + "/labs/01_transforms/transforms_math.cpp");
        // The staged copies: the build may sit where `nobody` cannot enter.
        g = grade(st.env + " FAKE_LAB_REAL_COPY=" + st.lab + " LAB_ROOT=" + tree +
                      " FAKE_LAB_TARGET=pipeline FAKE_LAB_MODE=" + mode + " " + env,
                  "pipeline transforms --verbose --run-as nobody --lab " + st.fake + options,
                  fw::test::out_dir() + "/" + p.name + "-" + mode, p.wrapper);
        fs::remove_all(st.dir);
    } else {
        g = grade("FAKE_LAB_TARGET=pipeline FAKE_LAB_MODE=" + mode + " " + env,
                  "pipeline transforms --verbose --lab " + fake_lab() + options,
                  fw::test::out_dir() + "/" + p.name + "-" + mode, p.wrapper);
    }
    CHECK(g.exit_code == exit_code);
    check_layers(g, p);
    check_transforms_full(g);
    check_nothing_left(run_as);
    return g;
}

}  // namespace

TEST_CASE("sandbox: no network for a lab, but for AF_UNIX; no DNS") {
    for (const Profile& p : profiles()) {
        Listener listener;
        const Graded g =
            attack(p, "network", "FAKE_LAB_PORT=" + std::to_string(listener.port), false);
        fw::test::check_mentions(g.output, {"network: tcp socket: Operation not permitted",
                                            "network: udp6 socket: Operation not permitted",
                                            "network: unix socket: opened"});
        CHECK(g.output.find("CONNECTED") == std::string::npos);
        CHECK(g.output.find("RESOLVED") == std::string::npos);
        CHECK(!listener.connected());
    }
}

TEST_CASE("sandbox: no ptrace, process_vm_readv or /proc of course") {
    for (const Profile& p : profiles())
        for (const bool run_as : {false, true}) {
            if (run_as && !can_run_as_nobody()) continue;
            CAPTURE(run_as);
            const Graded g = attack(p, "ptrace", "", run_as);
#if !defined(__SANITIZE_ADDRESS__)
            // (LeakSanitizer needs ptrace: sanitized builds leave it allowed.)
            CHECK(g.output.find("ATTACHED") == std::string::npos);
#endif
            // (Without --run-as the lab is course's own user, who may read
            // course's /proc: that is what --run-as is for.)
            if (p.privileged) {
                // Its own PID namespace: course is not there to attack, and
                // its init is root's alone.
                fw::test::check_mentions(g.output,
                                         {"my parent is pid 1;", "course: NOT VISIBLE in /proc"});
                if (run_as)
                    fw::test::check_mentions(g.output,
                                             {"/proc/1/environ of the init: Permission denied"});
                continue;
            }
            CHECK(g.output.find("of course: READ") == std::string::npos);
#if !defined(__SANITIZE_ADDRESS__)
            fw::test::check_mentions(g.output,
                                     {"ptrace: attach to course: Operation not permitted"});
#endif
            fw::test::check_mentions(
                g.output, {"ptrace: process_vm_readv of course: Operation not permitted"});
            // Another user may not read course's environment.
            if (run_as) fw::test::check_mentions(g.output, {"/environ: Permission denied"});
        }
}

TEST_CASE("sandbox: a setsid() daemon dies with its lab and writes nothing afterwards") {
    for (const Profile& p : profiles()) {
        CAPTURE(p.name);
        const std::string target = open_dir("daemon-target-" + p.name);
        const Graded g = attack(p, "daemon", "FAKE_LAB_SNOOP_WRITE=" + target, false, 0);
        // The daemon writes 1 s after its lab has ended: wait past that.
        std::this_thread::sleep_for(std::chrono::milliseconds(2500));
        CHECK(!fs::exists(target + "/daemon-was-here.txt"));
        CHECK(processes_named("lab-daemon") == 0);
    }
}

TEST_CASE("sandbox: a fork bomb is bounded, and nothing of it is left") {
    if (!can_run_as_nobody()) {
        std::printf("SKIP: RLIMIT_NPROC applies under --run-as, which needs root and 'nobody'\n");
        return;
    }
    for (const Profile& p : profiles()) {
        // The test's own bound: at most 3000 processes, whatever course does.
        const Graded g = attack(p, "forkbomb", "FAKE_LAB_FORKS=3000", true);
        fw::test::check_mentions(g.output, {"forkbomb: fork", "Resource temporarily unavailable"});
        CHECK(g.output.find("made 3000 of 3000") == std::string::npos);
    }
}

TEST_CASE("sandbox: 16 GiB of memory is refused; resident memory stops at the cgroup's limit") {
    // 1024 MiB per lab (--memory): the honest one needs less.
    for (const Profile& p : profiles()) {
#if defined(__SANITIZE_ADDRESS__)
        // No RLIMIT_AS under AddressSanitizer: only a cgroup bounds it here.
        if (!p.privileged) continue;
#endif
        // Resident memory is only asked for where a cgroup bounds it at 2 GiB.
        const Graded g =
            attack(p, "alloc", p.privileged ? "FAKE_LAB_TOUCH=1" : "", false, 1, " --memory 1024");
#if !defined(__SANITIZE_ADDRESS__)
        fw::test::check_mentions(g.output, {"alloc: 16 GiB at once: refused"});
#endif
        if (p.privileged) {
            fw::test::check_mentions(g.output, {"killed for memory: more than 1024 MiB in use"});
            CHECK(g.output.find("alloc: 1024 MiB resident") == std::string::npos);
        }
    }
}

TEST_CASE("sandbox: descriptors, a 10 MiB line and bytes that are not UTF-8") {
    for (const Profile& p : profiles()) {
        const Graded fds = attack(p, "fds", "", false);
        fw::test::check_mentions(fds.output, {"fds: opened", "Too many open files"});
        const Graded line = attack(p, "longline", "", false);
        fw::test::check_mentions(line.output, {"wrote more than 8 MiB to stdout/stderr"});
        // Shown cleaned, and the lab itself is graded as the real one.
        const Graded bytes = attack(p, "notutf8", "", false, 0);
        REQUIRE(bytes.results.is_object());
        const std::string summary =
            fw::test::read_text(fw::test::out_dir() + "/" + p.name + "-notutf8/summary.txt");
        CHECK(summary.find("\xff") == std::string::npos);
        CHECK(summary.find("\x1b") == std::string::npos);
    }
}

TEST_CASE("sandbox: filling the work directory stops at its cap") {
    for (const Profile& p : profiles()) {
        const Graded fill = attack(p, "fill", "", false);
        fw::test::check_mentions(fill.output, {"256 MiB into its work directory"});
    }
}

TEST_CASE("sandbox: under --run-as a lab writes nowhere but its work directory") {
    if (!can_run_as_nobody()) {
        std::printf("SKIP: --run-as needs root and a user 'nobody'\n");
        return;
    }
    for (const Profile& p : profiles()) {
        const std::string closed = fw::test::out_dir() + "/closed-" + p.name;
        fs::remove_all(closed);
        fs::create_directories(closed);
        chmod(closed.c_str(), 0755);
        const std::string targets = closed +
                                    "/planted.txt:/etc/fake_lab_planted:" + fw::test::out_dir() +
                                    "/" + p.name + "-outside/x.txt";
        const Graded g = attack(p, "outside", "FAKE_LAB_OUTSIDE=" + targets, true);
        CHECK(g.output.find("WRITTEN") == std::string::npos);
        fw::test::check_mentions(g.output, {"outside: write", "Permission denied"});
        CHECK(!fs::exists(closed + "/planted.txt"));
        CHECK(!fs::exists("/etc/fake_lab_planted"));
    }
}

TEST_CASE("sandbox: each lab in a cgroup of its own, with memory, pids and the CPU") {
    for (const Profile& p : profiles()) {
        if (!p.privileged) continue;
        const std::string report = fw::test::out_dir() + "/cgroups.txt";
        fs::remove(report);
        const Graded g = attack(p, "cgroups", "FAKE_LAB_REPORT=" + report, false, 0);
        const std::string where = fw::test::read_text(report);
        INFO(where);
        // Both labs in their own cgroups under this run's course-PID.
        std::vector<std::string> controllers = {"memory", "pids"};
        if (g.output.find(", cpu)") != std::string::npos ||
            g.output.find("an equal share of the CPU") != std::string::npos)
            controllers.push_back("cpu");
        for (const std::string& c : controllers) {
            CAPTURE(c);
            bool found = false;
            std::istringstream lines(where);
            for (std::string line; std::getline(lines, line);)
                if (line.find("cgroups: ") != std::string::npos &&
                    (line.find(":" + c + ":") != std::string::npos ||
                     line.find("," + c + ":") != std::string::npos ||
                     line.find(":" + c + ",") != std::string::npos ||
                     line.find("0::/") != std::string::npos))
                    found = found || (line.find("/course-") != std::string::npos &&
                                      line.find("/lab-") != std::string::npos);
            CHECK(found);
        }
    }
}

TEST_CASE("sandbox: --sandbox strict refuses to grade without namespaces and cgroups") {
    for (const Profile& p : profiles()) {
        CAPTURE(p.name);
        const std::string out = fw::test::out_dir() + "/strict-" + p.name;
        const Graded g = grade("", "pipeline --sandbox strict", out, p.wrapper);
        if (p.privileged) {
            CHECK(g.exit_code == 0);
            continue;
        }
        CHECK(g.exit_code == 2);
        fw::test::check_mentions(g.output, {"--sandbox strict: not grading", "namespaces", "cgroup",
                                            "CAP_SYS_ADMIN", "--sandbox auto"});
        CHECK(!fs::exists(out + "/results.json"));
    }
}

namespace {

// The hierarchies course makes its cgroups in: cgroup v2 where it has the
// memory controller, else v1's memory and pids hierarchies.
std::vector<std::string> course_cgroup_tops() {
    std::vector<std::string> v1;
    std::ifstream mounts("/proc/self/mounts");
    for (std::string line; std::getline(mounts, line);) {
        std::istringstream f(line);
        std::string device, dir, type, options;
        f >> device >> dir >> type >> options;
        if (type == "cgroup2" &&
            fw::test::read_text(dir + "/cgroup.controllers").find("memory") != std::string::npos)
            return {dir};
        const std::string o = "," + options + ",";
        const bool listed = std::find(v1.begin(), v1.end(), dir) != v1.end();
        if (type == "cgroup" && !listed && o.find(",memory,") != std::string::npos)
            v1.insert(v1.begin(), dir);
        else if (type == "cgroup" && !listed && o.find(",pids,") != std::string::npos)
            v1.push_back(dir);
    }
    return v1;
}

}  // namespace

TEST_CASE("sandbox: course removes its own PID namespace's stale cgroups, never another's") {
    bool privileged = false;
    for (const Profile& p : profiles()) privileged = privileged || p.privileged;
    if (!privileged) {
        std::printf("SKIP: course makes no cgroups on this machine (see the privileged profile)\n");
        return;
    }
    // A PID never handed out (PIDs stay below pid_max): each name's course is gone.
    const std::string dead = fw::test::read_text("/proc/sys/kernel/pid_max").substr(0, 12);
    const std::string gone = std::to_string(std::stol(dead));
    struct stat ns = {};
    REQUIRE(stat("/proc/self/ns/pid", &ns) == 0);
    // This namespace's stale cgroup; another namespace's (whose PIDs mean
    // nothing here); and the name an older course in any namespace made.
    const std::string own = "course-" + std::to_string(ns.st_ino) + "-" + gone;
    const std::vector<std::string> others = {"course-1-" + gone, "course-" + gone};
    const std::vector<std::string> tops = course_cgroup_tops();
    REQUIRE(!tops.empty());
    for (const std::string& top : tops)
        for (const std::string& name : {own, others[0], others[1]})
            REQUIRE(fs::create_directories(top + "/" + name + "/lab-0"));
    const Graded g = grade("", "pipeline", fw::test::out_dir() + "/stale-cgroups");
    CHECK(g.exit_code == 0);
    for (const std::string& top : tops) {
        CAPTURE(top);
        CHECK(!fs::exists(top + "/" + own));
        for (const std::string& name : others) {
            CAPTURE(name);
            CHECK(fs::exists(top + "/" + name + "/lab-0"));
            rmdir((top + "/" + name + "/lab-0").c_str());
            rmdir((top + "/" + name).c_str());
        }
        rmdir((top + "/" + own + "/lab-0").c_str());
        rmdir((top + "/" + own).c_str());
    }
}
