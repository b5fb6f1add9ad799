// bench_serve: what `lab serve` delivers to one client, per lab, at 800x600.
// For each lab a real `lab serve` child is started; a WebSocket client
// asks it to play and counts the frames that arrive in SECONDS
// seconds (frames per second), then changes a parameter ROUNDS times and
// times each change from the message sent to the new frame's last byte
// (latency). Beside it, the floor: the same frames rendered and JPEG-encoded
// in this process with no server (the renderer and the encoder alone), and
// the latency as a ratio of the floor's time per frame. Goals: >= 30 fps and
// <= 100 ms for every lab.
// Prints figures; not a test.
//
//   bench_serve [SECONDS=3] [ROUNDS=20] [LAB...]     (backend: $LAB_BACKEND, else auto)
#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <signal.h>
#include <spawn.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "framework/context.hpp"
#include "framework/error.hpp"
#include "framework/image.hpp"
#include "framework/lab.hpp"
#include "framework/render.hpp"

extern char** environ;

namespace {

using nlohmann::json;
using Clock = std::chrono::steady_clock;

double ms_since(Clock::time_point t) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t).count();
}

int free_port() {
    const int fd = socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    socklen_t len = sizeof addr;
    bind(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr);
    getsockname(fd, reinterpret_cast<sockaddr*>(&addr), &len);
    close(fd);
    return ntohs(addr.sin_port);
}

// What the client has received, shared with its reading thread.
struct Received {
    std::mutex m;
    std::condition_variable cv;
    int frames = 0;                  // binary messages (images)
    std::uint64_t last_version = 0;  // of the frame whose image came last
    std::uint64_t meta_version = 0;  // of the latest frame message
    std::uint64_t acked = 0;         // the version of the latest ack
    bool closed = false;
};

bool read_exact(int fd, void* out, size_t n) {
    auto* p = static_cast<char*>(out);
    while (n > 0) {
        const ssize_t got = read(fd, p, n);
        if (got <= 0) return false;
        p += got;
        n -= static_cast<size_t>(got);
    }
    return true;
}

// A minimal WebSocket client (RFC 6455) on a socket with TCP_NODELAY, as a
// browser's: each message leaves in one write, so that the figures are the
// server's and not Nagle's.
class Socket {
public:
    explicit Socket(int port) {
        fd_ = socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
        sockaddr_in addr{};
        addr.sin_family = AF_INET;
        addr.sin_port = htons(static_cast<uint16_t>(port));
        addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
        if (connect(fd_, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0) return;
        const int one = 1;
        setsockopt(fd_, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
        const std::string hello =
            "GET /ws HTTP/1.1\r\nHost: 127.0.0.1\r\nUpgrade: websocket\r\nConnection: "
            "Upgrade\r\nSec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: "
            "13\r\n\r\n";
        if (write(fd_, hello.data(), hello.size()) != static_cast<ssize_t>(hello.size())) return;
        std::string reply;
        char c;
        while (reply.find("\r\n\r\n") == std::string::npos && read_exact(fd_, &c, 1)) reply += c;
        ok_ = reply.rfind("HTTP/1.1 101", 0) == 0;
    }
    ~Socket() {
        if (fd_ >= 0) close(fd_);
        if (reader_.joinable()) reader_.join();
    }
    bool ok() const { return ok_; }
    void send(const json& message) {
        const std::string text = message.dump();
        std::string frame = {static_cast<char>(0x81)};  // FIN, text
        if (text.size() < 126) {
            frame += static_cast<char>(0x80 | text.size());
        } else {
            frame += static_cast<char>(0x80 | 126);
            frame += static_cast<char>(text.size() >> 8);
            frame += static_cast<char>(text.size() & 0xff);
        }
        frame += std::string(4, '\0');  // mask 0: the payload as it is
        frame += text;
        if (write(fd_, frame.data(), frame.size()) != static_cast<ssize_t>(frame.size()))
            std::fprintf(stderr, "bench_serve: a message was not sent\n");
    }
    void read_into(Received& r) {
        reader_ = std::thread([this, &r] {
            for (;;) {
                unsigned char head[2];
                if (!read_exact(fd_, head, 2)) break;
                std::uint64_t size = head[1] & 0x7f;
                if (size >= 126) {
                    unsigned char ext[8];
                    const size_t n = size == 126 ? 2 : 8;
                    if (!read_exact(fd_, ext, n)) break;
                    size = 0;
                    for (size_t i = 0; i < n; ++i) size = size << 8 | ext[i];
                }
                std::string payload(size, '\0');
                if (!read_exact(fd_, payload.data(), size)) break;
                std::lock_guard<std::mutex> lock(r.m);
                const int opcode = head[0] & 0x0f;
                if (opcode == 2) {
                    ++r.frames;
                    r.last_version = r.meta_version;
                } else if (opcode == 1) {
                    const json m = json::parse(payload, nullptr, false);
                    const std::string type = m.is_object() ? m.value("type", "") : "";
                    if (type == "frame") r.meta_version = m.value("version", 0ull);
                    if (type == "ack") r.acked = m.value("version", 0ull);
                }
                r.cv.notify_all();
            }
            std::lock_guard<std::mutex> lock(r.m);
            r.closed = true;
            r.cv.notify_all();
        });
    }
    void shut() { shutdown(fd_, SHUT_RDWR); }

private:
    int fd_ = -1;
    bool ok_ = false;
    std::thread reader_;
};

// A number parameter to change, and two values in its range.
bool pick_param(const fw::RegisteredLab& lab, std::string& name, double& a, double& b) {
    for (const fw::Param& p : lab.info.params)
        if (p.type == fw::ParamType::Float || p.type == fw::ParamType::Int) {
            name = p.name;
            a = p.min + (p.max - p.min) * 0.25;
            b = p.min + (p.max - p.min) * 0.75;
            if (p.type == fw::ParamType::Int) a = std::round(a), b = std::round(b);
            return a != b;
        }
    return false;
}

struct Figures {
    double fps = 0, latency_median = 0, latency_max = 0, floor_fps = 0;
};

Figures serve_figures(const fw::RegisteredLab& lab, const std::string& lab_exe, double seconds,
                      int rounds) {
    Figures f;
    const int port = free_port();
    const std::string port_text = std::to_string(port);
    std::vector<std::string> args = {lab_exe,   "serve",  lab.info.id, "--port",
                                     port_text, "--size", "800x600"};
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
    pid_t pid = 0;
    if (posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ) != 0)
        throw fw::Error("cannot start " + lab_exe);
    posix_spawn_file_actions_destroy(&actions);

    Received r;
    std::unique_ptr<Socket> conn;
    for (int i = 0; i < 100; ++i) {
        conn = std::make_unique<Socket>(port);
        if (conn->ok()) break;
        conn.reset();
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
    }
    if (!conn) {
        kill(pid, SIGKILL);
        waitpid(pid, nullptr, 0);
        throw fw::Error("cannot connect to lab serve " + lab.info.id);
    }
    conn->read_into(r);
    auto wait = [&](const std::function<bool()>& done, double timeout_ms) {
        std::unique_lock<std::mutex> lock(r.m);
        return r.cv.wait_for(lock, std::chrono::duration<double, std::milli>(timeout_ms), done);
    };
    wait([&] { return r.frames >= 1; }, 10000);

    // Frames per second while playing.
    conn->send({{"type", "play"}, {"on", true}});
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    int start_frames;
    {
        std::lock_guard<std::mutex> lock(r.m);
        start_frames = r.frames;
    }
    const Clock::time_point t0 = Clock::now();
    std::this_thread::sleep_for(std::chrono::duration<double>(seconds));
    {
        std::lock_guard<std::mutex> lock(r.m);
        f.fps = (r.frames - start_frames) / (ms_since(t0) / 1000.0);
    }
    conn->send({{"type", "play"}, {"on", false}});
    std::this_thread::sleep_for(std::chrono::milliseconds(300));

    // Latency of a parameter change, with the lab otherwise idle.
    std::string name;
    double a = 0, b = 0;
    std::vector<double> latencies;
    if (pick_param(lab, name, a, b)) {
        for (int i = 0; i < rounds; ++i) {
            std::uint64_t before;
            {
                std::lock_guard<std::mutex> lock(r.m);
                before = r.acked;
            }
            const Clock::time_point sent = Clock::now();
            conn->send({{"type", "set"}, {"name", name}, {"value", i % 2 ? a : b}});
            std::uint64_t version = 0;
            wait([&] { return r.acked > before; }, 5000);
            {
                std::lock_guard<std::mutex> lock(r.m);
                version = r.acked;
            }
            wait([&] { return r.last_version >= version; }, 5000);
            latencies.push_back(ms_since(sent));
            std::this_thread::sleep_for(std::chrono::milliseconds(30));
        }
        std::sort(latencies.begin(), latencies.end());
        f.latency_median = latencies[latencies.size() / 2];
        f.latency_max = latencies.back();
    }
    conn->shut();
    conn.reset();
    kill(pid, SIGTERM);
    waitpid(pid, nullptr, 0);
    return f;
}

// The same frames drawn and JPEG-encoded here, with no server: frames per
// second over `seconds`, time running as when playing.
double floor_fps(fw::OffscreenContext& context, const fw::RegisteredLab& lab, double seconds) {
    fw::LabRenderer renderer(lab, context.info());
    const fw::ParamValues params = fw::default_params(lab);
    renderer.render(params, 800, 600, 0.0, fw::ReadBack{.depth = false});
    int frames = 0;
    const Clock::time_point t0 = Clock::now();
    while (ms_since(t0) < seconds * 1000) {
        fw::RenderOutput out =
            renderer.render(params, 800, 600, ms_since(t0) / 1000.0, fw::ReadBack{.depth = false});
        const std::string jpeg = fw::encode_jpeg(out.color, 85);
        frames += jpeg.empty() ? 0 : 1;
    }
    return frames / (ms_since(t0) / 1000.0);
}

}  // namespace

int main(int argc, char** argv) {
    try {
        const double seconds = argc > 1 ? std::max(0.5, std::atof(argv[1])) : 3.0;
        const int rounds = argc > 2 ? std::max(1, std::atoi(argv[2])) : 20;
        std::vector<const fw::RegisteredLab*> labs;
        for (int i = 3; i < argc; ++i) labs.push_back(&fw::find_lab(argv[i]));
        if (labs.empty())
            for (const fw::RegisteredLab& lab : fw::registered_labs()) labs.push_back(&lab);
        char self[4096] = "";
        const ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
        if (n <= 0) throw fw::Error("cannot find bench_serve's own directory");
        std::string dir(self, static_cast<size_t>(n));
        const std::string lab_exe = dir.substr(0, dir.rfind('/')) + "/lab";

        auto context = fw::create_offscreen_context(fw::backend_from_env());
        std::printf("bench_serve: lab serve at 800x600, one client; %s, %s; %u cores\n",
                    context->info().backend.c_str(), context->info().gl_renderer.c_str(),
                    std::thread::hardware_concurrency());
        std::printf("(a playing lab is drawn every 16 ms at most: 62.5 fps is the ceiling)\n");
        std::printf("%-16s %7s %10s %11s %8s %15s %14s\n", "lab", "fps", "floor fps", "latency ms",
                    "max ms", "floor ms/frame", "latency/floor");
        bool met = true;
        for (const fw::RegisteredLab* lab : labs) {
            const Figures f = serve_figures(*lab, lab_exe, seconds, rounds);
            const double floor = floor_fps(*context, *lab, seconds);
            met = met && f.fps >= 30 && f.latency_max <= 100;
            std::printf("%-16s %7.1f %10.1f %11.1f %8.1f %15.2f %14.1f\n", lab->info.id.c_str(),
                        f.fps, floor, f.latency_median, f.latency_max, 1000 / floor,
                        f.latency_median * floor / 1000);
            std::fflush(stdout);
        }
        std::printf("goals: >= 30 fps and <= 100 ms (the slowest change) for every lab: %s\n",
                    met ? "met" : "NOT met");
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "bench_serve: %s\n", e.what());
        return 1;
    }
}
