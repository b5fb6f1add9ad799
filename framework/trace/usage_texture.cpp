// Whether the texture a sampler reads is complete (GL 4.3 section 8.17),
// and which types are samplers and images. Queried on the unit's texture
// with the unit made active for the query and made inactive again.
#include <algorithm>
#include <cmath>

#include "framework/gl/debug.hpp"
#include "framework/trace/calls.hpp"
#include "framework/trace/usage_detail.hpp"

namespace fw::gl_usage::detail {

namespace {

struct SamplerType {
    GLenum type, target;
};
constexpr SamplerType kSamplers[] = {
    {GL_SAMPLER_1D, GL_TEXTURE_1D},
    {GL_SAMPLER_2D, GL_TEXTURE_2D},
    {GL_SAMPLER_3D, GL_TEXTURE_3D},
    {GL_SAMPLER_CUBE, GL_TEXTURE_CUBE_MAP},
    {GL_SAMPLER_1D_SHADOW, GL_TEXTURE_1D},
    {GL_SAMPLER_2D_SHADOW, GL_TEXTURE_2D},
    {GL_SAMPLER_1D_ARRAY, GL_TEXTURE_1D_ARRAY},
    {GL_SAMPLER_2D_ARRAY, GL_TEXTURE_2D_ARRAY},
    {GL_SAMPLER_1D_ARRAY_SHADOW, GL_TEXTURE_1D_ARRAY},
    {GL_SAMPLER_2D_ARRAY_SHADOW, GL_TEXTURE_2D_ARRAY},
    {GL_SAMPLER_CUBE_SHADOW, GL_TEXTURE_CUBE_MAP},
    {GL_SAMPLER_2D_RECT, GL_TEXTURE_RECTANGLE},
    {GL_SAMPLER_2D_RECT_SHADOW, GL_TEXTURE_RECTANGLE},
    {GL_SAMPLER_CUBE_MAP_ARRAY, GL_TEXTURE_CUBE_MAP_ARRAY},
    {GL_SAMPLER_CUBE_MAP_ARRAY_SHADOW, GL_TEXTURE_CUBE_MAP_ARRAY},
    {GL_INT_SAMPLER_1D, GL_TEXTURE_1D},
    {GL_INT_SAMPLER_2D, GL_TEXTURE_2D},
    {GL_INT_SAMPLER_3D, GL_TEXTURE_3D},
    {GL_INT_SAMPLER_CUBE, GL_TEXTURE_CUBE_MAP},
    {GL_INT_SAMPLER_1D_ARRAY, GL_TEXTURE_1D_ARRAY},
    {GL_INT_SAMPLER_2D_ARRAY, GL_TEXTURE_2D_ARRAY},
    {GL_INT_SAMPLER_2D_RECT, GL_TEXTURE_RECTANGLE},
    {GL_INT_SAMPLER_CUBE_MAP_ARRAY, GL_TEXTURE_CUBE_MAP_ARRAY},
    {GL_UNSIGNED_INT_SAMPLER_1D, GL_TEXTURE_1D},
    {GL_UNSIGNED_INT_SAMPLER_2D, GL_TEXTURE_2D},
    {GL_UNSIGNED_INT_SAMPLER_3D, GL_TEXTURE_3D},
    {GL_UNSIGNED_INT_SAMPLER_CUBE, GL_TEXTURE_CUBE_MAP},
    {GL_UNSIGNED_INT_SAMPLER_1D_ARRAY, GL_TEXTURE_1D_ARRAY},
    {GL_UNSIGNED_INT_SAMPLER_2D_ARRAY, GL_TEXTURE_2D_ARRAY},
    {GL_UNSIGNED_INT_SAMPLER_2D_RECT, GL_TEXTURE_RECTANGLE},
    {GL_UNSIGNED_INT_SAMPLER_CUBE_MAP_ARRAY, GL_TEXTURE_CUBE_MAP_ARRAY},
    // Read by the checks as samplers, never judged complete or not here:
    // a buffer texture or a multisample one has no mipmaps or filters.
    {GL_SAMPLER_BUFFER, GL_TEXTURE_BUFFER},
    {GL_INT_SAMPLER_BUFFER, GL_TEXTURE_BUFFER},
    {GL_UNSIGNED_INT_SAMPLER_BUFFER, GL_TEXTURE_BUFFER},
    {GL_SAMPLER_2D_MULTISAMPLE, GL_TEXTURE_2D_MULTISAMPLE},
    {GL_INT_SAMPLER_2D_MULTISAMPLE, GL_TEXTURE_2D_MULTISAMPLE},
    {GL_UNSIGNED_INT_SAMPLER_2D_MULTISAMPLE, GL_TEXTURE_2D_MULTISAMPLE},
    {GL_SAMPLER_2D_MULTISAMPLE_ARRAY, GL_TEXTURE_2D_MULTISAMPLE_ARRAY},
    {GL_INT_SAMPLER_2D_MULTISAMPLE_ARRAY, GL_TEXTURE_2D_MULTISAMPLE_ARRAY},
    {GL_UNSIGNED_INT_SAMPLER_2D_MULTISAMPLE_ARRAY, GL_TEXTURE_2D_MULTISAMPLE_ARRAY},
};

struct Target {
    GLenum target, binding;
    int shrinking;  // dimensions that halve from level to level (the rest are layers)
    GLenum max_size;
};
constexpr Target kTargets[] = {
    {GL_TEXTURE_1D, GL_TEXTURE_BINDING_1D, 1, GL_MAX_TEXTURE_SIZE},
    {GL_TEXTURE_2D, GL_TEXTURE_BINDING_2D, 2, GL_MAX_TEXTURE_SIZE},
    {GL_TEXTURE_3D, GL_TEXTURE_BINDING_3D, 3, GL_MAX_3D_TEXTURE_SIZE},
    {GL_TEXTURE_CUBE_MAP, GL_TEXTURE_BINDING_CUBE_MAP, 2, GL_MAX_CUBE_MAP_TEXTURE_SIZE},
    {GL_TEXTURE_1D_ARRAY, GL_TEXTURE_BINDING_1D_ARRAY, 1, GL_MAX_TEXTURE_SIZE},
    {GL_TEXTURE_2D_ARRAY, GL_TEXTURE_BINDING_2D_ARRAY, 2, GL_MAX_TEXTURE_SIZE},
    {GL_TEXTURE_RECTANGLE, GL_TEXTURE_BINDING_RECTANGLE, 2, 0},
    {GL_TEXTURE_CUBE_MAP_ARRAY, GL_TEXTURE_BINDING_CUBE_MAP_ARRAY, 2, GL_MAX_CUBE_MAP_TEXTURE_SIZE},
    {GL_TEXTURE_BUFFER, GL_TEXTURE_BINDING_BUFFER, 0, 0},
    {GL_TEXTURE_2D_MULTISAMPLE, GL_TEXTURE_BINDING_2D_MULTISAMPLE, 0, 0},
    {GL_TEXTURE_2D_MULTISAMPLE_ARRAY, GL_TEXTURE_BINDING_2D_MULTISAMPLE_ARRAY, 0, 0},
};

const Target* target_of(GLenum target) {
    for (const Target& t : kTargets)
        if (t.target == target) return &t;
    return nullptr;
}

bool is_integer_format(GLint f) {
    static const GLint kInteger[] = {
        GL_R8I,      GL_R8UI,    GL_R16I,     GL_R16UI,     GL_R32I,   GL_R32UI,   GL_RG8I,
        GL_RG8UI,    GL_RG16I,   GL_RG16UI,   GL_RG32I,     GL_RG32UI, GL_RGB8I,   GL_RGB8UI,
        GL_RGB16I,   GL_RGB16UI, GL_RGB32I,   GL_RGB32UI,   GL_RGBA8I, GL_RGBA8UI, GL_RGBA16I,
        GL_RGBA16UI, GL_RGBA32I, GL_RGBA32UI, GL_RGB10_A2UI};
    return std::find(std::begin(kInteger), std::end(kInteger), f) != std::end(kInteger);
}

// A min or mag filter's name (GL_LINEAR is one of both).
std::string filter_name(GLint f) {
    return fw::gl_enum_name(GLenum(f), GLAD_GL_GROUP_TextureMinFilter);
}

struct Level {
    GLint size[3] = {0, 0, 0};
    GLint format = 0;
    bool exists() const { return size[0] > 0; }
};

std::string dims(const Level& l, int n) {
    std::string s = std::to_string(l.size[0]);
    for (int i = 1; i < n; ++i) s += "x" + std::to_string(l.size[i]);
    return s;
}

// What completeness depends on, of the texture bound to a target on the
// active unit: its levels' range and the filters that read it.
struct Bound {
    const Target* t = nullptr;
    GLint base = 0, max = 0, min_filter = 0, mag_filter = 0;
    bool immutable = false;
    std::string filters_of;  // " (the sampler object's)" where a sampler object filters
    int last_level = 0;      // the last level GL lets one ask about
    int faces = 1, dims = 2;

    Bound(const Target& target, GLuint sampler) : t(&target) {
        GLint immutable_format = 0, levels = 0;
        glGetTexParameteriv(t->target, GL_TEXTURE_IMMUTABLE_FORMAT, &immutable_format);
        glGetTexParameteriv(t->target, GL_TEXTURE_IMMUTABLE_LEVELS, &levels);
        glGetTexParameteriv(t->target, GL_TEXTURE_BASE_LEVEL, &base);
        glGetTexParameteriv(t->target, GL_TEXTURE_MAX_LEVEL, &max);
        if (sampler) {
            glGetSamplerParameteriv(sampler, GL_TEXTURE_MIN_FILTER, &min_filter);
            glGetSamplerParameteriv(sampler, GL_TEXTURE_MAG_FILTER, &mag_filter);
            filters_of = " (the sampler object's)";
        } else {
            glGetTexParameteriv(t->target, GL_TEXTURE_MIN_FILTER, &min_filter);
            glGetTexParameteriv(t->target, GL_TEXTURE_MAG_FILTER, &mag_filter);
        }
        // Immutable storage: base and max are clamped to the levels it has
        // (8.14.3), so that every level the filter reads exists.
        immutable = immutable_format != 0;
        if (immutable) {
            base = std::clamp(base, 0, std::max(levels - 1, 0));
            max = std::clamp(max, base, std::max(levels - 1, 0));
        }
        GLint largest = 1;
        if (t->max_size) glGetIntegerv(t->max_size, &largest);
        last_level = static_cast<int>(std::floor(std::log2(std::max(largest, 1))));
        faces = t->target == GL_TEXTURE_CUBE_MAP ? 6 : 1;
        const GLenum k = t->target;
        dims = k == GL_TEXTURE_3D || k == GL_TEXTURE_2D_ARRAY || k == GL_TEXTURE_CUBE_MAP_ARRAY ? 3
               : k == GL_TEXTURE_1D                                                             ? 1
                                                                                                : 2;
    }

    Level level(int l, int face) const {
        Level out;
        if (l > last_level || (t->max_size == 0 && l > 0)) return out;
        const GLenum at = faces == 6 ? GL_TEXTURE_CUBE_MAP_POSITIVE_X + face : t->target;
        const GLenum params[3] = {GL_TEXTURE_WIDTH, GL_TEXTURE_HEIGHT, GL_TEXTURE_DEPTH};
        for (int i = 0; i < 3; ++i) glGetTexLevelParameteriv(at, l, params[i], &out.size[i]);
        glGetTexLevelParameteriv(at, l, GL_TEXTURE_INTERNAL_FORMAT, &out.format);
        return out;
    }
};

// Why the base level (every face of it) cannot be read, or "".
std::string base_incomplete(const Bound& b, const Level& first) {
    if (!b.immutable && b.base > b.max)
        return "its base level (" + std::to_string(b.base) + ") is above its max level (" +
               std::to_string(b.max) + ")";
    if (!first.exists())
        return "level " + std::to_string(b.base) +
               " (its base level) has no image: no glTexImage or glTexStorage gave it one";
    for (int f = 1; f < b.faces; ++f) {
        const Level other = b.level(b.base, f);
        if (!other.exists() || other.size[0] != first.size[0] || other.size[1] != first.size[1] ||
            other.format != first.format)
            return "its six faces at level " + std::to_string(b.base) +
                   " are not all images of one size and format (face " + std::to_string(f) +
                   " differs from face 0)";
    }
    if (b.faces == 6 && first.size[0] != first.size[1])
        return "its faces are " + dims(first, 2) + ", not square";
    if (is_integer_format(first.format) &&
        (b.mag_filter != GL_NEAREST ||
         (b.min_filter != GL_NEAREST && b.min_filter != GL_NEAREST_MIPMAP_NEAREST)))
        return "its format is an integer one, which only GL_NEAREST and "
               "GL_NEAREST_MIPMAP_NEAREST filters may read, and its filters" +
               b.filters_of + " are " + filter_name(b.mag_filter) + " and " +
               filter_name(b.min_filter);
    return "";
}

// Why the levels a mipmap filter reads after the base are not a chain, or "".
std::string mipmaps_incomplete(const Bound& b, const Level& first) {
    int largest_size = 1;
    for (int i = 0; i < b.t->shrinking; ++i) largest_size = std::max(largest_size, first.size[i]);
    const int q = std::min(b.base + static_cast<int>(std::floor(std::log2(largest_size))), b.max);
    const std::string reads = std::string("its min filter") + b.filters_of + " " +
                              filter_name(b.min_filter) + " reads levels " +
                              std::to_string(b.base) + " to " + std::to_string(q) + ", and ";
    for (int l = b.base + 1; l <= q; ++l) {
        Level want = first;
        for (int i = 0; i < b.t->shrinking; ++i)
            want.size[i] = std::max(1, first.size[i] >> (l - b.base));
        for (int f = 0; f < b.faces; ++f) {
            const Level got = b.level(l, f);
            const std::string at = "level " + std::to_string(l);
            if (!got.exists())
                return reads + at +
                       " has no image (glGenerateMipmap makes them; GL_LINEAR or GL_NEAREST "
                       "reads the base level alone)";
            if (dims(got, b.dims) != dims(want, b.dims))
                return reads + at + " is " + dims(got, b.dims) + ", not the " + dims(want, b.dims) +
                       " that halving level " + std::to_string(b.base) + " gives";
            if (got.format != first.format)
                return reads + at + " has another internal format than level " +
                       std::to_string(b.base);
        }
    }
    return "";
}

// Why the texture bound to `t` on the active unit is incomplete, or "".
std::string why_incomplete(const Target& t, GLuint sampler) {
    const Bound b(t, sampler);
    const Level first = b.level(b.base, 0);
    const std::string base = base_incomplete(b, first);
    if (!base.empty()) return base;
    const bool mipmapped = b.min_filter != GL_NEAREST && b.min_filter != GL_LINEAR;
    return mipmapped ? mipmaps_incomplete(b, first) : "";
}

}  // namespace

bool is_sampler(GLenum type) {
    return std::any_of(std::begin(kSamplers), std::end(kSamplers),
                       [&](const SamplerType& s) { return s.type == type; });
}

bool is_image(GLenum type) {
    return type >= GL_IMAGE_1D && type <= GL_UNSIGNED_INT_IMAGE_2D_MULTISAMPLE_ARRAY;
}

GLenum sampler_target(GLenum type) {
    for (const SamplerType& s : kSamplers)
        if (s.type == type) return s.target;
    return 0;
}

std::string target_name(GLenum target) {
    return target_of(target) ? fw::gl_enum_name(target, GLAD_GL_GROUP_TextureTarget)
                             : "a texture target";
}

UnitTexture texture_on_unit(GLuint unit, GLenum target) {
    UnitTexture out;
    const Target* t = target_of(target);
    if (!t) return out;
    gl_calls::Unobserved quiet;
    GLint active = GL_TEXTURE0, texture = 0, sampler = 0;
    glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
    glActiveTexture(GL_TEXTURE0 + unit);
    glGetIntegerv(t->binding, &texture);
    glGetIntegerv(GL_SAMPLER_BINDING, &sampler);
    out.texture = static_cast<GLuint>(texture);
    if (texture == 0)
        out.incomplete = std::string("no texture is bound to ") + target_name(target) + " on it";
    else if (t->shrinking > 0)
        out.incomplete = why_incomplete(*t, static_cast<GLuint>(sampler));
    glActiveTexture(static_cast<GLenum>(active));
    return out;
}

}  // namespace fw::gl_usage::detail
