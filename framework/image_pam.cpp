// PAM (netpbm's P7): the raw frames a grading child hands to course, so that
// nothing is compressed by the child or decompressed by course. The header
// is text, the pixels follow as they are, top row first (netpbm's order):
//
//   P7\nWIDTH 512\nHEIGHT 512\nDEPTH 4\nMAXVAL 255\nTUPLTYPE RGB_ALPHA\nENDHDR\n<w*h*4 bytes>
//
// Reading is strict (course reads files a submission wrote): exactly those
// header lines, each once, sizes within 1..65536, and exactly the bytes the
// sizes call for. (pam_header_size reports any size the header states, so
// that a caller can say which size it expected instead.)
#include <cerrno>
#include <cstring>
#include <fstream>
#include <map>

#include "framework/error.hpp"
#include "framework/image.hpp"

namespace fw {

namespace {

void check_encodable(const Image& img) {
    if (img.width <= 0 || img.height <= 0 ||
        img.pixels.size() != static_cast<size_t>(img.width) * img.height)
        throw Error("cannot encode a PAM of an image " + std::to_string(img.width) + "x" +
                    std::to_string(img.height) + " with " + std::to_string(img.pixels.size()) +
                    " pixels");
}

}  // namespace

std::string pam_header(const Image& img) {
    check_encodable(img);
    return "P7\nWIDTH " + std::to_string(img.width) + "\nHEIGHT " + std::to_string(img.height) +
           "\nDEPTH 4\nMAXVAL 255\nTUPLTYPE RGB_ALPHA\nENDHDR\n";
}

std::string encode_pam(const Image& img) {
    std::string bytes = pam_header(img);
    const size_t header = bytes.size(), row = static_cast<size_t>(img.width) * 4;
    bytes.resize(header + row * img.height);
    for (int y = 0; y < img.height; ++y)  // bottom-first storage, top row first in the file
        std::memcpy(&bytes[header + row * (img.height - 1 - y)], &img.at(0, y), row);
    return bytes;
}

void write_pam(const std::string& path, const Image& img) {
    const std::string bytes = encode_pam(img);
    std::ofstream out(path, std::ios::binary);
    if (!out)
        throw Error("cannot write PAM '" + path + "': " + std::strerror(errno) +
                    "; check that its directory exists and is writable");
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
    out.close();
    if (!out) throw Error("cannot write PAM '" + path + "': write failed (disk full?)");
}

namespace {

// The header's sizes and where the pixels start; false with `why` when the
// header is not exactly what encode_pam writes (fields in any order).
bool parse_header(std::string_view bytes, int& width, int& height, size_t& pixels,
                  std::string& why) {
    if (bytes.compare(0, 3, "P7\n") != 0) {
        why = "not a PAM file (no 'P7' line)";
        return false;
    }
    std::map<std::string, std::string> fields;
    size_t pos = 3;
    for (;;) {
        const size_t end = bytes.find('\n', pos);
        if (end == std::string_view::npos || end - pos > 64 || pos > 512) {
            why = "header without an ENDHDR line";
            return false;
        }
        const std::string line(bytes.substr(pos, end - pos));
        pos = end + 1;
        if (line == "ENDHDR") break;
        const size_t space = line.find(' ');
        const std::string key = line.substr(0, space);
        if (space == std::string::npos || (key != "WIDTH" && key != "HEIGHT" && key != "DEPTH" &&
                                           key != "MAXVAL" && key != "TUPLTYPE")) {
            why = "unexpected header line \"" + line + "\"";
            return false;
        }
        if (!fields.emplace(key, line.substr(space + 1)).second) {
            why = key + " given twice";
            return false;
        }
    }
    if (fields.size() != 5) {
        why = "the header needs WIDTH, HEIGHT, DEPTH, MAXVAL and TUPLTYPE";
        return false;
    }
    if (fields["DEPTH"] != "4" || fields["MAXVAL"] != "255" || fields["TUPLTYPE"] != "RGB_ALPHA") {
        why = "DEPTH " + fields["DEPTH"] + ", MAXVAL " + fields["MAXVAL"] + ", TUPLTYPE " +
              fields["TUPLTYPE"] + "; only 8-bit RGB_ALPHA (DEPTH 4, MAXVAL 255) is read";
        return false;
    }
    for (const char* key : {"WIDTH", "HEIGHT"}) {
        const std::string& text = fields[key];
        const bool digits = !text.empty() && text.size() <= 9 &&
                            text.find_first_not_of("0123456789") == std::string::npos;
        const long v = digits ? std::stol(text) : 0;
        if (v < 1) {
            why = std::string(key) + " \"" + text + "\" is not a size (a whole number from 1)";
            return false;
        }
        (key[0] == 'W' ? width : height) = static_cast<int>(v);  // at most 9 digits
    }
    pixels = pos;
    return true;
}

}  // namespace

bool pam_header_size(std::string_view bytes, int& width, int& height) {
    size_t pixels = 0;
    std::string why;
    return parse_header(bytes, width, height, pixels, why);
}

Image decode_pam(std::string_view bytes, const std::string& name) {
    int w = 0, h = 0;
    size_t pos = 0;
    std::string why;
    if (!parse_header(bytes, w, h, pos, why)) throw Error("cannot read PAM '" + name + "': " + why);
    if (w > 65536 || h > 65536)
        throw Error("cannot read PAM '" + name + "': " + std::to_string(w) + "x" +
                    std::to_string(h) + " is over the limit of 65536 pixels a side");
    const size_t row = static_cast<size_t>(w) * 4, need = row * h;
    if (bytes.size() - pos != need)
        throw Error("cannot read PAM '" + name + "': " + std::to_string(w) + "x" +
                    std::to_string(h) + " needs " + std::to_string(need) +
                    " bytes of pixels; the file has " + std::to_string(bytes.size() - pos));
    Image img(w, h);
    for (int y = 0; y < h; ++y) std::memcpy(&img.at(0, y), &bytes[pos + row * (h - 1 - y)], row);
    return img;
}

}  // namespace fw
