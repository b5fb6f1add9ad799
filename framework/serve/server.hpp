// `lab serve` (docs/contract.md, `lab serve`): a lab rendered offscreen and
// shown live in a browser page, over CivetWeb (HTTP and WebSocket).
#pragma once

#include <string>

namespace fw {

struct ServeOptions {
    std::string lab;
    std::string host = "127.0.0.1";
    int port = 8080;  // 0: any free port (the printed URL says which)
    int width = 800, height = 600;
    std::string backend;  // empty: $LAB_BACKEND, else auto
};

// Serves until SIGINT or SIGTERM; throws UsageError or EnvironmentError when
// it cannot start (unknown lab, bad host, port in use, no GL context).
void serve(const ServeOptions& options);

// The page's files, embedded at build time from framework/serve/page/:
// the content and MIME type of `path` ("/", "/serve.js", ...), or null.
struct PageAsset {
    const char* path;
    const char* mime;
    const unsigned char* data;
    unsigned long size;
};
const PageAsset* find_page_asset(const std::string& path);

}  // namespace fw
