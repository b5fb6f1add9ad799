// Lab 8's sampler state and texture units: the student parts that choose how
// a texture is read (sampler_state.hpp says what each sets).
#include "sampler_state.hpp"

namespace texture_mapping {

void bind_texture(GLuint unit, const fw::Texture2D& texture) {
    // BEGIN SOLUTION
    // STUDENT: (void)unit;  // TODO: glActiveTexture(GL_TEXTURE0 + unit), then glBindTexture
    // STUDENT: glBindTexture(GL_TEXTURE_2D, texture.id());
    glActiveTexture(GL_TEXTURE0 + unit);
    glBindTexture(GL_TEXTURE_2D, texture.id());
    // END SOLUTION
}

void set_wrap(Wrap wrap) {
    GLint mode = GL_REPEAT;
    // BEGIN SOLUTION
    // STUDENT: (void)wrap, (void)mode;  // TODO: the GL name of `wrap` in mode, then
    // STUDENT: // glTexParameteri for GL_TEXTURE_WRAP_S and GL_TEXTURE_WRAP_T, and
    // STUDENT: // glTexParameterfv(GL_TEXTURE_BORDER_COLOR, ...) with kBorderColor
    switch (wrap) {
        case Wrap::Repeat:
            break;
        case Wrap::MirroredRepeat:
            mode = GL_MIRRORED_REPEAT;
            break;
        case Wrap::ClampToEdge:
            mode = GL_CLAMP_TO_EDGE;
            break;
        case Wrap::ClampToBorder:
            mode = GL_CLAMP_TO_BORDER;
            break;
    }
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_S, mode);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_WRAP_T, mode);
    glTexParameterfv(GL_TEXTURE_2D, GL_TEXTURE_BORDER_COLOR, &kBorderColor[0]);
    // END SOLUTION
}

void set_filters(MinFilter min, MagFilter mag) {
    GLint min_mode = GL_NEAREST;
    switch (min) {
        case MinFilter::Nearest:
            min_mode = GL_NEAREST;
            break;
        case MinFilter::Linear:
            min_mode = GL_LINEAR;
            break;
        case MinFilter::NearestMipmapNearest:
            min_mode = GL_NEAREST_MIPMAP_NEAREST;
            break;
        case MinFilter::LinearMipmapLinear:
            min_mode = GL_LINEAR_MIPMAP_LINEAR;
            break;
    }
    const GLint mag_mode = mag == MagFilter::Nearest ? GL_NEAREST : GL_LINEAR;
    // BEGIN SOLUTION
    // STUDENT: (void)min_mode, (void)mag_mode;
    // STUDENT: // TODO: glTexParameteri for GL_TEXTURE_MIN_FILTER and GL_TEXTURE_MAG_FILTER
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MIN_FILTER, min_mode);
    glTexParameteri(GL_TEXTURE_2D, GL_TEXTURE_MAG_FILTER, mag_mode);
    // END SOLUTION
}

void build_mipmaps(const fw::Texture2D& texture) {
    // BEGIN SOLUTION
    // STUDENT: (void)texture;  // TODO: bind it, then glGenerateMipmap(GL_TEXTURE_2D)
    bind_texture(0, texture);
    glGenerateMipmap(GL_TEXTURE_2D);
    // END SOLUTION
}

void bind_maps(const fw::Program& program, const fw::Texture2D& base, const fw::Texture2D& light) {
    // BEGIN SOLUTION
    // STUDENT: // TODO: the light map on unit 1 too, and the samplers: u_texture reads
    // STUDENT: // unit 0, u_light_map unit 1
    // STUDENT: bind_texture(0, base);
    // STUDENT: (void)light, (void)program;
    bind_texture(0, base);
    bind_texture(1, light);
    program.set("u_texture", 0);
    program.set("u_light_map", 1);
    // END SOLUTION
}

}  // namespace texture_mapping
