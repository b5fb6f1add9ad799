// The matrices a student's mistake would give instead of the expected one
// (mistakes.hpp): transposed, inverted, translation in the bottom row.
#include <cmath>
#include <optional>
#include <vector>

#include "grading/units/mistakes.hpp"

namespace grading {

namespace {

using nlohmann::json;
using Columns = std::vector<std::vector<double>>;  // [c][r]

// A square matrix of numbers, as columns.
std::optional<Columns> square_matrix(const json& m) {
    if (!m.is_array() || m.empty()) return std::nullopt;
    const size_t n = m.size();
    Columns out(n);
    for (size_t c = 0; c < n; ++c) {
        if (!m[c].is_array() || m[c].size() != n) return std::nullopt;
        for (const json& v : m[c]) {
            if (!v.is_number()) return std::nullopt;
            out[c].push_back(v.get<double>());
        }
    }
    return out;
}

json to_json(const Columns& m) {
    json out = json::array();
    for (const auto& column : m) out.push_back(column);
    return out;
}

}  // namespace

std::optional<json> transposed(const json& m) {
    std::optional<Columns> a = square_matrix(m);
    if (!a) return std::nullopt;
    Columns t = *a;
    for (size_t c = 0; c < t.size(); ++c)
        for (size_t r = 0; r < t.size(); ++r) t[c][r] = (*a)[r][c];
    return to_json(t);
}

std::optional<json> inverted(const json& m) {
    std::optional<Columns> a = square_matrix(m);
    if (!a) return std::nullopt;
    // Gauss-Jordan with partial pivoting on rows, in double.
    const size_t n = a->size();
    std::vector<std::vector<double>> x(n, std::vector<double>(2 * n, 0.0));  // [r][c]
    double scale = 0.0;
    for (size_t r = 0; r < n; ++r) {
        for (size_t c = 0; c < n; ++c) {
            x[r][c] = (*a)[c][r];
            scale = std::max(scale, std::fabs(x[r][c]));
        }
        x[r][n + r] = 1.0;
    }
    if (!(scale > 0.0) || !std::isfinite(scale)) return std::nullopt;
    for (size_t col = 0; col < n; ++col) {
        size_t pivot = col;
        for (size_t r = col + 1; r < n; ++r)
            if (std::fabs(x[r][col]) > std::fabs(x[pivot][col])) pivot = r;
        if (std::fabs(x[pivot][col]) <= 1e-9 * scale) return std::nullopt;
        std::swap(x[col], x[pivot]);
        const double p = x[col][col];
        for (double& v : x[col]) v /= p;
        for (size_t r = 0; r < n; ++r) {
            if (r == col || x[r][col] == 0.0) continue;
            const double f = x[r][col];
            for (size_t c = 0; c < 2 * n; ++c) x[r][c] -= f * x[col][c];
        }
    }
    Columns inv(n, std::vector<double>(n));
    for (size_t c = 0; c < n; ++c)
        for (size_t r = 0; r < n; ++r) inv[c][r] = x[r][n + c];
    return to_json(inv);
}

std::optional<json> translation_in_bottom_row(const json& m) {
    std::optional<Columns> a = square_matrix(m);
    if (!a || a->size() < 3) return std::nullopt;
    const size_t last = a->size() - 1;
    Columns b = *a;
    for (size_t r = 0; r < last; ++r) {
        b[r][last] = (*a)[last][r];
        b[last][r] = 0.0;
    }
    return to_json(b);
}

std::optional<json> rows_negated(const json& m, int rows, bool with_last) {
    std::optional<Columns> a = square_matrix(m);
    if (!a || a->size() < 3) return std::nullopt;
    const size_t last = a->size() - 1;
    Columns b = *a;
    for (size_t r = 0; r < last; ++r) {
        if (!(rows & (1 << r))) continue;
        for (size_t c = 0; c < (with_last ? last + 1 : last); ++c) b[c][r] = -b[c][r];
    }
    return to_json(b);
}

std::optional<json> diagonal_in_last_column(const json& m) {
    std::optional<Columns> a = square_matrix(m);
    if (!a || a->size() < 3) return std::nullopt;
    const size_t last = a->size() - 1;
    Columns b = *a;
    for (size_t r = 0; r < last; ++r) {
        b[last][r] = (*a)[r][r];
        b[r][r] = 1.0;
    }
    return to_json(b);
}

}  // namespace grading
