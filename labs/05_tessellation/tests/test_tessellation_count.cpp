// The counting rules of tessellation_count.cpp against values
// worked out by hand from the GL 4.3 specification's text (section 11.2.2)
// and against closed forms summed ring by ring. No GL here.
#include <doctest/doctest.h>

#include "tessellation_count.hpp"

using namespace tessellation_test;

namespace {

constexpr Spacing kEqual = Spacing::Equal, kEven = Spacing::FractionalEven,
                  kOdd = Spacing::FractionalOdd;

long triangles(float inner, float outer, Spacing s) {
    return triangle_patch_triangles(inner, {outer, outer, outer}, s);
}
long quads(float inner, float outer, Spacing s) {
    return quad_patch_triangles({inner, inner}, {outer, outer, outer, outer}, s);
}

}  // namespace

TEST_CASE("tessellation count: levels are clamped, then rounded up per spacing") {
    // equal: clamp to [1, 64], round up.
    CHECK(effective_level(1.0f, kEqual) == 1);
    CHECK(effective_level(1.01f, kEqual) == 2);
    CHECK(effective_level(2.5f, kEqual) == 3);
    CHECK(effective_level(63.2f, kEqual) == 64);
    CHECK(effective_level(100.0f, kEqual) == 64);
    CHECK(effective_level(0.5f, kEqual) == 1);
    // fractional_even: clamp to [2, 64], round up to even.
    CHECK(effective_level(1.0f, kEven) == 2);
    CHECK(effective_level(2.0f, kEven) == 2);
    CHECK(effective_level(2.5f, kEven) == 4);
    CHECK(effective_level(3.3f, kEven) == 4);
    CHECK(effective_level(4.0f, kEven) == 4);
    CHECK(effective_level(7.9f, kEven) == 8);
    CHECK(effective_level(64.0f, kEven) == 64);
    // fractional_odd: clamp to [1, 63], round up to odd.
    CHECK(effective_level(1.0f, kOdd) == 1);
    CHECK(effective_level(1.5f, kOdd) == 3);
    CHECK(effective_level(2.5f, kOdd) == 3);
    CHECK(effective_level(3.0f, kOdd) == 3);
    CHECK(effective_level(3.3f, kOdd) == 5);
    CHECK(effective_level(7.9f, kOdd) == 9);
    CHECK(effective_level(63.5f, kOdd) == 63);
    CHECK(effective_level(64.0f, kOdd) == 63);
}

TEST_CASE("tessellation count: triangle patches, worked by hand from the spec") {
    // All ones: the patch itself.
    CHECK(triangles(1, 1, kEqual) == 1);
    CHECK(triangles(1, 1, kOdd) == 1);
    // fractional_even makes at least two segments: inner 2 (a centre point),
    // outer 2 + 2 + 2: six triangles fan around the centre.
    CHECK(triangles(1, 1, kEven) == 6);
    // Inner 2, outer 1: the centre point joined to the three corners.
    CHECK(triangles(2, 1, kEqual) == 3);
    // Inner 1 with outer 4 is treated as 1 + epsilon: 2 (a centre point),
    // so 4 + 4 + 4 triangles fan around it; fractional_odd rounds 1 + epsilon
    // to 3: an inner triangle with 1 segment per edge, 12 + 3 + 1.
    CHECK(triangles(1, 4, kEqual) == 12);
    CHECK(triangles(1, 5, kOdd) == 15 + 3 + 1);
    // Inner 3: one inner triangle, 3 + 3 + 3 outer and 1 + 1 + 1 inner
    // segments between them, plus the inner triangle.
    CHECK(triangles(3, 3, kEqual) == 13);
    // Inner 4: rings of 2 segments a side, then a point: (12 + 6) + (6 + 0).
    CHECK(triangles(4, 4, kEqual) == 24);
    // Mixed outer levels: 1 + 2 + 3 outer segments, inner 5: rings of 3 and 1
    // segments a side: (6 + 9) + (9 + 3) + 1.
    CHECK(triangle_patch_triangles(5, {1, 2, 3}, kEqual) == 28);
}

TEST_CASE("tessellation count: all levels n give floor(3 n^2 / 2) triangles, 2 n^2 quads") {
    // Summed ring by ring: rings of a and a - 2 segments a side hold
    // 3a + 3(a - 2) triangles. n = 2k: sum over a = 2, 4, ..., 2k of
    // (6a - 6) = 6k^2 = 3n^2 / 2. n = 2k + 1: over a = 3, ..., 2k + 1, plus
    // the innermost triangle: 6k^2 + 6k + 1 = (3n^2 - 1) / 2.
    for (int n = 1; n <= kMaxLevel; ++n) {
        CAPTURE(n);
        const auto level = static_cast<float>(n);
        CHECK(triangles(level, level, kEqual) == 3L * n * n / 2);
        // A quad's rings are the n x n grid's cells, two triangles each.
        CHECK(quads(level, level, kEqual) == 2L * n * n);
        if (n % 2 == 0) CHECK(triangles(level, level, kEven) == 3L * n * n / 2);
        if (n % 2 == 1 && n < kMaxLevel) CHECK(quads(level, level, kOdd) == 2L * n * n);
    }
}

TEST_CASE("tessellation count: quad patches, worked by hand from the spec") {
    CHECK(quads(1, 1, kEqual) == 2);
    CHECK(quads(1, 1, kOdd) == 2);
    // fractional_even: at least 2 x 2, every inner edge degenerate: 8
    // triangles fan from the centre point to the 8 outer segments.
    CHECK(quads(1, 1, kEven) == 8);
    // Inner 1 with outer 3 is treated as 1 + epsilon: 2 x 2, a centre point
    // joined to 4 x 3 outer segments.
    CHECK(quads(1, 3, kEqual) == 12);
    // The spec's figure "Inner Quad Tessellation": inner levels (7, 4) leave
    // 5 x 2 = 10 inner rectangles; with outer 1 the border region has 4
    // outer and 2 (5 + 2) inner segments.
    CHECK(quad_patch_triangles({7, 4}, {1, 1, 1, 1}, kEqual) == 20 + 4 + 14);
    // Inner (4, 2): the inner rectangle is a line of 2 segments, seen from
    // both sides: 4 x 4 outer + 2 x 2 inner segments.
    CHECK(quad_patch_triangles({4, 2}, {4, 4, 4, 4}, kEqual) == 16 + 4);
    // fractional levels: 2.5 is 4 segments with fractional_even, 3 odd.
    CHECK(quads(2.5f, 2.5f, kEven) == 32);
    CHECK(quads(2.5f, 2.5f, kOdd) == 18);
}
