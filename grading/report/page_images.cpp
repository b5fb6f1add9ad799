#include "grading/report/page_images.hpp"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "framework/image.hpp"
#include "grading/report/by_checkpoint.hpp"
#include "grading/report/report_text.hpp"

namespace grading::report {

PageImage page_image(const std::string& path) {
    PageImage image;
    std::ifstream file(path, std::ios::binary);
    if (!file) {
        image.why = std::strerror(errno);
        return image;
    }
    std::ostringstream read;
    read << file.rdbuf();
    const std::string bytes = read.str();
    if (bytes.compare(0, 8, "\x89PNG\r\n\x1a\n") != 0) {
        image.why = "not a PNG file";
        return image;
    }
    image.uri = "data:image/png;base64," + base64(bytes);
    std::string head = bytes.substr(0, 24);
    head.resize(24, '\0');
    int w = 0, h = 0;
    image.aspect = fw::png_header_size(head, w, h) && w > 0 && h > 0
                       ? std::to_string(w) + " / " + std::to_string(h)
                       : "1 / 1";
    return image;
}

std::string ImageTable::figure(const std::string& caption, const std::string& relative,
                               const std::string& none) {
    std::string body;
    if (relative.empty()) {
        body = "<div class=\"missing\">" + (none.empty() ? "no " + caption + " image" : none) +
               "</div>";
    } else {
        const Entry& e = entry(relative);
        body = e.css_class.empty()
                   ? "<div class=\"missing\">image not available: " +
                         escape_markup(relative + " (" + e.why + ")") + "</div>"
                   : "<div class=\"shot " + e.css_class + "\" role=\"img\" aria-label=\"" +
                         caption + " image\" title=\"" + escape_markup(relative) +
                         "\" style=\"aspect-ratio: " + e.aspect + "\"></div>";
    }
    return "<figure>" + body + "<figcaption>" + caption + "</figcaption></figure>";
}

const ImageTable::Entry& ImageTable::entry(const std::string& relative) {
    const auto found = entries_.find(relative);
    if (found != entries_.end()) return found->second;
    // Read ahead when the lab was judged, else now.
    const PageImage* ahead = nullptr;
    if (ahead_) {
        const auto it = ahead_->find(relative);
        if (it != ahead_->end()) ahead = &it->second;
    }
    const PageImage read_now = ahead ? PageImage{} : page_image(in_dir(out_dir_, relative));
    const PageImage& made = ahead ? *ahead : read_now;
    Entry e;
    e.why = made.why;
    if (!made.uri.empty()) {
        e.css_class = "im" + std::to_string(entries_.size());
        // Appended piece by piece: a picture's URI is tens of kilobytes.
        css_.append(".").append(e.css_class).append(" { background-image: url(");
        css_.append(made.uri).append("); }\n");
        e.aspect = made.aspect;
    }
    return entries_.emplace(relative, e).first->second;
}

void read_page_images(LabResult& lab, const std::string& out_dir) {
    for (const CheckResult& c : lab.checks)
        for (const std::string* relative : {&c.rendered, &c.expected, &c.difference})
            if (!relative->empty() && !lab.page_images.count(*relative))
                lab.page_images.emplace(*relative, page_image(in_dir(out_dir, *relative)));
}

}  // namespace grading::report
