// Lab 9's uniform block: the std140 rules as a function (std140_place, a
// student part the grader checks), the C++ struct that mirrors the block
// SceneBlock of shaders/09_buffers/sphere.vert byte for byte, and what
// fills it (pack_scene, a student part), in block.cpp; what the block scene
// draws and reports with them, in block_scene.cpp.
#pragma once

#include <glm/glm.hpp>
#include <nlohmann/json_fwd.hpp>
#include <vector>

#include "framework/gl.hpp"
#include "framework/names.hpp"

namespace buffers {

// The member types a block may hold here.
enum class GlslType { Float, Vec2, Vec3, Vec4, Mat3, Mat4 };
constexpr fw::Choice<GlslType> kGlslTypes[] = {
    {GlslType::Float, "float"}, {GlslType::Vec2, "vec2"}, {GlslType::Vec3, "vec3"},
    {GlslType::Vec4, "vec4"},   {GlslType::Mat3, "mat3"}, {GlslType::Mat4, "mat4"}};

// Where a member goes: its first byte and the first byte after it.
struct Std140Place {
    int offset;
    int end;
};

// The std140 rules (GL 4.3 core, section 7.6.2.2) for a member of `type`
// whose block has used bytes [0, offset): the member starts at the first
// multiple of its base alignment at or after `offset` and takes its size.
//   float: alignment 4, size 4;  vec2: 8, 8;  vec3: 16, 12 (a float may
//   follow in its last 4 bytes);  vec4: 16, 16;  matCxR: C columns, each a
//   vecR rounded up to a vec4: mat3 alignment 16, size 48; mat4 16, 64.
Std140Place std140_place(int offset, GlslType type);

// The offsets of `members` placed one after the other, then the block's
// size (the end of the last member rounded up to 16): what
// glGetActiveUniformsiv(GL_UNIFORM_OFFSET) and GL_UNIFORM_BLOCK_DATA_SIZE
// report for the same block.
std::vector<int> std140_offsets(const std::vector<GlslType>& members);

// SceneBlock's members, in sphere.vert's order.
const std::vector<GlslType>& scene_block_members();

// The block SceneBlock as C++ lays it out: every member where std140 puts it.
// A mat3 is three columns of 16 bytes each, so it is stored as three vec4s.
struct SceneBlock {
    glm::mat4 mvp;               // bytes 0-63
    glm::vec4 normal_matrix[3];  // 64-111: column c in normal_matrix[c].xyz
    glm::vec3 light;             // 112-123
    float ambient;               // 124-127: in the last 4 bytes of light's 16
    glm::vec4 color;             // 128-143
};
static_assert(sizeof(SceneBlock) == 144, "SceneBlock must be 144 bytes, as std140 lays it out");

// The block's contents for these values.
SceneBlock pack_scene(const glm::mat4& mvp, const glm::mat3& normal_matrix, glm::vec3 light,
                      float ambient, glm::vec4 color);

// SceneBlock's member offsets and size three ways, for the frame's stats:
// "driver", as GL laid the block out in `program` (glGetActiveUniformsiv
// with GL_UNIFORM_OFFSET, GL_UNIFORM_BLOCK_DATA_SIZE), "struct", as the C++
// struct lays it out (offsetof, sizeof), and "std140_place", by
// std140_offsets().
nlohmann::json block_layouts(const fw::Program& program);

// scene=block's surface: the unit icosphere subdivided 3 times, with its
// normals (A_POSITION, A_NORMAL) and an index buffer; and the uniform buffer
// that holds its SceneBlock (GL_DYNAMIC_DRAW, written every frame).
struct Ellipsoid {
    fw::Buffer vbo, ibo;
    fw::VertexArray vertices;
    fw::Buffer block;
};
Ellipsoid make_ellipsoid();

}  // namespace buffers

template <>
struct fw::ChoicesOf<buffers::GlslType> {
    static constexpr const auto& list = buffers::kGlslTypes;
};

// The fields' names, for the grader's report ("your offset").
template <>
struct fw::FieldsOf<buffers::Std140Place> {
    using P = buffers::Std140Place;
    static constexpr fw::Field<P, int> list[] = {{"offset", &P::offset}, {"end", &P::end}};
};
