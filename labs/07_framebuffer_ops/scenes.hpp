// Lab 7's geometry, colours and cameras, with the numbers of
// labs/07_framebuffer_ops/README.md.
#pragma once

#include <glad/gl.h>

#include <glm/glm.hpp>
#include <vector>

namespace framebuffer_ops {

// A position and texture coordinates; read by shaders/07_framebuffer_ops/quad.vert.
struct Vertex {
    glm::vec3 position;
    glm::vec2 uv;
};

// The unit square [0, 1]^2 at z = 0 with uv = (x, y), as the triangles
// (0, 1, 2), (0, 2, 3): every rectangle of the lab is this square moved by
// rect().
std::vector<Vertex> square_vertices();
std::vector<GLuint> square_indices();
// The matrix that takes the unit square onto [x0, x1] x [y0, y1] at depth z.
glm::mat4 rect(float x0, float y0, float x1, float y1, float z);

// scene=blend (NDC): the opaque background, then the translucent quads A and
// B, each (r, g, b, alpha).
const glm::vec4 kBlendBackground{0.3f, 0.3f, 0.3f, 1.0f};
const glm::vec4 kQuadA{0.8f, 0.4f, 0.0f, 0.5f};   // [-0.7, 0.3]^2
const glm::vec4 kQuadB{0.0f, 0.4f, 0.8f, 0.75f};  // [-0.3, 0.7]^2
glm::mat4 quad_a();
glm::mat4 quad_b();

// scene=sorting: over the background of scene=blend (drawn with the depth
// test off), three translucent squares facing the camera, in the order the
// scene lists them: near (red, z = 0.5), middle (green, z = 0), far (blue,
// z = -0.5), each with alpha 0.5; seen from (0, 0, 3), 45 degrees.
struct Pane {
    glm::vec3 centre;
    float half_size;
    glm::vec4 color;
};
std::vector<Pane> panes();
const glm::vec3 kSortingEye{0.0f, 0.0f, 3.0f};
glm::mat4 sorting_view_projection();
glm::mat4 pane_model(const Pane& pane);

// scene=discard (NDC): the fence, 4 x 4 cells over [-0.8, 0.8]^2 at z = -0.5,
// drawn first, then the opaque back quad [-0.6, 0.6]^2 at z = 0.5.
const glm::vec3 kFenceColor{0.2f, 0.5f, 0.9f};
const glm::vec4 kBackColor{0.9f, 0.8f, 0.1f, 1.0f};
constexpr float kFenceCells = 4.0f;
glm::mat4 fence();
glm::mat4 back_quad();

// scene=stencil (NDC): the mask, a disc of radius 0.5 (a fan of 64
// triangles); three bands drawn inside it; the outline, a disc of radius 0.6
// drawn where the stencil is not set.
std::vector<Vertex> disc_vertices();  // the fan around the unit disc: centre, then 65 rim points
constexpr float kMaskRadius = 0.5f, kOutlineRadius = 0.6f;
struct Band {
    float y0, y1;
    glm::vec4 color;
};
std::vector<Band> bands();
const glm::vec4 kOutlineColor{1.0f, 1.0f, 1.0f, 1.0f};
glm::mat4 disc(float radius);

// scene=faces: the open box [-0.5, 0.5]^3 without its top, 5 faces of 2
// triangles each (gl_PrimitiveID 0-9): front (+z), right (+x), back (-z),
// left (-x), bottom (-y), each counter-clockwise seen from outside; seen from
// (1, 2.2, 1.6) looking at (0, -0.3, 0), 45 degrees.
std::vector<Vertex> box_vertices();
std::vector<GLuint> box_indices();
const glm::vec3 kBoxEye{1.0f, 2.2f, 1.6f};
glm::mat4 box_view_projection();

// scene=scissor: the rectangles, in pixels of a 512 x 512 viewport (x, y,
// width, height; y from the bottom): the clear's and the draw's.
const glm::ivec4 kClearRect{64, 64, 256, 192};
const glm::ivec4 kDrawRect{192, 160, 256, 256};
const glm::vec4 kScissorClear{0.2f, 0.6f, 0.3f, 1.0f};
const glm::vec4 kScissorDraw{0.8f, 0.2f, 0.2f, 1.0f};

}  // namespace framebuffer_ops
