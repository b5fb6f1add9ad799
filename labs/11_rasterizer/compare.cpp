// Lab 11's figures comparing the CPU image with GL's (README.md, Stats).
#include "compare.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <nlohmann/json.hpp>

namespace rasterizer {

namespace {

std::uint8_t to_byte(float c) {
    return static_cast<std::uint8_t>(std::clamp(std::floor(c * 255.0f + 0.5f), 0.0f, 255.0f));
}

}  // namespace

fw::Image canvas_image(const Canvas& canvas) {
    fw::Image out(canvas.width, canvas.height);
    for (size_t i = 0; i < canvas.color.size(); ++i) {
        const glm::vec3 c = canvas.color[i];
        out.pixels[i] = {to_byte(c.r), to_byte(c.g), to_byte(c.b), 255};
    }
    return out;
}

std::vector<bool> coverage(const fw::Image& image) {
    std::vector<bool> out(image.pixels.size());
    for (size_t i = 0; i < out.size(); ++i) {
        const fw::Rgba8 p = image.pixels[i];
        out[i] = p.r != 0 || p.g != 0 || p.b != 0;
    }
    return out;
}

int one_per_major(const std::vector<bool>& covered, int width, const std::vector<Line>& lines) {
    int total = 0;
    for (const Line& l : lines) {
        const glm::ivec2 lo = glm::min(l.a, l.b), hi = glm::max(l.a, l.b);
        const bool x_major = hi.x - lo.x >= hi.y - lo.y;
        const int major_lo = x_major ? lo.x : lo.y, major_hi = x_major ? hi.x : hi.y;
        const int minor_lo = x_major ? lo.y : lo.x, minor_hi = x_major ? hi.y : hi.x;
        for (int m = major_lo; m <= major_hi; ++m) {
            int n = 0;
            for (int k = minor_lo; k <= minor_hi; ++k) {
                const int x = x_major ? m : k, y = x_major ? k : m;
                n += covered[static_cast<size_t>(y * width + x)] ? 1 : 0;
            }
            total += n == 1 ? 1 : 0;
        }
    }
    return total;
}

nlohmann::json compare_stats(const CpuScene& cpu, const fw::Image& gl, const fw::DepthImage& depth,
                             const fw::Image& counts, const std::vector<Line>* lines) {
    const fw::Image mine = canvas_image(cpu.canvas);
    const std::vector<bool> cpu_covered = coverage(mine), gl_covered = coverage(gl);
    int cpu_filled = 0, cpu_overdraw = 0, gl_filled = 0, gl_overdraw = 0, differ = 0, max_diff = 0;
    int color_differ = 0;
    float max_depth = 0.0f;
    for (size_t i = 0; i < mine.pixels.size(); ++i) {
        cpu_filled += cpu.canvas.writes[i] > 0 ? 1 : 0;
        cpu_overdraw += cpu.canvas.writes[i] > 1 ? 1 : 0;
        gl_filled += counts.pixels[i].r > 0 ? 1 : 0;
        gl_overdraw += counts.pixels[i].r > 1 ? 1 : 0;
        max_depth = std::max(max_depth, std::abs(cpu.canvas.depth[i] - depth.values[i]));
        if (cpu_covered[i] != gl_covered[i]) ++differ;
        if (!cpu_covered[i] || !gl_covered[i]) continue;
        const fw::Rgba8 a = mine.pixels[i], b = gl.pixels[i];
        const int diff = std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
        max_diff = std::max(max_diff, diff);
        color_differ += diff > 2 ? 1 : 0;
    }
    nlohmann::json out = {{"cpu", {{"filled", cpu_filled}, {"overdraw", cpu_overdraw}}},
                          {"gl", {{"filled", gl_filled}, {"overdraw", gl_overdraw}}},
                          {"triangles", cpu.triangles},
                          {"differ", differ},
                          {"max_color_difference", max_diff},
                          {"color_differ", color_differ},
                          {"max_depth_difference", max_depth}};
    if (lines) {
        out["cpu"]["one_per_major"] = one_per_major(cpu_covered, mine.width, *lines);
        out["gl"]["one_per_major"] = one_per_major(gl_covered, gl.width, *lines);
    }
    return out;
}

}  // namespace rasterizer
