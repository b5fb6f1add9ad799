#include "grading/report/by_checkpoint.hpp"

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <fstream>
#include <iterator>

#include "framework/error.hpp"
#include "framework/image.hpp"
#include "grading/report/report_text.hpp"

namespace grading {

std::vector<CheckpointResult> by_checkpoint(const LabResult& lab) {
    std::vector<CheckpointResult> out;
    for (const CheckResult& c : lab.checks) {
        auto found = std::find_if(out.begin(), out.end(), [&](const CheckpointResult& cp) {
            return cp.checkpoint == c.checkpoint;
        });
        if (found == out.end()) {
            out.push_back({});
            found = out.end() - 1;
            found->checkpoint = c.checkpoint;
            found->visibility = c.visibility;
        }
        CheckpointResult& cp = *found;
        cp.checks.push_back(&c);
        cp.score = rounded_points(cp.score + c.score);
        cp.max_score += c.max_score;
        cp.passed = cp.passed && c.passed;
        // A hidden check makes its checkpoint hidden (they share one in practice).
        if (c.visibility == Visibility::Hidden) cp.visibility = Visibility::Hidden;
        if (cp.rendered.empty()) cp.rendered = c.rendered;
        if (c.kind == CheckKind::Image) {
            cp.image_failed = cp.image_failed || !c.passed;
            if (cp.expected.empty()) cp.expected = c.expected;
            if (cp.difference.empty() || !c.passed) cp.difference = c.difference;
        }
    }
    for (CheckpointResult& cp : out)
        std::stable_partition(cp.checks.begin(), cp.checks.end(),
                              [](const CheckResult* c) { return !c->passed; });
    return out;
}

std::string check_output(const LabResult& lab, const CheckResult& check) {
    std::string text = check.output;
    if (!lab.status.ok() && !check.passed)
        text += (text.empty() ? "" : "\n") + ("lab " + lab.lab + ": " + lab.status.text());
    return text;
}

std::string checkpoint_text(const LabResult& lab, const CheckpointResult& cp) {
    std::string text;
    for (const CheckResult* c : cp.checks) {
        text += std::string(c->passed ? "PASS" : "FAIL") + "  " + c->title + " (" +
                report::points(c->score) + "/" + report::points(c->max_score) + " points)\n";
        const std::string output = check_output(lab, *c);
        size_t start = 0;
        while (start < output.size()) {
            const size_t end = std::min(output.find('\n', start), output.size());
            text += "    " + output.substr(start, end - start) + "\n";
            start = end + 1;
        }
    }
    return text;
}

std::string check_failure(const LabResult& lab, const CheckResult& check) {
    const std::string output = check_output(lab, check);
    // An image check's first kind of difference says more than its pixel count.
    const size_t where = output.find("\nWhere:");
    if (where != std::string::npos) {
        const size_t kind = output.find("\n  ", where + 1);
        if (kind != std::string::npos) return report::first_line(output.substr(kind));
    }
    const size_t observed = output.find("Observed:");
    const std::string from = observed == std::string::npos ? output : output.substr(observed);
    std::string line = report::first_line(from);
    // A line that ends in a colon introduces the next one (a compiler's
    // message after "failed to compile:"): the cause is that one.
    if (!line.empty() && line.back() == ':') {
        const size_t end = from.find('\n', from.find(line));
        if (end != std::string::npos) {
            const std::string next = report::first_line(from.substr(end + 1));
            if (!next.empty()) line += " " + next;
        }
    }
    return line;
}

std::string checkpoint_failure(const LabResult& lab, const CheckpointResult& cp) {
    for (const CheckResult* c : cp.checks) {
        if (c->passed) continue;
        const std::string why = check_failure(lab, *c);
        return c->title + (why.empty() ? "" : ": " + why);
    }
    return {};
}

Thumbnails::Thumbnails(std::string out_dir, size_t budget, int max_side)
    : out_dir_(std::move(out_dir)), budget_(budget), max_side_(max_side) {}

void Thumbnails::restart(size_t budget) {
    budget_ = budget;
    used_ = skipped_ = 0;
}

std::string Thumbnails::uri(const std::string& relative, bool difference) {
    if (relative.empty()) return {};
    const std::string key = relative + (difference ? "\ndifference" : "");
    const auto made = made_.find(key);
    if (made != made_.end()) return made->second;
    return made_[key] = make_uri(relative, difference);
}

std::string Thumbnails::make_uri(const std::string& relative, bool difference) {
    std::ifstream file(report::in_dir(out_dir_, relative), std::ios::binary);
    if (!file) return {};
    const std::string bytes{std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>()};
    try {
        const fw::Image small = fw::shrink(fw::decode_png(bytes, relative), max_side_, difference);
        // Whichever is smaller: PNG for flat colours, JPEG for shading. A
        // difference image stays PNG: JPEG would blur its single pixels.
        const std::string png = fw::encode_png(small);
        const std::string jpeg = difference ? std::string() : fw::encode_jpeg(small, 85);
        return !jpeg.empty() && jpeg.size() < png.size() ? "data:image/jpeg;base64," + base64(jpeg)
                                                         : "data:image/png;base64," + base64(png);
    } catch (const fw::Error&) {
        return {};  // course wrote these files; one that does not decode is simply not shown
    }
}

std::vector<Thumbnails::Picture> Thumbnails::for_checkpoint(const CheckpointResult& cp,
                                                            bool* left_out) {
    if (left_out) *left_out = false;
    if (cp.passed || cp.rendered.empty()) return {};
    if (used_ >= budget_) {
        ++skipped_;
        if (left_out) *left_out = true;
        return {};
    }
    struct Source {
        const char* label;
        std::string relative;
        bool difference;
    };
    const Source sources[] = {{"rendered", cp.rendered, false},
                              {"expected", cp.expected, false},
                              {"difference", cp.image_failed ? cp.difference : "", true}};
    // A checkpoint shows all of its pictures or none: they are admitted only
    // when all of them fit in what is left of the budget, and once one
    // checkpoint's do not, later ones get none either (the report keeps its
    // order: the first failures are the ones a student reads first).
    std::vector<Picture> pictures;
    size_t bytes = 0;
    for (const Source& source : sources) {
        std::string u = uri(source.relative, source.difference);
        if (u.empty()) continue;
        bytes += u.size();
        pictures.push_back({source.label, std::move(u)});
    }
    if (bytes > budget_ - used_) {
        used_ = budget_;
        ++skipped_;
        if (left_out) *left_out = true;
        return {};
    }
    used_ += bytes;
    return pictures;
}

std::string within_limit(size_t limit, Thumbnails& thumbnails,
                         const std::function<std::string()>& write) {
    thumbnails.restart(0);
    std::string text = write();
    if (text.size() >= limit || thumbnails.skipped() == 0) return text;
    size_t budget = limit - text.size();
    // Pictures never take more than the budget, but each checkpoint's table
    // around them is a little longer than the line saying they were left out:
    // retry with the overshoot taken off, then with half the budget, and at
    // worst keep the text alone.
    for (int attempt = 0; attempt < 8 && budget > 0; ++attempt) {
        thumbnails.restart(budget);
        std::string with = write();
        if (with.size() <= limit) return with;
        const size_t over = with.size() - limit;
        budget = attempt < 3 && budget > over ? budget - over : budget / 2;
    }
    return text;
}

std::string lab_number(const LabResult& lab, size_t index) {
    size_t digits = 0;
    while (digits < lab.lab.size() && std::isdigit(static_cast<unsigned char>(lab.lab[digits])))
        ++digits;
    if (digits == 0) return std::to_string(index);
    const size_t first = lab.lab.find_first_not_of('0');
    return first >= digits ? "0" : lab.lab.substr(first, digits - first);
}

std::string base64(const std::string& bytes) {
    static const char alphabet[] =
        "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    const auto* in = reinterpret_cast<const unsigned char*>(bytes.data());
    const size_t n = bytes.size(), whole = n / 3 * 3;
    std::string out((n + 2) / 3 * 4, '=');
    char* o = out.data();
    for (size_t i = 0; i < whole; i += 3, o += 4) {
        const std::uint32_t g = (in[i] << 16) | (in[i + 1] << 8) | in[i + 2];
        o[0] = alphabet[g >> 18];
        o[1] = alphabet[(g >> 12) & 63];
        o[2] = alphabet[(g >> 6) & 63];
        o[3] = alphabet[g & 63];
    }
    // The last one or two bytes make two or three characters; '=' pads the rest.
    if (const size_t rest = n - whole) {
        const std::uint32_t g = (in[whole] << 16) | (rest == 2 ? in[whole + 1] << 8 : 0);
        o[0] = alphabet[g >> 18];
        o[1] = alphabet[(g >> 12) & 63];
        if (rest == 2) o[2] = alphabet[(g >> 6) & 63];
    }
    return out;
}

}  // namespace grading
