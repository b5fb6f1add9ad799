// The record's texture part: a sampler's unit, the texture bound there, the
// sampler state that applies and the texture's levels (record_state.hpp).
#include <algorithm>

#include "framework/trace/record_state.hpp"

namespace fw::gl_record::detail {

namespace {

GLenum binding_of(GLenum target) {
    switch (target) {
        case GL_TEXTURE_1D:
            return GL_TEXTURE_BINDING_1D;
        case GL_TEXTURE_3D:
            return GL_TEXTURE_BINDING_3D;
        case GL_TEXTURE_CUBE_MAP:
            return GL_TEXTURE_BINDING_CUBE_MAP;
        case GL_TEXTURE_2D_ARRAY:
            return GL_TEXTURE_BINDING_2D_ARRAY;
        case GL_TEXTURE_CUBE_MAP_ARRAY:
            return GL_TEXTURE_BINDING_CUBE_MAP_ARRAY;
        case GL_TEXTURE_RECTANGLE:
            return GL_TEXTURE_BINDING_RECTANGLE;
        case GL_TEXTURE_BUFFER:
            return GL_TEXTURE_BINDING_BUFFER;
        case GL_TEXTURE_2D_MULTISAMPLE:
            return GL_TEXTURE_BINDING_2D_MULTISAMPLE;
        default:
            return GL_TEXTURE_BINDING_2D;
    }
}

bool uses_mipmaps(GLenum min_filter) { return min_filter != GL_NEAREST && min_filter != GL_LINEAR; }

// A texture parameter as the unit reads it: a sampler object's where one is
// bound, else the texture's; the base and max levels are always the texture's.
GLint parameter(GLenum target, GLuint sampler, GLenum pname) {
    GLint v = 0;
    if (sampler && pname != GL_TEXTURE_BASE_LEVEL && pname != GL_TEXTURE_MAX_LEVEL)
        glGetSamplerParameteriv(sampler, pname, &v);
    else
        glGetTexParameteriv(target, pname, &v);
    return v;
}

// The filters, the wrap modes (the border colour only where one clamps to
// it) and the compare function where the texture is compared.
void sampler_state(json& t, GLenum target, GLuint sampler, GLenum min_filter) {
    t["min_filter"] = name(min_filter);
    t["mag_filter"] = name(static_cast<GLenum>(parameter(target, sampler, GL_TEXTURE_MAG_FILTER)));
    bool border = false;
    for (auto [pname, field] :
         {std::pair{GL_TEXTURE_WRAP_S, "wrap_s"}, std::pair{GL_TEXTURE_WRAP_T, "wrap_t"},
          std::pair{GL_TEXTURE_WRAP_R, "wrap_r"}}) {
        const GLenum wrap = static_cast<GLenum>(parameter(target, sampler, pname));
        t[field] = name(wrap);
        border = border || wrap == GL_CLAMP_TO_BORDER;
    }
    if (border) {
        GLfloat c[4] = {};
        if (sampler)
            glGetSamplerParameterfv(sampler, GL_TEXTURE_BORDER_COLOR, c);
        else
            glGetTexParameterfv(target, GL_TEXTURE_BORDER_COLOR, c);
        t["border_color"] = {number(c[0]), number(c[1]), number(c[2]), number(c[3])};
    }
    const GLenum compare = static_cast<GLenum>(parameter(target, sampler, GL_TEXTURE_COMPARE_MODE));
    if (compare != GL_NONE)
        t["compare_func"] =
            name(static_cast<GLenum>(parameter(target, sampler, GL_TEXTURE_COMPARE_FUNC)));
}

// The base level's size and format; where the minifying filter reads
// mipmaps, the base level (when not 0) and the levels that exist from it.
void level_state(json& t, GLenum target, GLuint sampler, bool mipmaps) {
    const GLenum face = target == GL_TEXTURE_CUBE_MAP ? GL_TEXTURE_CUBE_MAP_POSITIVE_X : target;
    const GLint base = parameter(target, sampler, GL_TEXTURE_BASE_LEVEL),
                max = parameter(target, sampler, GL_TEXTURE_MAX_LEVEL);
    GLint w = 0, h = 0, d = 0, format = 0;
    glGetTexLevelParameteriv(face, base, GL_TEXTURE_WIDTH, &w);
    glGetTexLevelParameteriv(face, base, GL_TEXTURE_HEIGHT, &h);
    glGetTexLevelParameteriv(face, base, GL_TEXTURE_DEPTH, &d);
    glGetTexLevelParameteriv(face, base, GL_TEXTURE_INTERNAL_FORMAT, &format);
    t["size"] = {w, h, d};
    t["format"] = name(static_cast<GLenum>(format));
    if (!mipmaps) return;
    if (base != 0) t["base_level"] = base;
    int levels = 0;
    for (GLint level = base; level <= std::min(max, base + 16); ++level) {
        GLint lw = 0;
        glGetTexLevelParameteriv(face, level, GL_TEXTURE_WIDTH, &lw);
        if (lw == 0) break;
        ++levels;
    }
    t["levels"] = levels;
}

}  // namespace

// A sampler's unit: the texture bound to the target it reads, the sampler
// state that applies (a sampler object's, else the texture's), and the
// levels that exist when the minifying filter reads mipmaps.
json StateReader::texture_unit(GLint unit, GLenum target) {
    const GLint active = get_integer(GL_ACTIVE_TEXTURE);
    glActiveTexture(GL_TEXTURE0 + static_cast<GLenum>(unit));
    const GLuint texture = static_cast<GLuint>(get_integer(binding_of(target)));
    const GLuint sampler = static_cast<GLuint>(get_integer(GL_SAMPLER_BINDING));
    json t = {{"target", name(target)}, {"texture", names_.of(GL_TEXTURE, texture)}};
    if (texture != 0 && target != GL_TEXTURE_BUFFER) {
        if (sampler) t["sampler"] = names_.of(GL_SAMPLER, sampler);
        const GLenum min_filter =
            static_cast<GLenum>(parameter(target, sampler, GL_TEXTURE_MIN_FILTER));
        sampler_state(t, target, sampler, min_filter);
        level_state(t, target, sampler, uses_mipmaps(min_filter));
    }
    glActiveTexture(static_cast<GLenum>(active));
    return t;
}

}  // namespace fw::gl_record::detail
