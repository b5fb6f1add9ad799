#include "geometry_scene.hpp"

#include <algorithm>
#include <glm/gtc/matrix_transform.hpp>

namespace geometry_test {

namespace {

// The direction from the eye through pixel (x, y)'s centre. The view is a
// translation by -4 along z, so eye and world directions are the same.
glm::vec3 ray_direction(int x, int y) {
    const glm::vec2 ndc = (glm::vec2(x + 0.5f, y + 0.5f) / (kSize / 2.0f)) - 1.0f;
    return {ndc.x / kFocal, ndc.y / kFocal, -1.0f};
}

float cross2(glm::vec2 a, glm::vec2 b) { return a.x * b.y - a.y * b.x; }

float distance_to_segment(glm::vec2 p, glm::vec2 a, glm::vec2 b) {
    const glm::vec2 ab = b - a;
    const float t = glm::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0f, 1.0f);
    return glm::length(p - (a + t * ab));
}

}  // namespace

glm::mat3 rotate_y(float degrees) {
    return glm::mat3(glm::rotate(glm::mat4(1.0f), glm::radians(degrees), {0.0f, 1.0f, 0.0f}));
}

glm::vec2 to_window(glm::vec3 world) {
    const glm::vec3 eye = world - kEye;
    const glm::vec2 ndc = kFocal * glm::vec2(eye.x, eye.y) / -eye.z;
    return (ndc + 1.0f) * (kSize / 2.0f);
}

glm::ivec2 pixel_of(glm::vec2 window) {
    return {static_cast<int>(std::floor(window.x)), static_cast<int>(std::floor(window.y))};
}

float silhouette_radius(float r) {
    return kSize / 2.0f * kFocal * r / std::sqrt(glm::dot(kEye, kEye) - r * r);
}

std::optional<glm::vec3> sphere_color(int x, int y, glm::vec3 centre, glm::vec3 color) {
    // |eye + t d - centre|^2 = 1: a t^2 + 2 b t + c = 0, nearest root.
    const glm::vec3 d = ray_direction(x, y), m = kEye - centre;
    const float a = glm::dot(d, d), b = glm::dot(m, d), c = glm::dot(m, m) - 1.0f;
    const float disc = b * b - a * c;
    if (disc < 0.0f) return std::nullopt;
    const glm::vec3 normal = kEye + (-b - std::sqrt(disc)) / a * d - centre;
    return color * std::max(glm::dot(normal, kLight), 0.0f);
}

std::vector<Face> icosahedron_faces(glm::mat3 model) {
    // (0, +-1, +-p), (+-1, +-p, 0), (+-p, 0, +-1) with p the golden ratio.
    const float p = (1.0f + std::sqrt(5.0f)) / 2.0f;
    std::vector<glm::vec3> corners;
    for (float s : {-1.0f, 1.0f})
        for (float t : {-1.0f, 1.0f})
            for (glm::vec3 c :
                 {glm::vec3(0, s, t * p), glm::vec3(s, t * p, 0), glm::vec3(t * p, 0, s)})
                corners.push_back(glm::normalize(c));
    const float edge = 2.0f / std::sqrt(1.0f + p * p);
    auto neighbours = [&](size_t i, size_t j) {
        return std::abs(glm::distance(corners[i], corners[j]) - edge) < 1e-4f;
    };
    std::vector<Face> faces;
    for (size_t i = 0; i < corners.size(); ++i)
        for (size_t j = i + 1; j < corners.size(); ++j)
            for (size_t k = j + 1; k < corners.size(); ++k) {
                if (!neighbours(i, j) || !neighbours(j, k) || !neighbours(i, k)) continue;
                glm::vec3 a = model * corners[i], b = model * corners[j], c = model * corners[k];
                if (glm::dot(glm::cross(b - a, c - a), a + b + c) < 0.0f) std::swap(b, c);
                faces.push_back({{a, b, c}, {a, b, c}, kGrey});
            }
    return faces;
}

std::vector<Face> moved(std::vector<Face> faces, glm::vec3 offset, glm::vec3 color) {
    for (Face& f : faces) {
        for (glm::vec3& p : f.p) p += offset;
        f.color = color;
    }
    return faces;
}

std::vector<Face> exploded(std::vector<Face> faces, float amount) {
    for (Face& f : faces) {
        const glm::vec3 n = glm::normalize(glm::cross(f.p[1] - f.p[0], f.p[2] - f.p[0]));
        for (glm::vec3& p : f.p) p += amount * n;
    }
    return faces;
}

std::vector<Projected> project(const std::vector<Face>& faces) {
    std::vector<Projected> front;
    for (const Face& f : faces) {
        Projected p{f, {}, {}, 0.0f, glm::vec2(1e30f), glm::vec2(-1e30f)};
        for (int i = 0; i < 3; ++i) {
            p.w[i] = to_window(f.p[i]);
            p.clip_w[i] = kEye.z - f.p[i].z;  // -z in eye space
            p.lo = glm::min(p.lo, p.w[i]);
            p.hi = glm::max(p.hi, p.w[i]);
        }
        // GL culls by the winding on screen: counter-clockwise is front.
        p.area2 = cross2(p.w[1] - p.w[0], p.w[2] - p.w[0]);
        if (p.area2 > 0.0f) front.push_back(p);
    }
    return front;
}

Hit cast(const std::vector<Projected>& faces, int x, int y, float margin) {
    const glm::vec2 centre(x + 0.5f, y + 0.5f);
    Hit hit;
    float nearest_w = 1e30f;
    for (const Projected& p : faces) {
        if (glm::any(glm::lessThan(centre, p.lo - margin)) ||
            glm::any(glm::greaterThan(centre, p.hi + margin)))
            continue;
        const glm::vec2* w = p.w;
        const float* clip_w = p.clip_w;
        const float area2 = p.area2;
        for (int i = 0; i < 3; ++i)
            if (distance_to_segment(centre, w[(i + 1) % 3], w[(i + 2) % 3]) < margin)
                hit.ambiguous = true;
        // Window-space barycentric coordinates; inside when all are >= 0.
        float l[3];
        for (int i = 0; i < 3; ++i)
            l[i] = cross2(w[(i + 2) % 3] - w[(i + 1) % 3], centre - w[(i + 1) % 3]) / area2;
        if (l[0] < 0.0f || l[1] < 0.0f || l[2] < 0.0f) continue;
        // Perspective-correct weights (the GL spec's interpolation): l_i / w_i,
        // normalised; 1 / sum(l_i / w_i) is the eye depth at the pixel.
        const float inv_w = l[0] / clip_w[0] + l[1] / clip_w[1] + l[2] / clip_w[2];
        if (1.0f / inv_w >= nearest_w) continue;
        nearest_w = 1.0f / inv_w;
        glm::vec3 normal(0.0f);
        for (int i = 0; i < 3; ++i) normal += l[i] / clip_w[i] / inv_w * p.face.n[i];
        hit.covered = true;
        hit.color = p.face.color * std::max(glm::dot(glm::normalize(normal), kLight), 0.0f);
        // Distance to edge i's line: l_i times the height over that edge.
        hit.edge_distance = 1e30f;
        for (int i = 0; i < 3; ++i)
            hit.edge_distance = std::min(
                hit.edge_distance, l[i] * area2 / glm::length(w[(i + 2) % 3] - w[(i + 1) % 3]));
    }
    return hit;
}

}  // namespace geometry_test
