// Lab 5's scenes, their control points and cameras (labs/05_tessellation/README.md,
// The scenes), and the parameters that choose and shape them.
#pragma once

#include <glad/gl.h>

#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "framework/params.hpp"

namespace tessellation {

// 12 bytes: one vec3, a control point. Read by shaders/05_tessellation/patch.vert.
struct Vertex {
    glm::vec3 position;
};

// The parameters' choices. Each enum is what the lab switches on; the names
// are what --set, checkpoints.json and the window's panel use.
// The sheet's scenes: one patch each, except the icosahedron's 20 and the
// ground's 16.
enum class Scene { Triangle, Sphere, Flag, ParamSphere, Lod };
constexpr fw::Choice<Scene> kScenes[] = {{Scene::Triangle, "triangle"},
                                         {Scene::Sphere, "sphere"},
                                         {Scene::Flag, "flag"},
                                         {Scene::ParamSphere, "param_sphere"},
                                         {Scene::Lod, "lod"}};
// Each spacing names its shader object spacing_<name>.tese.
enum class Spacing { Equal, FractionalEven, FractionalOdd };
constexpr fw::Choice<Spacing> kSpacings[] = {{Spacing::Equal, "equal"},
                                             {Spacing::FractionalEven, "fractional_even"},
                                             {Spacing::FractionalOdd, "fractional_odd"}};
enum class Show { Shaded, Normals };
constexpr fw::Choice<Show> kShows[] = {{Show::Shaded, "shaded"}, {Show::Normals, "normals"}};
// Scene lod: each outer level from its edge's midpoint, or every level from
// the patch's centre (the cracks).
enum class Lod { Edges, Centre };
constexpr fw::Choice<Lod> kLods[] = {{Lod::Edges, "edges"}, {Lod::Centre, "centre"}};

// The lab's parameters (labs/05_tessellation/README.md, Parameters): each
// named once, by its handle, for params() and draw().
constexpr fw::ParamId<Scene> kScene{"scene"};
constexpr fw::ParamId<float> kInner{"inner"};
constexpr fw::ParamId<float> kOuter{"outer"};
constexpr fw::ParamId<Spacing> kSpacing{"spacing"};
constexpr fw::ParamId<bool> kWireframe{"wireframe"};
constexpr fw::ParamId<Show> kShow{"show"};
constexpr fw::ParamId<float> kFlagD{"D"};
constexpr fw::ParamId<float> kFlagK{"K"};
constexpr fw::ParamId<float> kPhase{"phase"};
constexpr fw::ParamId<float> kDetail{"detail"};
constexpr fw::ParamId<Lod> kLod{"lod"};
using fw::kAnimate;  // the framework's: `lab serve` draws every frame while it is on
std::vector<fw::Param> params();

// The scene's control shader objects and its evaluation shader, files of
// shaders/05_tessellation/.
std::vector<std::string> control_shaders(Scene scene);
const char* evaluation_shader(Scene scene);
// Quad patches (4 control points) or triangles (3).
bool quad_patches(Scene scene);

// Scene triangle: one patch, NDC corners, counter-clockwise.
std::vector<Vertex> triangle_patch();
// Scenes flag and param_sphere: one patch, the unit square's corners in
// (u, v), counter-clockwise.
std::vector<Vertex> quad_patch();
// Scene sphere: the icosahedron's 12 corners and its 20 faces as 60 indices,
// one triangle patch per face.
struct Patches {
    std::vector<Vertex> vertices;
    std::vector<GLuint> indices;
};
Patches icosahedron_patches();
// Scene lod: the ground's 4 x 4 patches of 2 x 2, x and z in [-4, 4] at
// y = 0: the 25 corners of the grid, and 64 indices, 4 per patch in the order
// (u, v) = (0, 0), (1, 0), (1, 1), (0, 1), u along +x and v along -z.
Patches ground_patches();

// The flag, W x H = 2 x 1.2 in the plane z = 0 from the origin.
constexpr float kFlagW = 2.0f, kFlagH = 1.2f;
// The wave's phase in radians: `degrees`, and with `animate` in the window
// 180 degrees more each second of `time`.
float flag_phase(float degrees, bool animate, double time);

// The scene's camera, P V: the identity for the triangle (NDC corners),
// otherwise the perspective of the lit scenes times the scene's lookAt.
glm::mat4 view_projection(Scene scene, float aspect);
// Scene lod: the eye, from which lod.tesc measures each level's distance.
glm::vec3 ground_eye();

}  // namespace tessellation
