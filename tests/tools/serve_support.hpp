// `lab serve` as a real child process, and the plain sockets the tests speak
// to it with: raw HTTP requests (so that a request a browser would never
// send, like a path with "..", reaches the server as written) and a
// WebSocket client that connects and then never reads.
#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

namespace serve_test {

class Served {
public:
    // Starts `lab serve ARGS... --port 0` with `env` ("NAME=value") added and
    // waits for the URL it prints; fails the test case when it does not
    // come within 30 s.
    Served(const std::vector<std::string>& args, const std::vector<std::string>& env = {});
    ~Served();
    Served(const Served&) = delete;
    Served& operator=(const Served&) = delete;

    int port() const { return port_; }
    std::string url() const { return "http://127.0.0.1:" + std::to_string(port_) + "/"; }
    // Sends `signal`, waits up to 10 s for the exit; its wait status (or -1
    // when it had to be killed) and everything it printed.
    int stop(int signal, std::string& output);

private:
    pid_t pid_ = -1;
    int out_ = -1;
    int port_ = 0;
    std::string printed_;
};

// Sends `request` as written and returns the whole response ("" when the
// connection fails).
std::string http_raw(int port, const std::string& request);
// The status code of a response ("HTTP/1.1 404 ..." -> 404), 0 for none.
int status_of(const std::string& response);

// Opens a WebSocket to /ws with the smallest receive buffer the kernel
// allows, completes the handshake and reads nothing more: a client that has
// stopped reading. Returns its socket (close it to end it), or -1.
int stalled_websocket(int port);

}  // namespace serve_test
