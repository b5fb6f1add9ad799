// Lab 4's scene as the sheet defines it (labs/04_geometry/README.md),
// computed here without the lab's or the framework's code: the camera, the
// light, the sphere's silhouette, and a small ray caster that predicts every
// pixel of the icosahedron (subdiv 0), whose corners the sheet gives in
// closed form.
#pragma once

#include <cmath>
#include <glm/glm.hpp>
#include <optional>
#include <vector>

namespace geometry_test {

constexpr int kSize = 512;
const glm::vec3 kEye{0.0f, 0.0f, 4.0f};
const glm::vec3 kLight = glm::normalize(glm::vec3(1.0f, 1.0f, 1.0f));
const glm::vec3 kGrey{0.8f}, kTint{1.0f, 0.5f, 0.2f};
const glm::vec3 kBlack{0.0f}, kWhite{1.0f}, kYellow{1.0f, 1.0f, 0.0f};
// perspective(45 deg): y_ndc = f * y_eye / -z_eye with f = 1 / tan(22.5 deg).
const float kFocal = 1.0f / std::tan(glm::radians(22.5f));

// rotateY(spin) as a matrix of column vectors.
glm::mat3 rotate_y(float degrees);
// World point -> window position in pixels (512 x 512, origin bottom left).
glm::vec2 to_window(glm::vec3 world);
// The pixel whose square holds that window position.
glm::ivec2 pixel_of(glm::vec2 window);
// Radius in pixels of the silhouette of a sphere of radius r centred on the
// origin: f * r / sqrt(4^2 - r^2) in NDC, times 256.
float silhouette_radius(float r);
// The Lambert colour of a sphere of radius 1 centred at `centre` where the
// ray through pixel (x, y)'s centre first meets it; nullopt if it misses.
std::optional<glm::vec3> sphere_color(int x, int y, glm::vec3 centre, glm::vec3 color);

// One triangle of the scene, world space, counter-clockwise seen from outside.
struct Face {
    glm::vec3 p[3];
    glm::vec3 n[3];  // vertex normals
    glm::vec3 color;
};
// The icosahedron's 20 faces, found from its 12 corners alone: three corners
// that are pairwise one edge apart make a face, oriented to face outward.
std::vector<Face> icosahedron_faces(glm::mat3 model);
// Duplicate's copy: every face moved by `offset` (world space), in `color`.
std::vector<Face> moved(std::vector<Face> faces, glm::vec3 offset, glm::vec3 color);
// Explode: every face moved by `amount` along its own unit face normal.
std::vector<Face> exploded(std::vector<Face> faces, float amount);

// What the ray through pixel (x, y)'s centre sees: the nearest front face
// (back faces are culled), the Lambert colour there and, in window pixels, the
// distance from the pixel centre to that face's nearest edge line.
// `ambiguous` when the centre lies within `margin` pixels of a projected edge
// of any front face, where the rasterizer's rounding may decide either way.
struct Hit {
    bool covered = false;
    bool ambiguous = false;
    glm::vec3 color{0.0f};
    float edge_distance = 0.0f;
};
// A front face as the rasterizer sees it, projected once for every pixel:
// its corners in window pixels, their eye depths (the clip w), twice its
// window area, and its window bounding box (a pixel centre outside it, by
// more than the margin, can neither be covered by the face nor be ambiguous
// because of it).
struct Projected {
    Face face;
    glm::vec2 w[3];
    float clip_w[3];
    float area2;
    glm::vec2 lo, hi;
};
// The front faces of `faces` (back faces, culled, are left out).
std::vector<Projected> project(const std::vector<Face>& faces);
Hit cast(const std::vector<Projected>& faces, int x, int y, float margin);

}  // namespace geometry_test
