// HTTP on CivetWeb for `lab serve`: responses and query strings (http.hpp).
#include "framework/serve/http.hpp"

#include <civetweb.h>

#include <nlohmann/json.hpp>

#include "framework/error.hpp"

namespace fw {

void reply(mg_connection* conn, int status, const std::string& mime, const std::string& body,
           const std::string& extra_headers) {
    const char* reason = status == 200   ? "OK"
                         : status == 400 ? "Bad Request"
                         : status == 404 ? "Not Found"
                         : status == 405 ? "Method Not Allowed"
                                         : "Service Unavailable";
    mg_printf(conn,
              "HTTP/1.1 %d %s\r\nContent-Type: %s\r\nContent-Length: %zu\r\n"
              "Cache-Control: no-store\r\nX-Content-Type-Options: nosniff\r\n%sConnection: "
              "close\r\n\r\n",
              status, reason, mime.c_str(), body.size(), extra_headers.c_str());
    mg_write(conn, body.data(), body.size());
}

void reply_error(mg_connection* conn, int status, const std::string& message) {
    reply(conn, status, "application/json", nlohmann::json{{"error", message}}.dump() + "\n");
}

std::vector<std::pair<std::string, std::string>> query_pairs(const char* query) {
    std::vector<std::pair<std::string, std::string>> pairs;
    if (!query) return pairs;
    const std::string q = query;
    size_t start = 0;
    while (start <= q.size()) {
        size_t end = q.find('&', start);
        if (end == std::string::npos) end = q.size();
        const std::string item = q.substr(start, end - start);
        if (!item.empty()) {
            const size_t eq = item.find('=');
            auto decode = [](const std::string& s) {
                std::string out(s.size() + 1, '\0');
                const int n = mg_url_decode(s.c_str(), static_cast<int>(s.size()), out.data(),
                                            static_cast<int>(out.size()), 1);
                if (n < 0) throw UsageError("the query is not URL-encoded text: '" + s + "'");
                out.resize(static_cast<size_t>(n));
                return out;
            };
            pairs.emplace_back(decode(item.substr(0, eq)),
                               eq == std::string::npos ? "" : decode(item.substr(eq + 1)));
        }
        start = end + 1;
    }
    return pairs;
}

}  // namespace fw
