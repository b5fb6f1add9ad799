// Lab 13's cube map faces (environment.hpp says what the part does).
#include "environment.hpp"

namespace surface_detail {

void upload_cube_faces(const fw::TextureCube& cube, const CubeFaces& faces) {
    cube.bind(0);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    for (int face = 0; face < 6; ++face) {
        const fw::Image& image = faces[static_cast<size_t>(face)];
        // BEGIN SOLUTION
        // STUDENT: (void)image;  // TODO: glTexSubImage2D into the face's target, which is
        // STUDENT: // GL_TEXTURE_CUBE_MAP_POSITIVE_X + face in GL's order (environment.hpp)
        glTexSubImage2D(GL_TEXTURE_CUBE_MAP_POSITIVE_X + face, 0, 0, 0, image.width, image.height,
                        GL_RGBA, GL_UNSIGNED_BYTE, image.pixels.data());
        // END SOLUTION
    }
}

}  // namespace surface_detail
