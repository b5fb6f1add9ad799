// How many triangles the tessellation primitive generator makes from one
// patch, from the rules of the GL 4.3 core specification, section 11.2.2
// "Tessellation Primitive Generation", written here without the lab's code:
//
//   effective_level(3.3f, Spacing::FractionalOdd)        // 5
//   triangle_patch_triangles(4, {4, 4, 4}, Spacing::Equal)  // 24
//   quad_patch_triangles({4, 4}, {4, 4, 4, 4}, Spacing::Equal)  // 32
#pragma once

#include <array>

namespace tessellation_test {

enum class Spacing { Equal, FractionalEven, FractionalOdd };

// GL_MAX_TESS_GEN_LEVEL: the minimum GL 4.3 allows, and llvmpipe's value.
constexpr int kMaxLevel = 64;

// The number of segments a level makes: clamped, then rounded up (equal to
// [1, max], fractional_even to [2, max] and up to even, fractional_odd to
// [1, max - 1] and up to odd).
int effective_level(float level, Spacing spacing, int max_level = kMaxLevel);

// Triangles from one triangle patch: gl_TessLevelInner[0] and
// gl_TessLevelOuter[0..2].
long triangle_patch_triangles(float inner, std::array<float, 3> outer, Spacing spacing);

// Triangles from one quad patch: gl_TessLevelInner[0..1] and
// gl_TessLevelOuter[0..3].
long quad_patch_triangles(std::array<float, 2> inner, std::array<float, 4> outer, Spacing spacing);

}  // namespace tessellation_test
