// A hostile stand-in for `lab grade-child`, run by `course grade --lab`.
// For the lab named by FAKE_LAB_TARGET it misbehaves as FAKE_LAB_MODE says;
// for every other lab it becomes the real `lab` (exec), so that tests can
// show one lab's misbehaviour costs the others nothing. Given several labs
// at once (course's one child for several), it keeps their order: the real
// lab grades those before the target, the target misbehaves, and when that
// returns 0 the real lab grades those after it.
//
//   segv        dies of SIGSEGV before writing anything
//   hang        never returns (course's timeout must end it)
//   exit_segv   the real lab's outputs, child.json too, then SIGSEGV
//   spew        writes to stdout without end
//   bigfile     writes one file past course's per-file limit
//   fill        writes 1 MiB files without end (course's work directory cap)
//   garbage     text where the frames, depth, stats and units.json belong; the
//               first frame has a valid header claiming 100000 x 100000 pixels
//   liar        black frames, stats and units.json claiming a perfect score
//   symlink     each NAME.pam a link to course's reference (FAKE_LAB_REFERENCES)
//   wrong_unit  the real lab's outputs, with every unit result changed
//   transposed_unit  the real lab's outputs, with every 4x4 matrix result
//               transposed (a symmetric one still passes)
//   snoop       tries to read FAKE_LAB_SNOOP_READ and write into
//               FAKE_LAB_SNOOP_WRITE, prints what happened, exits 3
//   cache       writes into FAKE_LAB_REPORT where its Mesa shader cache is
//               and whether it may write every file in it, plants a file
//               there, then becomes the real lab
//   network     tries a TCP connection to 127.0.0.1:FAKE_LAB_PORT, a UDP
//               socket and a DNS lookup, prints what happened, exits 3
//   ptrace      tries ptrace and process_vm_readv on course (its parent)
//               and reading course's /proc environ, prints what happened,
//               exits 3
//   daemon      leaves a setsid() daemon (named lab-daemon) that waits until
//               the lab has ended, then 1 s, then writes into
//               FAKE_LAB_SNOOP_WRITE; the lab becomes the real lab
//   forkbomb    forks up to FAKE_LAB_FORKS children that wait, prints how
//               many it made, exits 3
//   quick       writes nothing (no frame, no shader cache) and exits 0
// and on its output descriptor (--output-fd), where course reads records:
//   stream_garbage   a line that is not a record, then exits 0
//   stream_outside   a record for a file outside its work directory
//   stream_flood     1 MiB records without end (the work directory's cap)
//   stream_cut       its first frame's record, cut short, then exits 0
// FAKE_LAB_MARK: a file the fake appends a line to whenever it runs:
// "ran:" and the labs it was given.
#include <arpa/inet.h>
#include <fcntl.h>
#include <netdb.h>
#include <netinet/in.h>
#include <sys/prctl.h>
#include <sys/ptrace.h>
#include <sys/socket.h>
#include <sys/uio.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cctype>
#include <cerrno>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "framework/image.hpp"

namespace {

using nlohmann::json;

std::string env(const char* name) {
    const char* v = std::getenv(name);
    return v ? v : "";
}

void write_text(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

// The real lab: FAKE_LAB_REAL_COPY when set (a copy another user may run),
// else the build's.
std::string real_lab() {
    return env("FAKE_LAB_REAL_COPY").empty() ? FAKE_LAB_REAL : env("FAKE_LAB_REAL_COPY");
}

// Runs the real lab with our arguments and waits for it.
int run_real(char* const* argv) {
    const std::string real = real_lab();
    pid_t pid = fork();
    if (pid == 0) {
        execv(real.c_str(), argv);
        _exit(127);
    }
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : 1;
}

int try_network(int port) {
    const int tcp = socket(AF_INET, SOCK_STREAM, 0);
    if (tcp < 0) {
        std::printf("network: tcp socket: %s\n", std::strerror(errno));
    } else {
        sockaddr_in addr{};
        addr.sin_family = AF_INET;
        addr.sin_port = htons(static_cast<uint16_t>(port));
        addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        const int rc = connect(tcp, reinterpret_cast<sockaddr*>(&addr), sizeof addr);
        std::printf("network: connect 127.0.0.1:%d: %s\n", port,
                    rc == 0 ? "CONNECTED" : std::strerror(errno));
        close(tcp);
    }
    const int udp = socket(AF_INET6, SOCK_DGRAM, 0);
    std::printf("network: udp6 socket: %s\n", udp < 0 ? std::strerror(errno) : "OPENED");
    addrinfo* found = nullptr;
    const int rc = getaddrinfo("deb.debian.org", "80", nullptr, &found);
    std::printf("network: dns lookup: %s\n", rc == 0 ? "RESOLVED" : gai_strerror(rc));
    if (found) freeaddrinfo(found);
    const int local = socket(AF_UNIX, SOCK_STREAM, 0);
    std::printf("network: unix socket: %s\n", local < 0 ? std::strerror(errno) : "opened");
    return 3;
}

// The process named "course" that this lab can see in /proc, or 0: in a
// PID namespace of its own it sees none.
pid_t find_course() {
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator("/proc", ec)) {
        std::ifstream comm(e.path() / "comm");
        std::string name;
        if (std::getline(comm, name) && name == "course")
            return static_cast<pid_t>(std::atoi(e.path().filename().c_str()));
    }
    return 0;
}

int try_ptrace() {
    const pid_t course = find_course();
    std::printf("ptrace: my parent is pid %d; processes visible: ", static_cast<int>(getppid()));
    std::error_code ec;
    int visible = 0;
    for (const auto& e : std::filesystem::directory_iterator("/proc", ec))
        visible += std::isdigit(static_cast<unsigned char>(e.path().filename().c_str()[0])) != 0;
    std::printf("%d\n", visible);
    if (course == 0) {
        std::printf("ptrace: course: NOT VISIBLE in /proc\n");
        // PID 1 is then the namespace's init, a copy of course.
        std::ifstream init("/proc/1/environ");
        std::string text;
        std::getline(init, text, '\0');
        std::printf("ptrace: read /proc/1/environ of the init: %s\n",
                    init ? "READ" : std::strerror(errno));
        return 3;
    }
    errno = 0;
    const long rc = ptrace(PTRACE_ATTACH, course, nullptr, nullptr);
    std::printf("ptrace: attach to course: %s\n", rc == 0 ? "ATTACHED" : std::strerror(errno));
    if (rc == 0) {
        // Attached (a sanitized build allows ptrace): wait for course to
        // stop, then let it go, or it would stay stopped.
        waitpid(course, nullptr, __WALL);
        ptrace(PTRACE_DETACH, course, nullptr, nullptr);
    }
    char buf[64];
    iovec local{buf, sizeof buf};
    iovec remote{reinterpret_cast<void*>(0x400000), sizeof buf};
    const ssize_t n = process_vm_readv(course, &local, 1, &remote, 1, 0);
    std::printf("ptrace: process_vm_readv of course: %s\n", n >= 0 ? "READ" : std::strerror(errno));
    const std::string environ_path = "/proc/" + std::to_string(course) + "/environ";
    std::ifstream in(environ_path);
    std::string text;
    std::getline(in, text, '\0');
    std::printf("ptrace: read %s: %s\n", environ_path.c_str(), in ? "READ" : std::strerror(errno));
    // The command line: every user may read it unless /proc hides processes.
    std::ifstream cmdline("/proc/" + std::to_string(course) + "/cmdline");
    std::string args;
    std::getline(cmdline, args, '\0');
    std::printf("ptrace: read /proc/%d/cmdline: %s\n", static_cast<int>(course),
                cmdline ? ("READ " + args).c_str() : std::strerror(errno));
    return 3;
}

// A daemon that outlives its lab unless course kills it: it leaves the
// lab's process group and session, and its parent exits at once.
void leave_daemon(const std::string& write_dir) {
    const pid_t lab = getpid();
    const pid_t first = fork();
    if (first != 0) {
        waitpid(first, nullptr, 0);
        return;
    }
    setsid();
    if (fork() != 0) _exit(0);
    prctl(PR_SET_NAME, "lab-daemon");
    // Until its lab has ended and been graded (a minute at most), then a
    // moment more: what it does while its lab still runs is the lab's own.
    for (int i = 0; i < 1200 && kill(lab, 0) == 0; ++i) usleep(50 * 1000);
    sleep(1);
    write_text(write_dir + "/daemon-was-here.txt", "the lab's daemon outlived it\n");
    _exit(0);
}

// Adds 1 to the first number found in `j`.
bool nudge(json& j) {
    if (j.is_number()) {
        j = j.get<double>() + 1.0;
        return true;
    }
    if (j.is_array())
        for (json& e : j)
            if (nudge(e)) return true;
    return false;
}

// A 4x4 matrix (four columns of four) transposed in place; other values stay.
void transpose(json& j) {
    if (!j.is_array() || j.size() != 4) return;
    for (const json& column : j)
        if (!column.is_array() || column.size() != 4) return;
    const json m = j;
    for (size_t c = 0; c < 4; ++c)
        for (size_t r = 0; r < 4; ++r) j[c][r] = m[r][c];
}

void snoop(const std::string& read_path, const std::string& write_dir) {
    int fd = open(read_path.c_str(), O_RDONLY);
    std::printf("snoop: read %s: %s\n", read_path.c_str(),
                fd >= 0 ? "ALLOWED" : std::strerror(errno));
    if (fd >= 0) close(fd);
    const std::string target = write_dir + "/planted.txt";
    fd = open(target.c_str(), O_WRONLY | O_CREAT, 0644);
    std::printf("snoop: write %s: %s\n", target.c_str(),
                fd >= 0 ? "ALLOWED" : std::strerror(errno));
    if (fd >= 0) close(fd);
}

// `lab grade-child` arguments for some of the jobs: {lab, "grade-child",
// --job J --out D for each, --backend B when given}.
struct ChildArgs {
    std::vector<std::string> args;
    std::vector<char*> argv() {
        std::vector<char*> v;
        for (std::string& a : args) v.push_back(a.data());
        v.push_back(nullptr);
        return v;
    }
};

// The target's misbehaviour (the modes above); its exit status when it
// returns.
int misbehave(const std::string& mode, const json& job, const std::string& out,
              std::vector<char*> target_argv, int output_fd) {
    const json renders = job.value("renders", json::array());
    const json units = job.value("units", json::array());
    std::printf("fake_lab: %s for lab %s\n", mode.c_str(), job.value("lab", "").c_str());
    std::fflush(stdout);

    auto send = [output_fd](const std::string& bytes) {
        if (write(output_fd, bytes.data(), bytes.size()) != static_cast<ssize_t>(bytes.size()))
            std::printf("fake_lab: write to the output descriptor: %s\n", std::strerror(errno));
    };
    if (mode == "quick") {
        return 0;
    } else if (mode == "stream_garbage") {
        send("garbage instead of a record\n");
    } else if (mode == "stream_outside") {
        send("OUTPUT 8 /etc/planted.txt\nplanted\n");
    } else if (mode == "stream_flood") {
        const std::string chunk(1 << 20, 'x');
        for (long i = 0;; ++i)
            send("OUTPUT " + std::to_string(chunk.size()) + " " + out + "/flood" +
                 std::to_string(i) + ".bin\n" + chunk);
    } else if (mode == "stream_cut") {
        const std::string name = renders.empty() ? "none" : renders[0].value("name", "");
        send("OUTPUT 1000 " + out + "/" + name + ".pam\nP7\nWIDTH 64\n");
    } else if (mode == "segv") {
        std::signal(SIGSEGV, SIG_DFL);  // not a sanitizer's report: the plain signal
        std::raise(SIGSEGV);
    } else if (mode == "hang") {
        for (;;) pause();
    } else if (mode == "exit_segv") {
        run_real(target_argv.data());
        std::signal(SIGSEGV, SIG_DFL);
        std::raise(SIGSEGV);
    } else if (mode == "spew") {
        const std::string chunk(1 << 20, 'x');
        for (;;) std::fwrite(chunk.data(), 1, chunk.size(), stdout);
    } else if (mode == "bigfile") {
        std::signal(SIGXFSZ, SIG_DFL);
        std::ofstream big(out + "/big.bin", std::ios::binary);
        const std::string chunk(1 << 20, 'x');
        for (int i = 0; i < 1024 && big; ++i)
            big.write(chunk.data(), static_cast<std::streamsize>(chunk.size()));
    } else if (mode == "fill") {
        const std::string chunk(1 << 20, 'x');
        for (long i = 0;; ++i) std::ofstream(out + "/fill" + std::to_string(i) + ".bin") << chunk;
    } else if (mode == "garbage") {
        bool first = true;
        for (const json& r : renders) {
            const std::string base = out + "/" + r.value("name", "");
            if (first) {
                // The header of a 100000 x 100000 frame, then nothing.
                write_text(base + ".pam",
                           "P7\nWIDTH 100000\nHEIGHT 100000\nDEPTH 4\nMAXVAL 255\n"
                           "TUPLTYPE RGB_ALPHA\nENDHDR\n");
            } else {
                write_text(base + ".pam", "garbage instead of a PAM");
            }
            first = false;
            write_text(base + ".pfm", "garbage");
            write_text(base + ".stats.json", "{not json");
        }
        write_text(out + "/units.json", "garbage");
    } else if (mode == "liar") {
        for (const json& r : renders) {
            const std::string base = out + "/" + r.value("name", "");
            fw::write_pam(base + ".pam",
                          fw::Image(r.value("width", 512), r.value("height", 512), {0, 0, 0, 255}));
            write_text(base + ".stats.json", json{{"params", r.value("params", json::object())},
                                                  {"passed", true},
                                                  {"score", 1000},
                                                  {"primitives_generated", 0}}
                                                 .dump());
        }
        json claims = json::object();
        for (const json& u : units) {  // the calls of one function: ids u<first>, ...
            const long first = u.value("first", 0L);
            for (size_t k = 0; k < u.value("args", json::array()).size(); ++k)
                claims["u" + std::to_string(first + static_cast<long>(k))] = {{"result", "perfect"},
                                                                              {"passed", true}};
        }
        write_text(out + "/units.json", claims.dump());
        write_text(out + "/child.json",
                   json{{"complete", true}, {"all_checks_passed", true}}.dump());
    } else if (mode == "symlink") {
        for (const json& r : renders) {
            const std::string name = r.value("name", "");
            if (symlink((env("FAKE_LAB_REFERENCES") + "/" + name + ".png").c_str(),
                        (out + "/" + name + ".pam").c_str()) != 0)
                std::perror("fake_lab: symlink");
        }
    } else if (mode == "wrong_unit") {
        const int rc = run_real(target_argv.data());
        std::ifstream results_in(out + "/units.json");
        json results = json::parse(results_in, nullptr, false);
        for (auto& [id, entry] : results.items())
            if (entry.contains("result")) nudge(entry["result"]);
        write_text(out + "/units.json", results.dump());
        return rc;
    } else if (mode == "transposed_unit") {
        const int rc = run_real(target_argv.data());
        std::ifstream results_in(out + "/units.json");
        json results = json::parse(results_in, nullptr, false);
        for (auto& [id, entry] : results.items())
            if (entry.contains("result")) transpose(entry["result"]);
        write_text(out + "/units.json", results.dump());
        return rc;
    } else if (mode == "cache") {
        const std::string dir = env("MESA_SHADER_CACHE_DIR");
        const bool inside = !dir.empty() && dir.rfind(out + "/", 0) == 0;
        int files = 0, writable = 0;
        std::error_code ec;
        for (const auto& e : std::filesystem::recursive_directory_iterator(dir, ec))
            if (e.is_regular_file()) {
                ++files;
                writable += access(e.path().c_str(), R_OK | W_OK) == 0;
            }
        write_text(env("FAKE_LAB_REPORT"),
                   "cache: " + dir + ", " + (inside ? "inside" : "outside") +
                       " the work directory\ncache: " + std::to_string(writable) + " of " +
                       std::to_string(files) + " files writable\n");
        write_text(dir + "/planted.txt", "planted\n");
        return run_real(target_argv.data());
    } else if (mode == "network") {
        return try_network(std::atoi(env("FAKE_LAB_PORT").c_str()));
    } else if (mode == "ptrace") {
        return try_ptrace();
    } else if (mode == "daemon") {
        leave_daemon(env("FAKE_LAB_SNOOP_WRITE"));
        return run_real(target_argv.data());
    } else if (mode == "forkbomb") {
        const int wanted = std::atoi(env("FAKE_LAB_FORKS").c_str());
        int made = 0;
        for (; made < wanted; ++made) {
            const pid_t pid = fork();
            if (pid < 0) {
                std::printf("forkbomb: fork %d failed: %s\n", made + 1, std::strerror(errno));
                break;
            }
            if (pid == 0) {
                for (;;) pause();
            }
        }
        std::printf("forkbomb: made %d of %d processes\n", made, wanted);
        std::fflush(stdout);
        _exit(3);  // no exit handlers: a sanitizer's leak check cannot start a thread now
    } else if (mode == "alloc") {
        // 16 GiB: in one piece, then (FAKE_LAB_TOUCH=1) 256 MiB at a time,
        // each written to, so that it is really resident.
#if defined(__SANITIZE_ADDRESS__)
        // (AddressSanitizer's allocator aborts where malloc would fail.)
        std::printf("alloc: 16 GiB at once: not tried under AddressSanitizer\n");
#else
        // volatile: a malloc whose pointer is only tested and freed may be
        // left out by the compiler (GCC 16 does), and then "GOT IT" is a lie.
        void* volatile whole = std::malloc(size_t{16} << 30);
        std::printf("alloc: 16 GiB at once: %s\n", whole ? "GOT IT" : "refused");
        std::free(whole);
#endif
        if (env("FAKE_LAB_TOUCH") == "1") {
            size_t got = 0;
            for (; got < 64; ++got) {
                char* piece = static_cast<char*>(std::malloc(size_t{256} << 20));
                if (!piece) break;
                std::memset(piece, 1, size_t{256} << 20);
                std::printf("alloc: %zu MiB resident\n", (got + 1) * 256);
                std::fflush(stdout);
            }
            std::printf("alloc: stopped at %zu MiB: %s\n", got * 256, std::strerror(errno));
        }
        return 3;
    } else if (mode == "fds") {
        std::vector<int> opened;
        for (int fd; (fd = open("/dev/null", O_RDONLY)) >= 0;) opened.push_back(fd);
        std::printf("fds: opened %zu, then: %s\n", opened.size(), std::strerror(errno));
        for (const int fd : opened) close(fd);
        return 3;
    } else if (mode == "longline") {
        const std::string line(10 << 20, 'y');  // 10 MiB, no newline
        std::fwrite(line.data(), 1, line.size(), stdout);
        return 3;
    } else if (mode == "notutf8") {
        std::printf("notutf8: \xff\xfe bad \xc3\x28 bytes, \x1b[31mred\x1b[0m, <b>&amp;</b>\n");
        std::fflush(stdout);
        return run_real(target_argv.data());
    } else if (mode == "outside") {
        // Writes where a lab has no business (the test names the files:
        // beside the references, into the report directory, ...).
        std::istringstream paths(env("FAKE_LAB_OUTSIDE"));
        for (std::string path; std::getline(paths, path, ':');) {
            std::ofstream f(path);
            f << "planted\n";
            std::printf("outside: write %s: %s\n", path.c_str(),
                        f ? "WRITTEN" : std::strerror(errno));
        }
        return 3;
    } else if (mode == "cgroups") {
        // Where it runs, for the test (a passing lab's output is not shown).
        std::ifstream groups("/proc/self/cgroup");
        std::string text;
        for (std::string line; std::getline(groups, line);) text += "cgroups: " + line + "\n";
        write_text(env("FAKE_LAB_REPORT"), text);
        return run_real(target_argv.data());
    } else if (mode == "snoop") {
        snoop(env("FAKE_LAB_SNOOP_READ"), env("FAKE_LAB_SNOOP_WRITE"));
        return 3;
    } else {
        std::fprintf(stderr, "fake_lab: unknown FAKE_LAB_MODE '%s'\n", mode.c_str());
        return 64;
    }
    return 0;
}

}  // namespace

int main(int argc, char** argv) {
    // Every --job/--out pair (course gives several when one child grades
    // several labs), and --backend.
    std::vector<std::pair<std::string, std::string>> pairs;
    std::string backend;
    int output_fd = -1, gate_fd = -1;
    std::vector<char*> ungated = {argv[0]};  // argv without --job-gate-fd
    for (int i = 1; i < argc; ++i)
        if (std::string(argv[i]) == "--job-gate-fd" && i + 1 < argc)
            gate_fd = std::atoi(argv[++i]);
        else
            ungated.push_back(argv[i]);
    ungated.push_back(nullptr);
    for (int i = 1; i + 1 < argc; ++i) {
        if (std::string(argv[i]) == "--output-fd") output_fd = std::atoi(argv[i + 1]);
        if (std::string(argv[i]) == "--job") pairs.push_back({argv[i + 1], ""});
        if (std::string(argv[i]) == "--out" && !pairs.empty()) pairs.back().second = argv[i + 1];
        if (std::string(argv[i]) == "--backend") backend = argv[i + 1];
    }
    const std::string mode = env("FAKE_LAB_MODE");
    // Course writes the jobs after the start: every one, before any is read.
    for (size_t k = 0; gate_fd >= 0 && k < pairs.size(); ++k) {
        char byte = 0;
        if (read(gate_fd, &byte, 1) != 1) {
            std::fprintf(stderr, "fake_lab: the job gate ended before job %zu\n", k);
            return 65;
        }
    }
    // The target's job, and the real lab's arguments for the others.
    json job;
    std::string out;
    ChildArgs target{{real_lab(), "grade-child"}}, before{{real_lab(), "grade-child"}},
        after{{real_lab(), "grade-child"}};
    std::string ran = "ran:";
    for (const auto& [path, dir] : pairs) {
        std::ifstream in(path);
        const json j = json::parse(in, nullptr, false);
        ran += " " + (j.is_object() ? j.value("lab", "?") : std::string("?"));
        const bool hit =
            !mode.empty() && j.is_object() && j.value("lab", "") == env("FAKE_LAB_TARGET");
        if (hit) {
            job = j;
            out = dir;
        }
        ChildArgs& to = hit ? target : job.is_null() ? before : after;
        to.args.insert(to.args.end(), {"--job", path, "--out", dir});
    }
    if (!env("FAKE_LAB_MARK").empty())
        std::ofstream(env("FAKE_LAB_MARK"), std::ios::app) << ran << "\n";
    if (!backend.empty())
        for (ChildArgs* a : {&target, &before, &after})
            a->args.insert(a->args.end(), {"--backend", backend});
    if (job.is_null()) {
        const std::string real = real_lab();
        execv(real.c_str(), ungated.data());
        std::perror(("fake_lab: exec " + real).c_str());
        return 127;
    }
    // In the child's order: the labs before the target as the real lab
    // grades them, the target misbehaving, and, when it returns 0, the labs
    // after it.
    if (before.args.size() > 2) run_real(before.argv().data());
    const int rc = misbehave(mode, job, out, target.argv(), output_fd);
    return rc == 0 && after.args.size() > 2 ? run_real(after.argv().data()) : rc;
}
