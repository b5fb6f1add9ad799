// A checkpoint's frame as the child wrote it (NAME.png), read with the
// suspicion due to anything a submission produced: size-limited, the PNG
// header checked before decoding, decoded from the bytes read once.
#include <cstdio>

#include "framework/error.hpp"
#include "grading/checks.hpp"

namespace grading {

namespace {

// Shown when a file does not start like a PNG: its first bytes, escaped.
std::string first_bytes(const std::string& bytes) {
    std::string s;
    for (size_t i = 0; i < bytes.size() && i < 16; ++i) {
        unsigned char c = static_cast<unsigned char>(bytes[i]);
        char buf[8];
        std::snprintf(buf, sizeof buf, c >= 32 && c < 127 && c != '"' ? "%c" : "\\x%02x", c);
        s += buf;
    }
    return "\"" + s + "\"";
}

}  // namespace

bool read_rendered(const ChildOutputs& outputs, const RenderPlan& render, fw::Image& image,
                   std::string& why, std::string* png_bytes) {
    const std::string name = render.checkpoint + ".png";
    // An uncompressed PNG: 4 bytes a pixel, a filter byte a row, chunk overhead.
    const std::uint64_t limit =
        std::uint64_t(render.width) * render.height * 4 + render.height + kMiB;
    std::string bytes;
    if (!outputs.read(name, limit, bytes, why)) return false;
    int w = 0, h = 0;
    if (!fw::png_header_size(bytes, w, h)) {
        why = name + " is not a PNG: it starts with " + first_bytes(bytes);
        return false;
    }
    // The size in the header, checked before decoding anything.
    if (w != render.width || h != render.height) {
        why = name + " is " + std::to_string(w) + "x" + std::to_string(h) +
              ", but course asked for " + std::to_string(render.width) + "x" +
              std::to_string(render.height);
        return false;
    }
    try {
        // Decoded from the bytes read (and size-checked) above, never from the
        // file again: a process the child left behind could have replaced it.
        image = fw::decode_png(bytes, name);
    } catch (const fw::Error& e) {
        why = name + " is not a PNG: " + e.what();
        return false;
    }
    if (png_bytes) *png_bytes = std::move(bytes);
    return true;
}

}  // namespace grading
