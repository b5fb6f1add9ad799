// GL's one table of enum names (fw::gl_enum_name, generated with glad by
// scripts/gen-gl-names.py): a value is named within the group of the state
// it belongs to, since GL's values collide, and the record's names come
// from it. No context is needed.
#include "framework/gl/debug.hpp"
#include "framework/trace/record.hpp"
#include "tests/support/test_support.hpp"

using fw::gl_enum_name;

TEST_CASE("gl_enum_name: one value, the name of its group") {
    CHECK(gl_enum_name(0, GLAD_GL_GROUP_PrimitiveType) == "GL_POINTS");
    CHECK(gl_enum_name(0, GLAD_GL_GROUP_BlendingFactor) == "GL_ZERO");
    CHECK(gl_enum_name(0, GLAD_GL_GROUP_ErrorCode) == "GL_NO_ERROR");
    CHECK(gl_enum_name(1, GLAD_GL_GROUP_BlendingFactor) == "GL_ONE");
    CHECK(gl_enum_name(GL_KEEP, GLAD_GL_GROUP_StencilOp) == "GL_KEEP");
    CHECK(gl_enum_name(GL_INVALID_OPERATION, GLAD_GL_GROUP_ErrorCode) == "GL_INVALID_OPERATION");
    CHECK(gl_enum_name(GL_UNIFORM_BARRIER_BIT, GLAD_GL_GROUP_MemoryBarrierMask) ==
          "GL_UNIFORM_BARRIER_BIT");
    CHECK(gl_enum_name(0xFFFFFFFFu, GLAD_GL_GROUP_MemoryBarrierMask) == "GL_ALL_BARRIER_BITS");
}

TEST_CASE("gl_enum_name: any group; aliases by the shorter name; the unnamed in hex") {
    CHECK(gl_enum_name(GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT) ==
          "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT");
    CHECK(gl_enum_name(GL_RGBA8) == "GL_RGBA8");
    CHECK(gl_enum_name(GL_TIME_ELAPSED) == "GL_TIME_ELAPSED");
    // GL_VERTEX_PROGRAM_POINT_SIZE and GL_COPY_READ_BUFFER_BINDING share these values.
    CHECK(gl_enum_name(GL_PROGRAM_POINT_SIZE) == "GL_PROGRAM_POINT_SIZE");
    CHECK(gl_enum_name(GL_COPY_READ_BUFFER) == "GL_COPY_READ_BUFFER");
    CHECK(gl_enum_name(0x1234) == "0x1234");
    CHECK(gl_enum_name(GL_LESS, GLAD_GL_GROUP_PrimitiveType) == "0x0201");
}

TEST_CASE("the record's names: by the state's kind, bits in the record's order") {
    using fw::gl_record::EnumKind;
    CHECK(fw::gl_record::enum_name(EnumKind::Mode, 0) == "GL_POINTS");
    CHECK(fw::gl_record::enum_name(EnumKind::Factor, 0) == "GL_ZERO");
    CHECK(fw::gl_record::enum_name(EnumKind::StencilOp, 0) == "GL_ZERO");
    CHECK(fw::gl_record::enum_name(EnumKind::Other, 0) == "GL_NONE");
    CHECK(fw::gl_record::enum_name(EnumKind::Other, GL_FRONT_LEFT) == "GL_FRONT_LEFT");
    CHECK(fw::gl_record::enum_name(EnumKind::Mode, GL_PATCHES) == "GL_PATCHES");
    CHECK(fw::gl_record::bits_name(
              GLAD_GL_GROUP_ClearBufferMask, GL_DEPTH_BUFFER_BIT | GL_COLOR_BUFFER_BIT,
              {GL_COLOR_BUFFER_BIT, GL_DEPTH_BUFFER_BIT, GL_STENCIL_BUFFER_BIT}) ==
          "GL_COLOR_BUFFER_BIT|GL_DEPTH_BUFFER_BIT");
    CHECK(fw::gl_record::bits_name(
              GLAD_GL_GROUP_MemoryBarrierMask,
              GL_SHADER_STORAGE_BARRIER_BIT | GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT) ==
          "GL_VERTEX_ATTRIB_ARRAY_BARRIER_BIT|GL_SHADER_STORAGE_BARRIER_BIT");
    CHECK(fw::gl_record::bits_name(GLAD_GL_GROUP_MapBufferAccessMask, 0x80000001u) ==
          "GL_MAP_READ_BIT|0x80000000");
    CHECK(fw::gl_record::bits_name(GLAD_GL_GROUP_MapBufferAccessMask, 0) == "0");
}
