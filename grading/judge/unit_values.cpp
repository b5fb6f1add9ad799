// How a unit check's values and points are written (judge_unit.hpp): the
// points of a partly passed check, and numbers, vectors and matrices as the
// lecture writes them.
#include <algorithm>
#include <cmath>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "framework/json_glm.hpp"
#include "framework/text.hpp"
#include "grading/judge/judge_unit.hpp"

namespace grading {

using nlohmann::json;

double unit_points(double max_score, size_t passed, size_t cases) {
    if (cases == 0 || passed >= cases) return cases == 0 ? 0.0 : max_score;
    const double tenths = std::floor(
        max_score * 10.0 * static_cast<double>(passed) / static_cast<double>(cases) + 1e-9);
    return tenths / 10.0;
}

int unit_decimals(double tolerance) {
    if (!(tolerance > 0.0) || !std::isfinite(tolerance)) return 9;
    const int d = static_cast<int>(std::ceil(-std::log10(tolerance) - 1e-9)) + 1;
    return std::clamp(d, 2, 9);
}

std::string unit_number(double value, int decimals) {
    if (!std::isfinite(value)) return fw::non_finite_name(value);
    if (std::fabs(value) >= 1e7) return fw::number_text(value, 7);
    return fw::trimmed_decimals(value, decimals);
}

std::vector<std::string> matrix_rows(const json& m, int decimals) {
    if (!m.is_array() || m.empty() || !m[0].is_array() || m[0].empty()) return {};
    const size_t columns = m.size(), rows = m[0].size();
    std::vector<std::vector<std::string>> cells(rows, std::vector<std::string>(columns));
    std::vector<size_t> width(columns, 0);
    for (size_t c = 0; c < columns; ++c) {
        if (!m[c].is_array() || m[c].size() != rows) return {};
        for (size_t r = 0; r < rows; ++r) {
            const std::optional<double> x = fw::json_number(m[c][r]);
            if (!x) return {};
            cells[r][c] = unit_number(*x, decimals);
            width[c] = std::max(width[c], cells[r][c].size());
        }
    }
    std::vector<std::string> out;
    for (size_t r = 0; r < rows; ++r) {
        std::string line = "[ ";
        for (size_t c = 0; c < columns; ++c)
            line += (c ? "  " : "") + std::string(width[c] - cells[r][c].size(), ' ') + cells[r][c];
        out.push_back(line + " ]");
    }
    return out;
}

std::string vector_text(const json& v, int decimals) {
    if (!v.is_array() || v.empty()) return "";
    for (const json& x : v)
        if (!fw::json_number(x)) return "";
    return "(" +
           fw::join(v, ", ",
                    [&](const json& x) { return unit_number(*fw::json_number(x), decimals); }) +
           ")";
}

}  // namespace grading
