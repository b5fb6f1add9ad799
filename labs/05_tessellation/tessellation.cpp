// Lab 5 `tessellation`: tessellation control and evaluation.
//
// Teaches: patches instead of triangles; the control shader that sets a
// patch's inner and outer tessellation levels; the fixed-function
// tessellator that subdivides a triangle or a quad domain into rings of
// triangles (equal, fractional_even and fractional_odd spacing); the
// evaluation shader that places each generated vertex from gl_TessCoord:
// a flat triangle, an icosahedron pushed onto the sphere, a waving flag with
// normals from partial derivatives, and a parametric sphere.
// Lecture: tessellation shaders (control, primitive generator, evaluation),
// the icosahedron's normalize(p0 + p1 + p2), the waving flag r(u, v), the
// parametric sphere, normals from the cross product of partial derivatives.
// GL: GL_PATCHES, glPatchParameteri(GL_PATCH_VERTICES), GL_TESS_CONTROL_SHADER
// (layout(vertices = N) out, gl_TessLevelInner/Outer), GL_TESS_EVALUATION_SHADER
// (layout(triangles / quads, *_spacing, ccw) in, gl_TessCoord), a stage linked
// from several shader objects, GL_PRIMITIVES_GENERATED.
// Student parts (marked TODO), all GLSL: the
// levels in shaders/05_tessellation/levels.tesc, the evaluation shaders
// sphere.tese, flag.tese and param_sphere.tese.
#include <algorithm>
#include <array>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <iterator>
#include <string>
#include <vector>

#include "framework/gl.hpp"
#include "framework/lab.hpp"
#include "framework/meshes.hpp"

namespace tessellation {

namespace {

// The vertex attribute location, the same number as `layout(location = 0)`
// in shaders/05_tessellation/patch.vert: change both or neither.
constexpr GLuint kPositionLocation = 0;  // in vec3 a_position

// How shade.frag colours a fragment: its constants kFill, kLambert, kNormal.
enum Shading { kFill = 0, kLambert = 1, kNormal = 2 };

constexpr double kMinLevel = 1.0, kMaxLevel = 64.0;
// The values of `spacing`; each names its shader object spacing_<name>.tese.
constexpr const char* kSpacings[] = {"equal", "fractional_even", "fractional_odd"};
constexpr std::size_t kSpacingCount = sizeof(kSpacings) / sizeof(kSpacings[0]);

// The sheet's scenes: one patch each, except the icosahedron's 20.
struct Scene {
    const char* name;
    const char* evaluation;  // the scene's .tese
    bool quads;              // quad patches (4 control points) or triangles (3)
};
constexpr Scene kScenes[] = {
    {"triangle", "flat.tese", false},
    {"sphere", "sphere.tese", false},
    {"flag", "flag.tese", true},
    {"param_sphere", "param_sphere.tese", true},
};
constexpr std::size_t kSceneCount = sizeof(kScenes) / sizeof(kScenes[0]);

// Scene triangle: NDC corners, counter-clockwise, identity matrices.
const std::vector<glm::vec3> kTriangle = {
    {-0.9f, -0.8f, 0.0f}, {0.9f, -0.8f, 0.0f}, {0.0f, 0.9f, 0.0f}};
// A quad patch: the unit square's corners in (u, v), counter-clockwise.
const std::vector<glm::vec3> kQuad = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
const glm::vec3 kFillColor{0.2f, 0.3f, 0.8f};
const glm::vec3 kWhite{1.0f};

// Sphere, param_sphere (as lab 4) and flag: lit with Lambert alone.
const glm::vec3 kGrey{0.8f};
const glm::vec3 kLightDir = glm::normalize(glm::vec3(1.0f, 1.0f, 1.0f));
constexpr float kFovYDegrees = 45.0f, kNear = 0.1f, kFar = 100.0f;
const glm::vec3 kSphereEye{0.0f, 0.0f, 4.0f};
// The flag, W x H = 2 x 1.2 in the plane z = 0 from the origin, seen from
// the front, up and to the left, looking at its centre.
constexpr float kFlagW = 2.0f, kFlagH = 1.2f;
const glm::vec3 kFlagEye{-0.2f, 1.3f, 2.6f};
const glm::vec3 kFlagCentre{1.0f, 0.6f, 0.0f};
// animate: the phase grows by 180 degrees a second in the window.
constexpr float kWaveSpeed = glm::pi<float>();  // radians per second

// Uniforms read only by the student parts, which the compiler removes until
// the part that reads them is written; fw::Program::set() refuses those.
template <class T>
void set_student_uniform(const fw::Program& program, const char* name, const T& value) {
    if (program.has_uniform(name)) program.set(name, value);
}

fw::Param level(const char* name, int key, const char* what) {
    return fw::Param::number(name, 4)
        .range(kMinLevel, kMaxLevel)
        .step(1)
        .help(std::string(what) +
              " tessellation level of every patch; fractions matter with "
              "the fractional spacings")
        .key(key);
}

}  // namespace

class TessellationLab : public fw::Lab {
public:
    static fw::LabInfo info() {
        std::vector<std::string> scenes, spacings(std::begin(kSpacings), std::end(kSpacings));
        for (const Scene& s : kScenes) scenes.push_back(s.name);
        fw::LabInfo i;
        i.number = 5;
        i.id = "tessellation";
        i.dir = "05_tessellation";
        i.title = "Tessellation control and evaluation";
        i.params = {
            fw::Param::choice("scene", scenes, "triangle")
                .help("triangle: one flat patch; sphere: the icosahedron's 20 faces pushed onto "
                      "the sphere; flag: the waving flag; param_sphere: the parametric sphere")
                .key('S'),
            level("inner", 'I', "inner"),
            level("outer", 'O', "outer"),
            fw::Param::choice("spacing", spacings, "equal")
                .help("how a level becomes segments: equal rounds up; fractional_even and "
                      "fractional_odd round up to an even or odd count, two segments shorter")
                .key('P'),
            fw::Param::boolean("wireframe", true)
                .help("draw the tessellated triangles' edges in white")
                .key('W'),
            fw::Param::choice("show", {"shaded", "normals"}, "shaded")
                .help("shaded: fill colour or Lambert; normals: the unit normal n as the colour "
                      "0.5 n + 0.5")
                .key('N'),
            fw::Param::number("D", 0.15)
                .range(0, 0.5)
                .step(0.05)
                .help("depth of the flag's wave: r.z = sin(K pi u + phase) D (flag)")
                .key('D'),
            fw::Param::number("K", 2)
                .range(0, 8)
                .step(0.5)
                .help("half-waves across the flag (flag)")
                .key('K'),
            fw::Param::number("phase", 0)
                .range(0, 360)
                .step(15)
                .unit("deg")
                .help("the wave's phase (flag)")
                .key('H'),
            fw::Param::boolean("animate", false)
                .help("in the window, the phase grows by 180 degrees a second (flag)")
                .key('A'),
        };
        i.controls = {"scroll: inner and outer levels up / down together"};
        return i;
    }

    void init(fw::ProgramLibrary& programs) override {
        for (std::size_t s = 0; s < kSceneCount; ++s)
            for (std::size_t k = 0; k < kSpacingCount; ++k) {
                const std::string dir = "05_tessellation/";
                programs_[s][k] = &programs.load({
                    dir + "patch.vert",
                    dir + "levels.tesc",
                    dir + (kScenes[s].quads ? "quad.tesc" : "triangle.tesc"),
                    dir + kScenes[s].evaluation,
                    dir + "spacing_" + std::string(kSpacings[k]) + ".tese",
                    dir + "wireframe.geom",
                    dir + "shade.frag",
                });
            }

        const fw::VertexLayout layout =
            fw::VertexLayout::of<glm::vec3>().add({kPositionLocation, 3, GL_FLOAT, 0});
        triangle_vbo_ = fw::Buffer::from(kTriangle, GL_ARRAY_BUFFER, "triangle patch");
        triangle_ = fw::VertexArray({&triangle_vbo_, layout, nullptr, GL_UNSIGNED_INT, "triangle"});
        quad_vbo_ = fw::Buffer::from(kQuad, GL_ARRAY_BUFFER, "quad patch");
        quad_ = fw::VertexArray({&quad_vbo_, layout, nullptr, GL_UNSIGNED_INT, "quad"});
        const fw::MeshData ico = fw::icosahedron();
        ico_vbo_ = fw::Buffer::from(ico.positions, GL_ARRAY_BUFFER, "icosahedron corners");
        ico_ibo_ = fw::Buffer::from(ico.indices, GL_ELEMENT_ARRAY_BUFFER, "icosahedron faces");
        ico_ = fw::VertexArray({&ico_vbo_, layout, &ico_ibo_, GL_UNSIGNED_INT, "icosahedron"});
    }

    void draw(const fw::ParamValues& p, const fw::Frame& frame) override {
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glDisable(GL_CULL_FACE);

        const std::size_t scene = static_cast<std::size_t>(p.choice_index("scene"));
        const std::string& name = kScenes[scene].name;
        const fw::Program& program =
            *programs_[scene][static_cast<std::size_t>(p.choice_index("spacing"))];
        set_student_uniform(program, "u_inner", p.number("inner"));
        set_student_uniform(program, "u_outer", p.number("outer"));
        program.set("u_viewport", glm::vec2(frame.width, frame.height));
        program.set("u_wireframe", p.flag("wireframe"));
        program.set("u_edge_color", kWhite);
        program.set("u_light_dir", kLightDir);

        const float aspect = static_cast<float>(frame.width) / static_cast<float>(frame.height);
        const glm::mat4 projection =
            glm::perspective(glm::radians(kFovYDegrees), aspect, kNear, kFar);
        const glm::vec3 up{0.0f, 1.0f, 0.0f};
        glm::mat4 view_projection(1.0f);
        if (name == "flag") {
            view_projection = projection * glm::lookAt(kFlagEye, kFlagCentre, up);
            // Offscreen, frame.time is 0: the same parameters draw the same image.
            const float phase =
                glm::radians(p.number("phase")) +
                (p.flag("animate") ? static_cast<float>(frame.time) * kWaveSpeed : 0.0f);
            set_student_uniform(program, "u_W", kFlagW);
            set_student_uniform(program, "u_H", kFlagH);
            set_student_uniform(program, "u_D", p.number("D"));
            set_student_uniform(program, "u_K", p.number("K"));
            set_student_uniform(program, "u_phase", phase);
        } else if (name != "triangle") {
            view_projection = projection * glm::lookAt(kSphereEye, glm::vec3(0.0f), up);
        }
        program.set("u_view_projection", view_projection);
        const bool normals = p.choice("show") == "normals";
        const Shading shading = normals ? kNormal : name == "triangle" ? kFill : kLambert;
        program.set("u_shading", static_cast<int>(shading));
        program.set("u_color", name == "triangle" ? kFillColor : kGrey);

        // A patch is a list of control points with no shape of its own:
        // GL_PATCH_VERTICES says how many make one.
        program.use();
        if (name == "sphere") {
            glPatchParameteri(GL_PATCH_VERTICES, 3);
            ico_.draw_indexed(GL_PATCHES, static_cast<GLsizei>(ico_.index_count()));
        } else if (kScenes[scene].quads) {
            glPatchParameteri(GL_PATCH_VERTICES, 4);
            quad_.draw(GL_PATCHES, static_cast<GLsizei>(quad_.vertex_count()));
        } else {
            glPatchParameteri(GL_PATCH_VERTICES, 3);
            triangle_.draw(GL_PATCHES, static_cast<GLsizei>(triangle_.vertex_count()));
        }
    }

    // The patches drawn and their domain: {"patches": 20, "domain": "triangles"}.
    nlohmann::json stats(const fw::ParamValues& p) const override {
        const Scene& scene = kScenes[p.choice_index("scene")];
        const std::size_t patches =
            std::string(scene.name) == "sphere" ? ico_.index_count() / 3 : 1;
        return {{"patches", patches}, {"domain", scene.quads ? "quads" : "triangles"}};
    }

    // Scroll: both levels up or down by one a step, within [1, 64].
    bool on_scroll(fw::ParamValues& p, double steps) override {
        for (const char* name : {"inner", "outer"})
            p.number_ref(name) = std::clamp(p.number(name) + steps, kMinLevel, kMaxLevel);
        return true;
    }

private:
    // programs_[scene][spacing]: the spacing is fixed when a program is linked.
    std::array<std::array<fw::Program*, kSpacingCount>, kSceneCount> programs_{};
    fw::Buffer triangle_vbo_, quad_vbo_, ico_vbo_, ico_ibo_;
    fw::VertexArray triangle_, quad_, ico_;
};

FW_LAB(TessellationLab)

}  // namespace tessellation
