#include "tests/tools/serve_support.hpp"

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <regex>
#include <thread>

#include "tests/support/test_support.hpp"

namespace serve_test {

namespace {

using Clock = std::chrono::steady_clock;

// Appends what `fd` has to `text`, waiting up to `ms`; false at end of file.
bool read_some(int fd, std::string& text, int ms) {
    pollfd p{fd, POLLIN, 0};
    if (poll(&p, 1, ms) <= 0) return true;
    char buf[4096];
    const ssize_t n = read(fd, buf, sizeof buf);
    if (n <= 0) return false;
    text.append(buf, static_cast<size_t>(n));
    return true;
}

int connect_local(int port) {
    const int fd = socket(AF_INET, SOCK_STREAM | SOCK_CLOEXEC, 0);
    if (fd < 0) return -1;
    sockaddr_in addr{};
    addr.sin_family = AF_INET;
    addr.sin_port = htons(static_cast<uint16_t>(port));
    addr.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    if (connect(fd, reinterpret_cast<sockaddr*>(&addr), sizeof addr) != 0) {
        close(fd);
        return -1;
    }
    return fd;
}

bool write_all(int fd, const std::string& bytes) {
    size_t done = 0;
    while (done < bytes.size()) {
        const ssize_t n = write(fd, bytes.data() + done, bytes.size() - done);
        if (n <= 0) return false;
        done += static_cast<size_t>(n);
    }
    return true;
}

}  // namespace

Served::Served(const std::vector<std::string>& args, const std::vector<std::string>& env) {
    int fds[2];
    REQUIRE(pipe2(fds, O_CLOEXEC) == 0);
    std::vector<std::string> argv = {fw::test::bin_dir() + "/lab", "serve"};
    argv.insert(argv.end(), args.begin(), args.end());
    argv.insert(argv.end(), {"--port", "0"});
    pid_ = fork();
    REQUIRE(pid_ >= 0);
    if (pid_ == 0) {
        dup2(fds[1], 1);
        dup2(fds[1], 2);
        for (const std::string& e : env) putenv(const_cast<char*>(e.c_str()));
        std::vector<char*> cargv;
        for (const std::string& a : argv) cargv.push_back(const_cast<char*>(a.c_str()));
        cargv.push_back(nullptr);
        execv(cargv[0], cargv.data());
        _exit(127);
    }
    close(fds[1]);
    out_ = fds[0];
    const std::regex url(R"(http://127\.0\.0\.1:(\d+)/)");
    const auto deadline = Clock::now() + std::chrono::seconds(30);
    std::smatch m;
    while (Clock::now() < deadline && !std::regex_search(printed_, m, url))
        if (!read_some(out_, printed_, 100)) break;
    INFO("lab serve printed: " << printed_);
    REQUIRE_MESSAGE(std::regex_search(printed_, m, url), "lab serve printed no URL");
    port_ = std::stoi(m[1].str());
}

Served::~Served() {
    if (pid_ > 0) {
        std::string ignored;
        stop(SIGKILL, ignored);
    }
    if (out_ >= 0) close(out_);
}

int Served::stop(int signal, std::string& output) {
    if (pid_ <= 0) return -1;
    kill(pid_, signal);
    const auto deadline = Clock::now() + std::chrono::seconds(10);
    int status = 0;
    pid_t done = 0;
    while ((done = waitpid(pid_, &status, WNOHANG)) == 0 && Clock::now() < deadline)
        read_some(out_, printed_, 50);
    if (done == 0) {
        kill(pid_, SIGKILL);
        waitpid(pid_, &status, 0);
        status = -1;
    }
    for (int i = 0; i < 100 && read_some(out_, printed_, 100); ++i) {  // what is left, to its end
    }
    pid_ = -1;
    output = printed_;
    return status;
}

std::string http_raw(int port, const std::string& request) {
    const int fd = connect_local(port);
    if (fd < 0) return {};
    std::string response;
    if (write_all(fd, request))
        while (read_some(fd, response, 5000)) {
        }
    close(fd);
    return response;
}

int status_of(const std::string& response) {
    std::smatch m;
    static const std::regex status(R"(^HTTP/1\.[01] (\d{3}))");
    return std::regex_search(response, m, status) ? std::stoi(m[1].str()) : 0;
}

int stalled_websocket(int port) {
    const int ws = connect_local(port);
    if (ws < 0) return -1;
    const int small = 1;  // the kernel raises it to its minimum
    setsockopt(ws, SOL_SOCKET, SO_RCVBUF, &small, sizeof small);
    const std::string handshake =
        "GET /ws HTTP/1.1\r\nHost: 127.0.0.1\r\nUpgrade: websocket\r\nConnection: Upgrade\r\n"
        "Sec-WebSocket-Key: dGhlIHNhbXBsZSBub25jZQ==\r\nSec-WebSocket-Version: 13\r\n\r\n";
    std::string reply;
    if (!write_all(ws, handshake)) {
        close(ws);
        return -1;
    }
    const auto deadline = Clock::now() + std::chrono::seconds(5);
    while (reply.find("\r\n\r\n") == std::string::npos && Clock::now() < deadline)
        if (!read_some(ws, reply, 100)) break;
    if (status_of(reply) != 101) {
        close(ws);
        return -1;
    }
    return ws;
}

}  // namespace serve_test
