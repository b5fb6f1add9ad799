#include "grading/judge/judge_values.hpp"

#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <vector>

#include "framework/text.hpp"

namespace grading {

std::string num(double v) { return fw::number_text(v, 7); }

void verdict(CheckResult& r, bool pass, const std::string& output) {
    r.passed = pass;
    r.score = pass ? r.max_score : 0.0;
    r.output = output;
}

namespace {

using nlohmann::json;

// JSON with numbers at float precision, cut to `max` characters.
std::string compact(const json& j, size_t max = 240) {
    std::string s;
    if (j.is_array()) {
        s = "[";
        for (size_t i = 0; i < j.size() && s.size() <= max; ++i)
            s += (i ? ", " : "") + compact(j[i], max);
        s += "]";
    } else {
        s = j.is_number_float() ? num(j.get<double>()) : j.dump();
    }
    return s.size() > max ? s.substr(0, max) + "..." : s;
}

std::string tuple(const std::vector<double>& v) { return "(" + fw::join(v, ", ", num) + ")"; }

}  // namespace

void judge_probe(const ProbeCheck& check, const RenderPlan& plan, Frame& frame, CheckResult& r) {
    int x, y;
    std::string where;
    if (check.at) {
        x = (*check.at)[0];
        y = (*check.at)[1];
    } else {
        // The pixel whose square holds the point: NDC -1..1 covers 0..width.
        const double nx = check.ndc[0], ny = check.ndc[1];
        x = std::min(plan.width - 1, static_cast<int>(std::floor((nx + 1) / 2 * plan.width)));
        y = std::min(plan.height - 1, static_cast<int>(std::floor((ny + 1) / 2 * plan.height)));
        where = " (NDC " + tuple({nx, ny}) + ")";
    }
    const std::string pixel = "(" + std::to_string(x) + ", " + std::to_string(y) + ")";
    std::string why;
    if (!check.reads_depth()) {
        r.title = "probe " + pixel + " colour";
        const std::vector<double>& expected = check.color;
        const double tol = check.tolerance;
        const std::string want = "Expected: colour " + tuple(expected) + " within " + num(tol) +
                                 " per channel at pixel " + pixel + where + "\n";
        const fw::Image* image = frame.color(why);
        r.rendered = frame.rendered();
        if (!image) return verdict(r, false, want + "Observed: " + why);
        if (x >= image->width || y >= image->height)
            return verdict(r, false, want + "Observed: outside the image");
        const fw::Rgba8 p = image->at(x, y);
        const double channels[4] = {p.r / 255.0, p.g / 255.0, p.b / 255.0, p.a / 255.0};
        std::vector<double> seen(channels, channels + expected.size());
        double worst = 0.0;
        for (size_t i = 0; i < expected.size(); ++i)
            worst = std::max(worst, std::fabs(seen[i] - expected[i]));
        return verdict(r, worst <= tol,
                       want + "Observed: " + tuple(seen) + ", largest difference " + num(worst));
    }
    r.title = "probe " + pixel + " depth";
    const double expected = check.depth, tol = check.tolerance;
    const std::string want = "Expected: depth " + num(expected) + " within " + num(tol) +
                             " at pixel " + pixel + where + "\n";
    const fw::DepthImage* depth = frame.depth(why);
    if (!depth) return verdict(r, false, want + "Observed: " + why);
    const double seen = depth->at(x, y);
    verdict(
        r, std::fabs(seen - expected) <= tol,
        want + "Observed: depth " + num(seen) + ", difference " + num(std::fabs(seen - expected)));
}

void judge_stat(const StatCheck& check, Frame& frame, CheckResult& r) {
    const std::string& path = check.stat;
    std::string want;
    if (check.equals) {
        want = path + " == " + compact(*check.equals);
        if (check.tolerance) want += " within " + num(*check.tolerance);
    } else if (check.min && check.max) {
        want = path + " in [" + num(*check.min) + ", " + num(*check.max) + "]";
    } else {
        want = path + (check.min ? " >= " + num(*check.min) : " <= " + num(*check.max));
    }
    r.title = "stat " + want;
    want = "Expected: " + want + "\n";
    std::string why;
    const json* stats = frame.stats(why);
    if (!stats) return verdict(r, false, want + "Observed: " + why);
    const json* value = stats;
    for (size_t start = 0; value && start <= path.size();) {
        size_t dot = std::min(path.find('.', start), path.size());
        const std::string key = path.substr(start, dot - start);
        value = value->is_object() && value->contains(key) ? &(*value)[key] : nullptr;
        start = dot + 1;
    }
    if (!value) return verdict(r, false, want + "Observed: the frame's stats have no " + path);
    const std::string seen = "Observed: " + path + " = " + compact(*value);
    if (check.equals) {
        const json& e = *check.equals;
        if (!e.is_number()) return verdict(r, *value == e, want + seen);
        if (!value->is_number()) return verdict(r, false, want + seen + " (not a number)");
        const double diff = std::fabs(value->get<double>() - e.get<double>());
        return verdict(r, diff <= check.tolerance.value_or(0.0), want + seen);
    }
    if (!value->is_number()) return verdict(r, false, want + seen + " (not a number)");
    const double v = value->get<double>();
    const bool pass = (!check.min || v >= *check.min) && (!check.max || v <= *check.max);
    verdict(r, pass, want + seen);
}

}  // namespace grading
