// The GL names the record writes for the enums it records. GL's values
// collide (GL_ZERO, GL_NONE and GL_POINTS are all 0), so each name is looked
// up in the table of the state it belongs to.
#include <map>
#include <string>

#include "framework/gl/debug.hpp"
#include "framework/gl/record.hpp"

namespace fw::gl_record {

namespace {

#define E(name) std::pair<const GLenum, const char*>(name, #name)

const std::map<GLenum, const char*> kModes = {E(GL_POINTS),
                                              E(GL_LINES),
                                              E(GL_LINE_LOOP),
                                              E(GL_LINE_STRIP),
                                              E(GL_TRIANGLES),
                                              E(GL_TRIANGLE_STRIP),
                                              E(GL_TRIANGLE_FAN),
                                              E(GL_LINES_ADJACENCY),
                                              E(GL_LINE_STRIP_ADJACENCY),
                                              E(GL_TRIANGLES_ADJACENCY),
                                              E(GL_TRIANGLE_STRIP_ADJACENCY),
                                              E(GL_PATCHES)};

const std::map<GLenum, const char*> kFactors = {E(GL_ZERO),
                                                E(GL_ONE),
                                                E(GL_SRC_COLOR),
                                                E(GL_ONE_MINUS_SRC_COLOR),
                                                E(GL_DST_COLOR),
                                                E(GL_ONE_MINUS_DST_COLOR),
                                                E(GL_SRC_ALPHA),
                                                E(GL_ONE_MINUS_SRC_ALPHA),
                                                E(GL_DST_ALPHA),
                                                E(GL_ONE_MINUS_DST_ALPHA),
                                                E(GL_CONSTANT_COLOR),
                                                E(GL_ONE_MINUS_CONSTANT_COLOR),
                                                E(GL_CONSTANT_ALPHA),
                                                E(GL_ONE_MINUS_CONSTANT_ALPHA),
                                                E(GL_SRC_ALPHA_SATURATE),
                                                E(GL_SRC1_COLOR),
                                                E(GL_ONE_MINUS_SRC1_COLOR),
                                                E(GL_SRC1_ALPHA),
                                                E(GL_ONE_MINUS_SRC1_ALPHA)};

const std::map<GLenum, const char*> kStencilOps = {E(GL_KEEP),      E(GL_ZERO),      E(GL_REPLACE),
                                                   E(GL_INCR),      E(GL_INCR_WRAP), E(GL_DECR),
                                                   E(GL_DECR_WRAP), E(GL_INVERT)};

// Everything else the record names: no value here is 0 or 1.
const std::map<GLenum, const char*> kOthers = {
    // types
    E(GL_BYTE), E(GL_UNSIGNED_BYTE), E(GL_SHORT), E(GL_UNSIGNED_SHORT), E(GL_INT),
    E(GL_UNSIGNED_INT), E(GL_FLOAT), E(GL_DOUBLE), E(GL_HALF_FLOAT), E(GL_FIXED),
    E(GL_INT_2_10_10_10_REV), E(GL_UNSIGNED_INT_2_10_10_10_REV), E(GL_UNSIGNED_INT_10F_11F_11F_REV),
    E(GL_UNSIGNED_INT_24_8), E(GL_FLOAT_32_UNSIGNED_INT_24_8_REV),
    // blend equations
    E(GL_FUNC_ADD), E(GL_FUNC_SUBTRACT), E(GL_FUNC_REVERSE_SUBTRACT), E(GL_MIN), E(GL_MAX),
    // comparisons
    E(GL_NEVER), E(GL_LESS), E(GL_EQUAL), E(GL_LEQUAL), E(GL_GREATER), E(GL_NOTEQUAL), E(GL_GEQUAL),
    E(GL_ALWAYS),
    // faces
    E(GL_FRONT), E(GL_BACK), E(GL_FRONT_AND_BACK), E(GL_CW), E(GL_CCW), E(GL_FILL), E(GL_LINE),
    E(GL_POINT),
    // capabilities
    E(GL_BLEND), E(GL_DEPTH_TEST), E(GL_STENCIL_TEST), E(GL_SCISSOR_TEST), E(GL_CULL_FACE),
    E(GL_RASTERIZER_DISCARD), E(GL_CLIP_DISTANCE0), E(GL_CLIP_DISTANCE1), E(GL_CLIP_DISTANCE2),
    E(GL_CLIP_DISTANCE3), E(GL_CLIP_DISTANCE4), E(GL_CLIP_DISTANCE5), E(GL_CLIP_DISTANCE6),
    E(GL_CLIP_DISTANCE7), E(GL_DEPTH_CLAMP), E(GL_POLYGON_OFFSET_FILL), E(GL_POLYGON_OFFSET_LINE),
    E(GL_POLYGON_OFFSET_POINT), E(GL_PROGRAM_POINT_SIZE), E(GL_PRIMITIVE_RESTART),
    E(GL_PRIMITIVE_RESTART_FIXED_INDEX), E(GL_MULTISAMPLE), E(GL_SAMPLE_ALPHA_TO_COVERAGE),
    E(GL_SAMPLE_COVERAGE), E(GL_SAMPLE_SHADING), E(GL_SAMPLE_MASK), E(GL_FRAMEBUFFER_SRGB),
    E(GL_COLOR_LOGIC_OP), E(GL_LINE_SMOOTH), E(GL_POLYGON_SMOOTH), E(GL_DITHER),
    E(GL_TEXTURE_CUBE_MAP_SEAMLESS),
    // texture targets, filters, wraps and compare modes
    E(GL_TEXTURE_1D), E(GL_TEXTURE_2D), E(GL_TEXTURE_3D), E(GL_TEXTURE_CUBE_MAP),
    E(GL_TEXTURE_1D_ARRAY), E(GL_TEXTURE_2D_ARRAY), E(GL_TEXTURE_CUBE_MAP_ARRAY),
    E(GL_TEXTURE_RECTANGLE), E(GL_TEXTURE_BUFFER), E(GL_TEXTURE_2D_MULTISAMPLE), E(GL_NEAREST),
    E(GL_LINEAR), E(GL_NEAREST_MIPMAP_NEAREST), E(GL_LINEAR_MIPMAP_NEAREST),
    E(GL_NEAREST_MIPMAP_LINEAR), E(GL_LINEAR_MIPMAP_LINEAR), E(GL_REPEAT), E(GL_MIRRORED_REPEAT),
    E(GL_CLAMP_TO_EDGE), E(GL_CLAMP_TO_BORDER), E(GL_COMPARE_REF_TO_TEXTURE),
    // formats
    E(GL_RED), E(GL_RG), E(GL_RGB), E(GL_RGBA), E(GL_BGRA), E(GL_DEPTH_COMPONENT),
    E(GL_STENCIL_INDEX), E(GL_DEPTH_STENCIL), E(GL_RED_INTEGER), E(GL_RGBA_INTEGER), E(GL_R8),
    E(GL_RG8), E(GL_RGB8), E(GL_RGBA8), E(GL_SRGB8), E(GL_SRGB8_ALPHA8), E(GL_R16F), E(GL_RG16F),
    E(GL_RGB16F), E(GL_RGBA16F), E(GL_R32F), E(GL_RG32F), E(GL_RGB32F), E(GL_RGBA32F), E(GL_R32I),
    E(GL_R32UI), E(GL_RGBA32I), E(GL_RGBA32UI), E(GL_R11F_G11F_B10F), E(GL_DEPTH_COMPONENT16),
    E(GL_DEPTH_COMPONENT24), E(GL_DEPTH_COMPONENT32F), E(GL_DEPTH24_STENCIL8),
    E(GL_DEPTH32F_STENCIL8), E(GL_STENCIL_INDEX8),
    // buffers, attachments and access
    E(GL_ARRAY_BUFFER), E(GL_ELEMENT_ARRAY_BUFFER), E(GL_UNIFORM_BUFFER),
    E(GL_SHADER_STORAGE_BUFFER), E(GL_TRANSFORM_FEEDBACK_BUFFER), E(GL_COPY_READ_BUFFER),
    E(GL_COPY_WRITE_BUFFER), E(GL_PIXEL_PACK_BUFFER), E(GL_PIXEL_UNPACK_BUFFER),
    E(GL_DRAW_INDIRECT_BUFFER), E(GL_DISPATCH_INDIRECT_BUFFER), E(GL_ATOMIC_COUNTER_BUFFER),
    E(GL_TEXTURE_BUFFER), E(GL_READ_ONLY), E(GL_WRITE_ONLY), E(GL_READ_WRITE), E(GL_COLOR),
    E(GL_DEPTH), E(GL_STENCIL), E(GL_COLOR_ATTACHMENT0), E(GL_COLOR_ATTACHMENT1),
    E(GL_COLOR_ATTACHMENT2), E(GL_COLOR_ATTACHMENT3), E(GL_COLOR_ATTACHMENT4),
    E(GL_COLOR_ATTACHMENT5), E(GL_COLOR_ATTACHMENT6), E(GL_COLOR_ATTACHMENT7), E(GL_BACK_LEFT),
    E(GL_FRONT_LEFT),
    // transform feedback's buffer modes
    E(GL_INTERLEAVED_ATTRIBS), E(GL_SEPARATE_ATTRIBS)};

#undef E

}  // namespace

std::string enum_name(EnumKind kind, GLenum value) {
    const std::map<GLenum, const char*>* table = &kOthers;
    switch (kind) {
        case EnumKind::Mode:
            table = &kModes;
            break;
        case EnumKind::Factor:
            table = &kFactors;
            break;
        case EnumKind::StencilOp:
            table = &kStencilOps;
            break;
        case EnumKind::Other:
            if (value == GL_NONE) return "GL_NONE";
            break;
    }
    auto it = table->find(value);
    return it != table->end() ? it->second : fw::gl_enum_name(value);
}

std::string bits_name(const std::vector<std::pair<GLbitfield, const char*>>& bits,
                      GLbitfield value) {
    if (value == 0) return "0";
    std::string out;
    for (const auto& [bit, name] : bits)
        if (value & bit) {
            out += (out.empty() ? "" : "|") + std::string(name);
            value &= ~bit;
        }
    if (value) {
        char hex[16];
        std::snprintf(hex, sizeof hex, "0x%X", value);
        out += (out.empty() ? "" : "|") + std::string(hex);
    }
    return out;
}

}  // namespace fw::gl_record
