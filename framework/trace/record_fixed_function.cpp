// The record's fixed-function part: what a draw's fragments meet after the
// program (viewport, colour mask, blending, depth and stencil tests, scissor,
// culling, polygon mode, line width and point size) and the framebuffer
// they are written to (record_state.hpp).
#include "framework/trace/record_state.hpp"

namespace fw::gl_record::detail {

namespace {

bool uses_constant(GLenum factor) {
    return factor == GL_CONSTANT_COLOR || factor == GL_ONE_MINUS_CONSTANT_COLOR ||
           factor == GL_CONSTANT_ALPHA || factor == GL_ONE_MINUS_CONSTANT_ALPHA;
}

// The blend factors and equations (with blending on and colour written):
// alpha's only where alpha is written, the blend colour only where a factor
// reads it.
json blend_state(bool alpha) {
    const GLenum src = static_cast<GLenum>(get_integer(GL_BLEND_SRC_RGB)),
                 dst = static_cast<GLenum>(get_integer(GL_BLEND_DST_RGB));
    json blend = {{"src_rgb", name(src, EnumKind::Factor)},
                  {"dst_rgb", name(dst, EnumKind::Factor)},
                  {"equation_rgb", name_of(GL_BLEND_EQUATION_RGB)}};
    bool constant = uses_constant(src) || uses_constant(dst);
    if (alpha) {
        const GLenum sa = static_cast<GLenum>(get_integer(GL_BLEND_SRC_ALPHA)),
                     da = static_cast<GLenum>(get_integer(GL_BLEND_DST_ALPHA));
        blend["src_alpha"] = name(sa, EnumKind::Factor);
        blend["dst_alpha"] = name(da, EnumKind::Factor);
        blend["equation_alpha"] = name_of(GL_BLEND_EQUATION_ALPHA);
        constant = constant || uses_constant(sa) || uses_constant(da);
    }
    if (constant) blend["color"] = floats(GL_BLEND_COLOR, 4);
    return blend;
}

// One face's stencil function, reference, operations and masks, by the
// state that holds each.
json stencil_face(GLenum func, GLenum ref, GLenum value_mask, GLenum fail, GLenum zfail,
                  GLenum zpass, GLenum write_mask) {
    return json{{"func", name_of(func)},
                {"ref", get_integer(ref)},
                {"value_mask", get_integer(value_mask) & 0xFF},
                {"fail", name_of(fail, EnumKind::StencilOp)},
                {"zfail", name_of(zfail, EnumKind::StencilOp)},
                {"zpass", name_of(zpass, EnumKind::StencilOp)},
                {"write_mask", get_integer(write_mask) & 0xFF}};
}

// The stencil test's state (with the test on): the front face's, and the
// back face's for triangles where it differs.
void stencil_state(json& event, bool triangles) {
    const json front =
        stencil_face(GL_STENCIL_FUNC, GL_STENCIL_REF, GL_STENCIL_VALUE_MASK, GL_STENCIL_FAIL,
                     GL_STENCIL_PASS_DEPTH_FAIL, GL_STENCIL_PASS_DEPTH_PASS, GL_STENCIL_WRITEMASK);
    event["stencil"] = front;
    if (!triangles) return;
    const json back =
        stencil_face(GL_STENCIL_BACK_FUNC, GL_STENCIL_BACK_REF, GL_STENCIL_BACK_VALUE_MASK,
                     GL_STENCIL_BACK_FAIL, GL_STENCIL_BACK_PASS_DEPTH_FAIL,
                     GL_STENCIL_BACK_PASS_DEPTH_PASS, GL_STENCIL_BACK_WRITEMASK);
    if (back != front) event["stencil_back"] = back;
}

// How primitives of `mode` are rasterized: the cull and front face and the
// polygon mode for triangles, the line width for lines, the point size where
// the program does not set it.
void rasterization_state(json& event, GLenum mode, bool triangles) {
    if (triangles && glIsEnabled(GL_CULL_FACE))
        event["cull"] = {{"face", name_of(GL_CULL_FACE_MODE)},
                         {"front_face", name_of(GL_FRONT_FACE)}};
    if (triangles) {
        const std::string polygon = name_of(GL_POLYGON_MODE);
        if (polygon != "GL_FILL") event["polygon_mode"] = polygon;
    }
    if (!triangles && mode != GL_POINTS) event["line_width"] = number(floats(GL_LINE_WIDTH, 1)[0]);
    if (mode == GL_POINTS && !glIsEnabled(GL_PROGRAM_POINT_SIZE))
        event["point_size"] = number(floats(GL_POINT_SIZE, 1)[0]);
}

}  // namespace

json StateReader::framebuffer(GLenum binding, GLenum target) {
    const GLuint fbo = static_cast<GLuint>(get_integer(binding));
    json f = {{"label", names_.of(GL_FRAMEBUFFER, fbo)}};
    if (fbo == 0) return f;
    auto attached = [&](GLenum attachment) -> std::string {
        GLint type = GL_NONE, object = 0;
        glGetFramebufferAttachmentParameteriv(target, attachment,
                                              GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE, &type);
        if (type == GL_NONE) return "";
        glGetFramebufferAttachmentParameteriv(target, attachment,
                                              GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME, &object);
        if (type == GL_RENDERBUFFER) return names_.of(GL_RENDERBUFFER, static_cast<GLuint>(object));
        GLint level = 0, layer = 0, layered = 0;
        glGetFramebufferAttachmentParameteriv(target, attachment,
                                              GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL, &level);
        glGetFramebufferAttachmentParameteriv(target, attachment, GL_FRAMEBUFFER_ATTACHMENT_LAYERED,
                                              &layered);
        glGetFramebufferAttachmentParameteriv(target, attachment,
                                              GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LAYER, &layer);
        std::string out = names_.of(GL_TEXTURE, static_cast<GLuint>(object));
        if (level) out += " level " + std::to_string(level);
        if (layered)
            out += " layered";
        else if (layer)
            out += " layer " + std::to_string(layer);
        return out;
    };
    for (GLenum i = 0; i < 8; ++i) {
        const std::string a = attached(GL_COLOR_ATTACHMENT0 + i);
        if (!a.empty()) f["color" + std::to_string(i)] = a;
    }
    for (auto [attachment, field] :
         {std::pair{GL_DEPTH_ATTACHMENT, "depth"}, std::pair{GL_STENCIL_ATTACHMENT, "stencil"}}) {
        const std::string a = attached(attachment);
        if (!a.empty()) f[field] = a;
    }
    return f;
}

void StateReader::fragment_state(json& event, GLenum mode) {
    event["viewport"] = ints(GL_VIEWPORT, 4);
    GLboolean mask[4] = {};
    glGetBooleanv(GL_COLOR_WRITEMASK, mask);
    event["color_mask"] = {mask[0] != 0, mask[1] != 0, mask[2] != 0, mask[3] != 0};
    const bool colour = mask[0] || mask[1] || mask[2] || mask[3];
    const bool triangles = mode != GL_POINTS && mode != GL_LINES && mode != GL_LINE_LOOP &&
                           mode != GL_LINE_STRIP && mode != GL_LINES_ADJACENCY &&
                           mode != GL_LINE_STRIP_ADJACENCY;
    if (glIsEnabled(GL_BLEND) && colour) event["blend"] = blend_state(mask[3] != 0);
    // GL writes depth only where the depth test is on (GL 4.3, 17.3.6).
    if (glIsEnabled(GL_DEPTH_TEST)) {
        GLboolean depth_mask = GL_TRUE;
        glGetBooleanv(GL_DEPTH_WRITEMASK, &depth_mask);
        event["depth"] = {{"func", name_of(GL_DEPTH_FUNC)},
                          {"mask", depth_mask != 0},
                          {"range", floats(GL_DEPTH_RANGE, 2)}};
    }
    if (glIsEnabled(GL_STENCIL_TEST)) stencil_state(event, triangles);
    if (glIsEnabled(GL_SCISSOR_TEST)) event["scissor"] = ints(GL_SCISSOR_BOX, 4);
    rasterization_state(event, mode, triangles);
    event["framebuffer"] = framebuffer(GL_DRAW_FRAMEBUFFER_BINDING, GL_DRAW_FRAMEBUFFER);
}

}  // namespace fw::gl_record::detail
