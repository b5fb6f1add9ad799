// A checkpoint's frame as the child wrote it (NAME.pam: raw pixels, see
// framework/image_pam.cpp), read with the suspicion due to anything a
// submission produced: size-limited, the header checked before anything else,
// decoded from the bytes read once.
#include <cstdio>

#include "framework/error.hpp"
#include "grading/judge/checks.hpp"

namespace grading {

namespace {

// Shown when a file does not start like a PAM: its first bytes, escaped.
std::string first_bytes(std::string_view bytes) {
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
                   std::string& why) {
    const std::string name = render.checkpoint + ".pam";
    // 4 bytes a pixel and a header of a few lines.
    const std::uint64_t limit = std::uint64_t(render.width) * render.height * 4 + 1024;
    std::string storage;
    std::string_view bytes;  // the record the child sent, not a copy of it
    if (!outputs.read_view(name, limit, bytes, storage, why)) return false;
    int w = 0, h = 0;
    if (!fw::pam_header_size(bytes, w, h)) {
        why = name + " is not a PAM file: it starts with " + first_bytes(bytes);
        return false;
    }
    // The size in the header, checked before anything else.
    if (w != render.width || h != render.height) {
        why = name + " is " + std::to_string(w) + "x" + std::to_string(h) +
              ", but course asked for " + std::to_string(render.width) + "x" +
              std::to_string(render.height);
        return false;
    }
    try {
        // Decoded from the bytes read (and size-checked) above, never from the
        // file again: a process the child left behind could have replaced it.
        image = fw::decode_pam(bytes, name);
    } catch (const fw::Error& e) {
        why = e.what();
        return false;
    }
    return true;
}

}  // namespace grading
