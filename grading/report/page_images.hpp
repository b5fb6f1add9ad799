// index.html's pictures: each PNG a check names, embedded once as a data:
// URI in a CSS class that every figure showing it names. Read when the page
// is made, or, for a lab judged while its child went on with the next, ahead
// of it (read_page_images, report_text.hpp).
#pragma once

#include <map>
#include <string>

#include "grading/results/results.hpp"

namespace grading::report {

// The PNG file at `path` for the page: its data: URI and shape, or why not.
PageImage page_image(const std::string& path);

// Each image file is embedded once, as the background of a CSS class in the
// <style> block, and every figure that shows it names the class: the same
// frame appears in every check of its checkpoint, and embedding it each time
// would multiply the report's size.
class ImageTable {
public:
    explicit ImageTable(const std::string& out_dir) : out_dir_(out_dir) {}
    // The pictures read ahead for the lab whose figures come next (or none).
    void read_ahead(const std::map<std::string, PageImage>* images) { ahead_ = images; }

    // The figure for `relative` (under out_dir), or a note saying why there
    // is none (`none`, else "no CAPTION image").
    std::string figure(const std::string& caption, const std::string& relative,
                       const std::string& none = "");
    const std::string& css() const { return css_; }
    // The <style> rules, moved out (the table is done with), and room for
    // `bytes` of them made first.
    std::string take_css() { return std::move(css_); }
    void reserve(size_t bytes) { css_.reserve(bytes + bytes / 16); }

private:
    struct Entry {
        std::string css_class, aspect, why;
    };
    const Entry& entry(const std::string& relative);

    const std::string& out_dir_;
    std::map<std::string, Entry> entries_;
    const std::map<std::string, PageImage>* ahead_ = nullptr;
    std::string css_;
};

}  // namespace grading::report
