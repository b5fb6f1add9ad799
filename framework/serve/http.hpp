// The HTTP plumbing of `lab serve` (server.cpp), on CivetWeb: a response
// with the headers every page and API reply carries, an error as JSON that
// says what is wrong, and a query string taken apart.
#pragma once

#include <string>
#include <utility>
#include <vector>

struct mg_connection;

namespace fw {

// One whole response: status line, Content-Type, Content-Length, no caching,
// nosniff, `extra_headers` (each ending in "\r\n") and the body; the
// connection closes after it.
void reply(mg_connection* conn, int status, const std::string& mime, const std::string& body,
           const std::string& extra_headers = "");
// {"error": message} with `status`.
void reply_error(mg_connection* conn, int status, const std::string& message);

// "a=1&b=two" -> {a: "1", b: "two"}, URL-decoded; throws UsageError for text
// that is not URL-encoded.
std::vector<std::pair<std::string, std::string>> query_pairs(const char* query);

}  // namespace fw
