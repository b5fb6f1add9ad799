// Lab 5's scenes and parameters; the numbers are those of
// labs/05_tessellation/README.md.
#include "scenes.hpp"

#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <string>

#include "framework/meshes.hpp"

namespace tessellation {

namespace {

// Sphere, param_sphere (as lab 4) and flag: perspective(45 deg, W/H, 0.1, 100).
constexpr float kFovYDegrees = 45.0f, kNear = 0.1f, kFar = 100.0f;
const glm::vec3 kUp{0.0f, 1.0f, 0.0f};
const glm::vec3 kSphereEye{0.0f, 0.0f, 4.0f};
// The flag seen from the front, up and to the left, looking at its centre.
const glm::vec3 kFlagEye{-0.2f, 1.3f, 2.6f};
const glm::vec3 kFlagCentre{1.0f, 0.6f, 0.0f};
// The ground seen from above its near edge, looking at its centre.
const glm::vec3 kGroundEye{0.0f, 5.0f, 7.0f};
// The ground: kGroundCells x kGroundCells patches of kGroundCell x kGroundCell.
constexpr int kGroundCells = 4;
constexpr float kGroundCell = 2.0f;
// animate: the phase grows by 180 degrees a second in the window.
constexpr float kWaveSpeed = glm::pi<float>();  // radians per second

constexpr double kMinLevel = 1.0, kMaxLevel = 64.0;

fw::Param level(fw::ParamId<float> id, int key) {
    return fw::Param::number(id, 4)
        .range(kMinLevel, kMaxLevel)
        .step(1)
        .help(std::string(id.name) +
              " tessellation level of every patch (lod computes its own); fractions "
              "matter with the fractional spacings")
        .key(key);
}

}  // namespace

std::vector<fw::Param> params() {
    return {
        fw::Param::choice(kScene, kScenes, Scene::Triangle)
            .help("triangle: one flat patch; sphere: the icosahedron's 20 faces pushed onto "
                  "the sphere; flag: the waving flag; param_sphere: the parametric sphere; lod: "
                  "16 ground patches, each cut by its distance to the eye")
            .key('S'),
        level(kInner, 'I'),
        level(kOuter, 'O'),
        fw::Param::choice(kSpacing, kSpacings, Spacing::Equal)
            .help("how a level becomes segments: equal rounds up; fractional_even and "
                  "fractional_odd round up to an even or odd count, two segments shorter")
            .key('P'),
        fw::Param::boolean(kWireframe, true)
            .help("draw the tessellated triangles' edges in white")
            .key('W'),
        fw::Param::choice(kShow, kShows, Show::Shaded)
            .help("shaded: fill colour or Lambert; normals: the unit normal n as the colour "
                  "0.5 n + 0.5")
            .key('N'),
        fw::Param::number(kFlagD, 0.15)
            .range(0, 0.5)
            .step(0.05)
            .help("depth of the flag's wave: r.z = sin(K pi u + phase) D (flag)")
            .key('D'),
        fw::Param::number(kFlagK, 2)
            .range(0, 8)
            .step(0.5)
            .help("half-waves across the flag (flag)")
            .key('K'),
        fw::Param::number(kPhase, 0)
            .range(0, 360)
            .step(15)
            .unit("deg")
            .help("the wave's phase (flag)")
            .key('H'),
        fw::Param::boolean(kAnimate, false)
            .help("in the window, the phase grows by 180 degrees a second (flag)")
            .key('A'),
        fw::Param::number(kDetail, 45)
            .range(1, 100)
            .step(1)
            .help("k: a point at distance d from the eye gets the level clamp(round(k / d), 1, "
                  "64) (lod)")
            .key('L'),
        fw::Param::choice(kLod, kLods, Lod::Edges)
            .help("edges: each outer level from its edge's midpoint; centre: every level from "
                  "the patch's centre, which opens cracks between patches (lod)")
            .key('E'),
    };
}

std::vector<std::string> control_shaders(Scene scene) {
    switch (scene) {
        case Scene::Triangle:
        case Scene::Sphere:
            return {"levels.tesc", "triangle.tesc"};
        case Scene::Flag:
        case Scene::ParamSphere:
            return {"levels.tesc", "quad.tesc"};
        case Scene::Lod:
            return {"lod.tesc"};
    }
    return {};
}

const char* evaluation_shader(Scene scene) {
    switch (scene) {
        case Scene::Triangle:
            return "flat.tese";
        case Scene::Sphere:
            return "sphere.tese";
        case Scene::Flag:
            return "flag.tese";
        case Scene::ParamSphere:
            return "param_sphere.tese";
        case Scene::Lod:
            return "lod.tese";
    }
    return "";
}

bool quad_patches(Scene scene) {
    return scene == Scene::Flag || scene == Scene::ParamSphere || scene == Scene::Lod;
}

std::vector<Vertex> triangle_patch() {
    return {{{-0.9f, -0.8f, 0.0f}}, {{0.9f, -0.8f, 0.0f}}, {{0.0f, 0.9f, 0.0f}}};
}

std::vector<Vertex> quad_patch() { return {{{0, 0, 0}}, {{1, 0, 0}}, {{1, 1, 0}}, {{0, 1, 0}}}; }

Patches icosahedron_patches() {
    const fw::MeshData ico = fw::icosahedron();
    Patches patches;
    for (const glm::vec3& corner : ico.positions) patches.vertices.push_back({corner});
    patches.indices = ico.indices;
    return patches;
}

Patches ground_patches() {
    Patches patches;
    constexpr int corners = kGroundCells + 1;
    const float half = kGroundCells * kGroundCell / 2.0f;
    // Corner (i, j) at x = -4 + 2 i, z = -4 + 2 j.
    for (int j = 0; j < corners; ++j)
        for (int i = 0; i < corners; ++i)
            patches.vertices.push_back({{-half + i * kGroundCell, 0.0f, -half + j * kGroundCell}});
    auto corner = [](int i, int j) { return static_cast<GLuint>(j * corners + i); };
    // The patch over [x_i, x_i+1] x [z_j, z_j+1]: u along +x from its near
    // edge (z_j+1) to v = 1 at its far edge (z_j), counter-clockwise seen from above.
    for (int j = 0; j < kGroundCells; ++j)
        for (int i = 0; i < kGroundCells; ++i)
            for (const GLuint index :
                 {corner(i, j + 1), corner(i + 1, j + 1), corner(i + 1, j), corner(i, j)})
                patches.indices.push_back(index);
    return patches;
}

float flag_phase(float degrees, bool animate, double time) {
    // Offscreen, time is 0: the same parameters draw the same image.
    return glm::radians(degrees) + (animate ? static_cast<float>(time) * kWaveSpeed : 0.0f);
}

glm::mat4 view_projection(Scene scene, float aspect) {
    const glm::mat4 projection = glm::perspective(glm::radians(kFovYDegrees), aspect, kNear, kFar);
    switch (scene) {
        case Scene::Triangle:
            return glm::mat4(1.0f);
        case Scene::Flag:
            return projection * glm::lookAt(kFlagEye, kFlagCentre, kUp);
        case Scene::Sphere:
        case Scene::ParamSphere:
            return projection * glm::lookAt(kSphereEye, glm::vec3(0.0f), kUp);
        case Scene::Lod:
            return projection * glm::lookAt(kGroundEye, glm::vec3(0.0f), kUp);
    }
    return glm::mat4(1.0f);
}

glm::vec3 ground_eye() { return kGroundEye; }

}  // namespace tessellation
