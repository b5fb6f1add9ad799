// The GL names the record writes for the enums it records. GL's values
// collide (GL_ZERO, GL_NONE and GL_POINTS are all 0), so each name is looked
// up among the names of the group of the state it belongs to, in GL's one
// table of names (fw::gl_enum_name).
#include <string>

#include "framework/gl/debug.hpp"
#include "framework/trace/record.hpp"

namespace fw::gl_record {

std::string enum_name(EnumKind kind, GLenum value) {
    GladGlGroup group = GLAD_GL_GROUP_any;
    switch (kind) {
        case EnumKind::Mode:
            group = GLAD_GL_GROUP_PrimitiveType;
            break;
        case EnumKind::Factor:
            group = GLAD_GL_GROUP_BlendingFactor;
            break;
        case EnumKind::StencilOp:
            group = GLAD_GL_GROUP_StencilOp;
            break;
        case EnumKind::Other:
            // Of the names of 0, the one a state that is unset holds.
            if (value == GL_NONE) return "GL_NONE";
            break;
    }
    const char* name = fw::gl_enum_name_or_null(value, group);
    return name ? name : fw::gl_enum_name(value);
}

std::string bits_name(GladGlGroup group, GLbitfield value,
                      std::initializer_list<GLbitfield> order) {
    if (value == 0) return "0";
    std::string out;
    const auto add = [&](GLbitfield bit) {
        if (!(value & bit)) return;
        const char* name = fw::gl_enum_name_or_null(bit, group);
        if (!name) return;
        out += (out.empty() ? "" : "|") + std::string(name);
        value &= ~bit;
    };
    if (order.size() == 0)
        for (int i = 0; i < 32; ++i) add(GLbitfield{1} << i);
    for (GLbitfield bit : order) add(bit);
    if (value) {
        char hex[16];
        std::snprintf(hex, sizeof hex, "0x%X", value);
        out += (out.empty() ? "" : "|") + std::string(hex);
    }
    return out;
}

}  // namespace fw::gl_record
