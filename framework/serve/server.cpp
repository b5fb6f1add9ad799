// The HTTP and WebSocket side of `lab serve`, on CivetWeb. Every connection
// has a CivetWeb worker thread of its own; each WebSocket client also has a
// sender thread that sends it the newest frame whenever there is one it has
// not had, so a slow client only ever skips frames, and never holds up the
// renderer or another client.
#include "framework/serve/server.hpp"

#include <civetweb.h>
#include <pthread.h>

#include <atomic>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <map>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <set>
#include <string_view>
#include <thread>

#include "framework/context.hpp"
#include "framework/error.hpp"
#include "framework/image.hpp"
#include "framework/serve/http.hpp"
#include "framework/serve/live.hpp"
#include "framework/serve/messages.hpp"

namespace fw {

namespace {

using nlohmann::json;

// A WebSocket client: its connection and the thread that sends it frames.
struct Client : ClientFlags {
    mg_connection* conn = nullptr;
    std::thread sender;
    std::atomic<bool> closing{false};
};

class Server {
public:
    Server(LiveLab& live, std::string lab_id) : live_(live), lab_id_(std::move(lab_id)) {}

    LiveLab& live() { return live_; }
    const std::string& lab_id() const { return lab_id_; }

    // Sends one WebSocket message; false once the client is gone.
    static bool send(mg_connection* conn, int opcode, const std::string& bytes) {
        mg_lock_connection(conn);
        const int sent = mg_websocket_write(conn, opcode, bytes.data(), bytes.size());
        mg_unlock_connection(conn);
        return sent > 0;
    }
    static bool send_json(mg_connection* conn, const json& message) {
        return send(conn, MG_WEBSOCKET_OPCODE_TEXT, message.dump());
    }

    void frames_to(Client& client) {
        std::uint64_t sent = 0;
        while (!client.closing) {
            auto frame = live_.wait_frame(sent, std::chrono::milliseconds(100));
            if (!frame) continue;
            const bool png = client.png;
            json meta = {{"type", "frame"},
                         {"seq", frame->seq},
                         {"version", frame->version},
                         {"render_ms", frame->render_ms},
                         {"width", frame->color.width},
                         {"height", frame->color.height},
                         {"format", png ? "png" : "jpeg"},
                         {"params", frame->params},
                         {"stats", frame->stats},
                         {"problems", live_.problems()}};
            if (frame->color.pixels.empty()) meta["format"] = "none";
            if (!send_json(client.conn, meta)) break;
            if (!frame->color.pixels.empty() && !send(client.conn, MG_WEBSOCKET_OPCODE_BINARY,
                                                      png ? encode_png(frame->color) : frame->jpeg))
                break;
            sent = frame->seq;
        }
    }

    std::mutex clients_mutex;
    std::set<Client*> clients;

private:
    LiveLab& live_;
    std::string lab_id_;
};

int ws_connect(const mg_connection*, void*) { return 0; }

void ws_ready(mg_connection* conn, void* data) {
    auto& server = *static_cast<Server*>(data);
    auto client = std::make_unique<Client>();
    client->conn = conn;
    Server::send_json(conn, {{"type", "hello"},
                             {"lab", server.live().describe()},
                             {"problems", server.live().problems()}});
    Client* c = client.get();
    c->sender = std::thread([&server, c] { server.frames_to(*c); });
    mg_set_user_connection_data(conn, client.release());
    std::lock_guard<std::mutex> lock(server.clients_mutex);
    server.clients.insert(c);
}

int ws_data(mg_connection* conn, int bits, char* data, size_t size, void* cbdata) {
    auto& server = *static_cast<Server*>(cbdata);
    auto* client = static_cast<Client*>(mg_get_user_connection_data(conn));
    const int opcode = bits & 0x0f;
    if (opcode == MG_WEBSOCKET_OPCODE_CONNECTION_CLOSE) return 0;
    if (opcode == MG_WEBSOCKET_OPCODE_PING || opcode == MG_WEBSOCKET_OPCODE_PONG) return 1;
    if (!client) return 0;
    json id;
    try {
        if (opcode != MG_WEBSOCKET_OPCODE_TEXT)
            throw UsageError("messages must be JSON text, not binary");
        const json m = json::parse(data, data + size, nullptr, false);
        if (!m.is_object()) throw UsageError("a message must be a JSON object");
        if (m.contains("id")) id = m["id"];
        const std::uint64_t version = apply_message(server.live(), *client, m);
        Server::send_json(conn, {{"type", "ack"}, {"id", id}, {"version", version}});
    } catch (const Error& e) {
        Server::send_json(conn, {{"type", "error"}, {"id", id}, {"message", e.what()}});
    }
    return 1;
}

void ws_close(const mg_connection* conn, void* cbdata) {
    auto& server = *static_cast<Server*>(cbdata);
    auto* known =
        static_cast<Client*>(mg_get_user_connection_data(const_cast<mg_connection*>(conn)));
    {
        // Only a client still in the set is this handler's: serve() ends the
        // others itself when it stops.
        std::lock_guard<std::mutex> lock(server.clients_mutex);
        if (!known || server.clients.erase(known) == 0) return;
    }
    std::unique_ptr<Client> client(known);
    client->closing = true;
    if (client->sender.joinable()) client->sender.join();
    if (client->playing) server.live().play(false);
}

// The HTTP requests of the page and the API, by path; each replies and
// returns the status it sent.
using RouteHandler = int (*)(Server&, mg_connection*, const mg_request_info*, const std::string&);
struct Route {
    std::string_view path;
    bool post;  // POST only; every other route takes GET and HEAD
    RouteHandler serve;
};

int api_set(Server& server, mg_connection* conn, const mg_request_info* info, const std::string&) {
    const auto pairs = query_pairs(info->query_string);
    if (pairs.empty()) throw UsageError("/api/set needs name=value in its query");
    std::uint64_t version = 0;
    for (const auto& [name, value] : pairs) version = server.live().set(name, value);
    reply(conn, 200, "application/json", json{{"version", version}}.dump() + "\n");
    return 200;
}

int api_lab(Server& server, mg_connection* conn, const mg_request_info*, const std::string&) {
    json body = server.live().describe();
    body["problems"] = server.live().problems();
    if (auto frame = server.live().latest()) body["params_now"] = frame->params;
    reply(conn, 200, "application/json", body.dump() + "\n");
    return 200;
}

int frame_file(Server& server, mg_connection* conn, const mg_request_info* info,
               const std::string& path) {
    auto frame = server.live().wait_frame(0, std::chrono::seconds(10));
    if (!frame || frame->color.pixels.empty()) {
        reply_error(conn, 503, "no frame has been rendered yet");
        return 503;
    }
    const bool png = path == "/frame.png";
    std::string headers;
    for (const auto& [name, value] : query_pairs(info->query_string))
        if (name == "download")
            headers = "Content-Disposition: attachment; filename=\"" + server.lab_id() + "-" +
                      std::to_string(frame->seq) + ".png\"\r\n";
    reply(conn, 200, png ? "image/png" : "image/jpeg", png ? encode_png(frame->color) : frame->jpeg,
          headers);
    return 200;
}

const Route kRoutes[] = {{"/api/set", true, api_set},
                         {"/api/lab", false, api_lab},
                         {"/frame.jpg", false, frame_file},
                         {"/frame.png", false, frame_file}};

int http(mg_connection* conn, void* cbdata) {
    auto& server = *static_cast<Server*>(cbdata);
    const mg_request_info* info = mg_get_request_info(conn);
    const std::string method = info->request_method ? info->request_method : "";
    const std::string path = info->local_uri_raw ? info->local_uri_raw : "";
    const Route* route = nullptr;
    for (const Route& r : kRoutes)
        if (r.path == path) route = &r;
    try {
        if (route && route->post && method != "POST") {
            reply_error(conn, 405, path + " takes POST, e.g. POST " + path + "?name=value");
            return 405;
        }
        if (!(route && route->post) && method != "GET" && method != "HEAD") {
            reply_error(conn, 405, method + " " + path + ": only GET is served here");
            return 405;
        }
        if (route) return route->serve(server, conn, info, path);
        if (const PageAsset* asset = find_page_asset(path)) {
            reply(conn, 200, asset->mime,
                  std::string(reinterpret_cast<const char*>(asset->data), asset->size));
            return 200;
        }
        reply_error(conn, 404, "no such page: " + path + " (lab serve serves only its own page)");
        return 404;
    } catch (const Error& e) {
        reply_error(conn, 400, e.what());
        return 400;
    }
}

void check_host(const std::string& host) {
    const bool ok =
        !host.empty() && host.find_first_not_of("0123456789abcdefABCDEF.:[]") == std::string::npos;
    if (!ok)
        throw UsageError("--host " + host +
                         ": give an IP address, e.g. 127.0.0.1 (this machine only, the default) "
                         "or 0.0.0.0 (every network interface, as in a container)");
}

// CivetWeb listening on `ports` ("127.0.0.1:8080") with the page's and the
// WebSocket's handlers; throws fw::EnvironmentError when it cannot.
mg_context* start_civetweb(const std::string& ports, Server& server) {
    mg_init_library(0);
    if (!mg_check_feature(16)) {
        mg_exit_library();
        throw EnvironmentError("this CivetWeb library was built without WebSocket support");
    }
    // tcp_nodelay: a frame's last bytes and an ack go out at once, not after
    // the peer's delayed acknowledgement (40 ms and more per change).
    const char* mg_options[] = {
        "listening_ports", ports.c_str(), "num_threads", "32",   "request_timeout_ms",
        "10000",           "tcp_nodelay", "1",           nullptr};
    mg_callbacks callbacks{};
    mg_context* ctx = mg_start(&callbacks, &server, mg_options);
    if (!ctx) {
        mg_exit_library();
        throw EnvironmentError("cannot listen on " + ports +
                               ": the port is in use or the address is not this machine's; "
                               "choose another with --port N");
    }
    mg_set_websocket_handler(ctx, "/ws", ws_connect, ws_ready, ws_data, ws_close, &server);
    mg_set_request_handler(ctx, "/", http, &server);
    return ctx;
}

// The clients' senders end first (they use the connections and the lab);
// then CivetWeb closes the connections; what its close handlers did not take
// is freed here.
void stop_civetweb(mg_context* ctx, LiveLab& live, Server& server) {
    live.stop();
    {
        std::lock_guard<std::mutex> lock(server.clients_mutex);
        for (Client* c : server.clients) c->closing = true;
        for (Client* c : server.clients)
            if (c->sender.joinable()) c->sender.join();
    }
    mg_stop(ctx);
    {
        std::lock_guard<std::mutex> lock(server.clients_mutex);
        for (Client* c : server.clients) delete c;
        server.clients.clear();
    }
    mg_exit_library();
}

}  // namespace

void serve(const ServeOptions& options) {
    const RegisteredLab& lab = find_lab(options.lab);
    check_host(options.host);
    if (options.port < 0 || options.port > 65535)
        throw UsageError("--port " + std::to_string(options.port) + ": a port is 0 to 65535");
    const Backend backend =
        options.backend.empty() ? backend_from_env() : parse_backend(options.backend);

    // SIGINT and SIGTERM wait for sigwait below: every thread started from
    // here on inherits the blocked mask, so none of them is interrupted.
    sigset_t stop_signals;
    sigemptyset(&stop_signals);
    sigaddset(&stop_signals, SIGINT);
    sigaddset(&stop_signals, SIGTERM);
    pthread_sigmask(SIG_BLOCK, &stop_signals, nullptr);

    LiveLab live(lab, backend, options.width, options.height);
    Server server(live, lab.info.id);

    const bool v6 = options.host.find(':') != std::string::npos;
    const std::string ports =
        (v6 ? "[" + options.host + "]" : options.host) + ":" + std::to_string(options.port);
    mg_context* ctx = start_civetweb(ports, server);

    mg_server_port port{};
    const int port_count = mg_get_server_ports(ctx, 1, &port);
    const int bound = port_count > 0 ? port.port : options.port;
    const std::string shown = options.host == "0.0.0.0" ? "127.0.0.1" : options.host;
    std::printf("lab serve: %s on %s (%s)\n", lab.info.id.c_str(),
                live.describe().value("gl_renderer", "?").c_str(),
                live.describe().value("backend", "?").c_str());
    std::printf("open http://%s:%d/ in a browser; Ctrl-C stops\n",
                v6 ? ("[" + shown + "]").c_str() : shown.c_str(), bound);
    std::fflush(stdout);

    int signal = 0;
    sigwait(&stop_signals, &signal);
    std::printf("lab serve: %s, stopping\n", signal == SIGINT ? "interrupted" : "terminated");
    std::fflush(stdout);
    stop_civetweb(ctx, live, server);
}

}  // namespace fw
