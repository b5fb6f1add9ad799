// Lab 0's parameters and the culling scene's camera; the numbers are those of
// labs/00_pipeline/README.md.
#include "scenes.hpp"

#include <glm/gtc/matrix_transform.hpp>

namespace pipeline {

namespace {

// scene=culling's camera: on the +z axis looking at the cube's centre.
const glm::vec3 kEye{0.0f, 0.0f, 3.0f};
constexpr float kFovYDegrees = 45.0f, kNear = 0.1f, kFar = 100.0f;

}  // namespace

std::vector<fw::Param> params() {
    return {
        fw::Param::choice(kScene, kScenes, Scene::Order)
            .help("order: two quads and the depth test; indexed: an indexed face set; "
                  "primitives: 6 vertices in each primitive mode; culling: a cube")
            .key('S'),
        fw::Param::boolean(kDepthTest, true)
            .help("keep the nearest fragment (GL_LESS) instead of the last drawn (order, "
                  "culling)")
            .key('D'),
        fw::Param::choice(kFirst, kFirsts, First::Red)
            .help("which quad is drawn first (order)")
            .key('F'),
        fw::Param::choice(kStorage, kStorages, Storage::Indexed)
            .help("6 vertices + 12 indices, or the 12 vertices they expand to (indexed)")
            .key('I'),
        fw::Param::choice(kPrimitive, kPrimitives, Primitive::Triangles)
            .help("how the 6 vertices are assembled (primitives)")
            .key('P'),
        fw::Param::choice(kCull, kCulls, Cull::Back)
            .help("which faces are culled; front faces are counter-clockwise (culling)")
            .key('C'),
        fw::Param::number(kYaw, 30)
            .range(-180, 180)
            .step(15)
            .unit("deg")
            .help("cube rotation about the y axis, applied first (culling)")
            .key('Y'),
        fw::Param::number(kPitch, 20)
            .range(-180, 180)
            .step(15)
            .unit("deg")
            .help("cube rotation about the x axis, applied after yaw (culling)")
            .key('X'),
    };
}

glm::mat4 cube_mvp(float yaw, float pitch, float aspect) {
    const glm::mat4 projection = glm::perspective(glm::radians(kFovYDegrees), aspect, kNear, kFar);
    const glm::mat4 view = glm::lookAt(kEye, glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
    glm::mat4 model = glm::rotate(glm::mat4(1.0f), glm::radians(pitch), {1, 0, 0});
    model = glm::rotate(model, glm::radians(yaw), {0, 1, 0});
    return projection * view * model;
}

float wrap_degrees(float a) {
    while (a > 180.0f) a -= 360.0f;
    while (a < -180.0f) a += 360.0f;
    return a;
}

}  // namespace pipeline
