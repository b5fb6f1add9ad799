// The GL 4.3 specification's tessellation rules (section 11.2.2), counted.
// Every region the spec fills with triangles is bounded by subdivided edges,
// and "two of the three vertices of each triangle are taken from adjacent
// vertices on a subdivided edge of one triangle; the third is one of the
// vertices on the corresponding edge of the other": one triangle per
// segment on either side. A region between two rings therefore holds as many
// triangles as both rings have segments, however the implementation chooses
// its diagonals.
#include "tessellation_count.hpp"

#include <algorithm>
#include <cmath>

namespace tessellation_test {

int effective_level(float level, Spacing spacing, int max_level) {
    switch (spacing) {
        case Spacing::Equal:
            return static_cast<int>(std::ceil(std::clamp(level, 1.0f, float(max_level))));
        case Spacing::FractionalEven: {
            const int n = static_cast<int>(std::ceil(std::clamp(level, 2.0f, float(max_level))));
            return n % 2 == 0 ? n : n + 1;
        }
        case Spacing::FractionalOdd: {
            const int n =
                static_cast<int>(std::ceil(std::clamp(level, 1.0f, float(max_level - 1))));
            return n % 2 == 1 ? n : n + 1;
        }
    }
    return 0;
}

namespace {

// "If the inner tessellation level is one and any of the outer tessellation
// levels is greater than one, the inner tessellation level is treated as
// though it were originally specified as 1 + epsilon": two segments with
// equal spacing, three with fractional_odd (fractional_even never gives one).
int inner_level(float level, Spacing spacing) {
    const int n = effective_level(level, spacing);
    return n == 1 ? effective_level(std::nextafter(1.0f, 2.0f), spacing) : n;
}

}  // namespace

long triangle_patch_triangles(float inner, std::array<float, 3> outer, Spacing spacing) {
    long outer_segments = 0;
    bool all_one = effective_level(inner, spacing) == 1;
    for (float level : outer) {
        const int n = effective_level(level, spacing);
        outer_segments += n;
        all_one = all_one && n == 1;
    }
    // "If the first inner tessellation level and all three outer tessellation
    // levels are exactly one after clamping and rounding, only a single
    // triangle ... is generated."
    if (all_one) return 1;
    // The inner level n makes concentric triangles whose edges have n - 2,
    // n - 4, ... segments, down to a single point (0) or a triangle (1).
    // Between the outer edges (subdivided by the outer levels) and the first
    // inner triangle: one triangle per segment of either.
    int ring = inner_level(inner, spacing) - 2;
    long triangles = outer_segments + 3L * ring;
    while (ring >= 2) {
        triangles += 3L * ring + 3L * (ring - 2);
        ring -= 2;
    }
    // "If the innermost triangle is not degenerate, that triangle is added to
    // the set of generated triangles as-is."
    if (ring == 1) triangles += 1;
    return triangles;
}

long quad_patch_triangles(std::array<float, 2> inner, std::array<float, 4> outer, Spacing spacing) {
    long outer_segments = 0;
    bool all_one =
        effective_level(inner[0], spacing) == 1 && effective_level(inner[1], spacing) == 1;
    for (float level : outer) {
        const int n = effective_level(level, spacing);
        outer_segments += n;
        all_one = all_one && n == 1;
    }
    // "If both clamped inner tessellation levels and all four clamped outer
    // tessellation levels are exactly one, only a single triangle pair
    // covering the outer rectangle is generated."
    if (all_one) return 2;
    // An m x n grid; the (m - 2) x (n - 2) rectangles not on the border are
    // split in two. The inner rectangle's edges have m - 2 and n - 2
    // segments (0: a degenerate edge, a single point), and the border region
    // holds one triangle per segment of the outer and of the inner edges.
    const long m = inner_level(inner[0], spacing) - 2;
    const long n = inner_level(inner[1], spacing) - 2;
    return 2 * m * n + outer_segments + 2 * m + 2 * n;
}

}  // namespace tessellation_test
