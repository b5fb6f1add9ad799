// Lab 13's scenes (scenes.hpp).
#include "scenes.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace surface_detail {

namespace {

// The two triangles of a square, its corners counter-clockwise from the
// lower left, with their texture coordinates.
void add_square(std::vector<BumpVertex>& out, const glm::vec3 (&p)[4], const glm::vec2 (&uv)[4]) {
    const glm::vec3 n(0.0f, 0.0f, 1.0f);
    for (const glm::ivec3 tri : {glm::ivec3(0, 1, 2), glm::ivec3(0, 2, 3)}) {
        const glm::mat3 tbn =
            tangent_frame(p[tri.x], p[tri.y], p[tri.z], uv[tri.x], uv[tri.y], uv[tri.z], n);
        for (int k = 0; k < 3; ++k) out.push_back({p[tri[k]], n, tbn[0], tbn[1], uv[tri[k]]});
    }
}

fw::Rgba8 rgba(glm::vec3 c) {
    return {static_cast<std::uint8_t>(255 * c.r), static_cast<std::uint8_t>(255 * c.g),
            static_cast<std::uint8_t>(255 * c.b), 255};
}

}  // namespace

std::vector<BumpVertex> bump_squares() {
    std::vector<BumpVertex> out;
    add_square(out, {{-3.5f, -1.5f, 0}, {-0.5f, -1.5f, 0}, {-0.5f, 1.5f, 0}, {-3.5f, 1.5f, 0}},
               {{0, 0}, {1, 0}, {1, 1}, {0, 1}});
    // B: u = (y + 1.5) / 3, v = (3.5 - x) / 3.
    add_square(out, {{0.5f, -1.5f, 0}, {3.5f, -1.5f, 0}, {3.5f, 1.5f, 0}, {0.5f, 1.5f, 0}},
               {{0, 1}, {0, 0}, {1, 0}, {1, 1}});
    return out;
}

HeightMap height_map() {
    HeightMap map{64, std::vector<float>(64 * 64)};
    for (int j = 0; j < 64; ++j)
        for (int i = 0; i < 64; ++i) {
            const float x = static_cast<float>(i % 16) - 7.5f,
                        y = static_cast<float>(j % 16) - 7.5f;
            map.h[static_cast<size_t>(j * 64 + i)] = glm::max(0.0f, 1.0f - (x * x + y * y) / 36.0f);
        }
    return map;
}

glm::vec3 height_normal(int i, int j, float scale) {
    static const HeightMap map = height_map();
    return normal_map(map, scale)[static_cast<size_t>(j * map.size + i)];
}

glm::mat4 bump_projection() { return glm::ortho(-4.0f, 4.0f, -4.0f, 4.0f, -1.0f, 1.0f); }

CubeFaces cube_faces() {
    const glm::vec3 colors[6] = {{1, 0, 0}, {0, 1, 1}, {0, 1, 0}, {1, 0, 1}, {0, 0, 1}, {1, 1, 0}};
    CubeFaces faces;
    for (int f = 0; f < 6; ++f) {
        faces[static_cast<size_t>(f)] = fw::Image(kFaceSize, kFaceSize, rgba(colors[f]));
        faces[static_cast<size_t>(f)].at(0, 0) = rgba(glm::vec3(1.0f));
    }
    return faces;
}

std::vector<Triangle> ray_scene() {
    const glm::vec3 grey(0.8f), red(0.9f, 0.1f, 0.1f), blue(0.1f, 0.1f, 0.9f);
    std::vector<Triangle> s = {{{-20, 0, 6}, {20, 0, 6}, {0, 0, -30}, grey}};
    // The cube x in [-1.5, -0.5], y in [0, 1], z in [-0.6, 0.4], no bottom.
    const glm::vec3 c[8] = {{-1.5f, 0, 0.4f},  {-0.5f, 0, 0.4f},  {-0.5f, 1, 0.4f},
                            {-1.5f, 1, 0.4f},  {-1.5f, 0, -0.6f}, {-0.5f, 0, -0.6f},
                            {-0.5f, 1, -0.6f}, {-1.5f, 1, -0.6f}};
    for (const glm::ivec4 q :
         {glm::ivec4(0, 1, 2, 3), glm::ivec4(1, 5, 6, 2), glm::ivec4(5, 4, 7, 6),
          glm::ivec4(4, 0, 3, 7), glm::ivec4(3, 2, 6, 7)}) {
        s.push_back({c[q.x], c[q.y], c[q.z], red});
        s.push_back({c[q.x], c[q.z], c[q.w], red});
    }
    // The pyramid: base x in [0.6, 1.6], z in [-0.6, 0.4], apex (1.1, 1.2, -0.1).
    const glm::vec3 apex(1.1f, 1.2f, -0.1f);
    const glm::vec3 base[4] = {
        {0.6f, 0, 0.4f}, {1.6f, 0, 0.4f}, {1.6f, 0, -0.6f}, {0.6f, 0, -0.6f}};
    for (int k = 0; k < 4; ++k) s.push_back({base[k], base[(k + 1) % 4], apex, blue});
    return s;
}

glm::mat4 ray_view_projection() {
    return glm::perspective(glm::radians(45.0f), 1.0f, 0.5f, 20.0f) *
           glm::lookAt(kEye, glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
}

}  // namespace surface_detail
