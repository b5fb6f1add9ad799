// Lab 5 `tessellation`: tessellation control and evaluation.
//
// Teaches: patches instead of triangles; the control shader that sets a
// patch's inner and outer tessellation levels; the fixed-function
// tessellator that subdivides a triangle or a quad domain into rings of
// triangles (equal, fractional_even and fractional_odd spacing); the
// evaluation shader that places each generated vertex from gl_TessCoord:
// a flat triangle, an icosahedron pushed onto the sphere, a waving flag with
// normals from partial derivatives, and a parametric sphere; level of detail,
// levels from the distance to the eye, and the cracks between patches that
// cut a shared edge differently.
// Lecture: tessellation shaders (control, primitive generator, evaluation),
// the icosahedron's normalize(p0 + p1 + p2), the waving flag r(u, v), the
// parametric sphere, normals from the cross product of partial derivatives,
// dynamic subdivision and level of detail.
// GL: glEnable(GL_DEPTH_TEST), glDepthFunc, glDisable(GL_CULL_FACE),
// glBindVertexArray, glPatchParameteri(GL_PATCH_VERTICES, 3 or 4),
// glDrawArrays(GL_PATCHES) and glDrawElements(GL_PATCHES), GL_TESS_CONTROL_SHADER
// (layout(vertices = N) out, gl_TessLevelInner/Outer), GL_TESS_EVALUATION_SHADER
// (layout(triangles / quads, *_spacing, ccw) in, gl_TessCoord), a stage linked
// from several shader objects (the framework's fw::ProgramLibrary links them),
// GL_PRIMITIVES_GENERATED (the framework's query around each frame).
// Student parts (marked TODO), all GLSL: the
// levels in shaders/05_tessellation/levels.tesc, the evaluation shaders
// sphere.tese, flag.tese and param_sphere.tese, and level_at() and
// set_edge_levels() in lod.tesc.
#include <array>
#include <string>
#include <vector>

#include "framework/gl.hpp"
#include "framework/lab.hpp"
#include "scenes.hpp"
// A_POSITION (attribute location, shared with patch.vert) and SHADING_*
// (values of u_shading, shared with shade.frag).
#include "shared.glsl"

namespace tessellation {

namespace {

// The shaders' uniforms.
constexpr const char* kInnerUniform = "u_inner";                     // levels.tesc
constexpr const char* kOuterUniform = "u_outer";                     // levels.tesc
constexpr const char* kViewProjectionUniform = "u_view_projection";  // the .tese
constexpr const char* kFlagWUniform = "u_W";                         // flag.tese
constexpr const char* kFlagHUniform = "u_H";                         // flag.tese
constexpr const char* kFlagDUniform = "u_D";                         // flag.tese
constexpr const char* kFlagKUniform = "u_K";                         // flag.tese
constexpr const char* kPhaseUniform = "u_phase";                     // flag.tese
constexpr const char* kEyeUniform = "u_eye";                         // lod.tesc
constexpr const char* kDetailUniform = "u_detail";                   // lod.tesc
constexpr const char* kFromCentreUniform = "u_from_centre";          // lod.tesc
constexpr const char* kViewportUniform = "u_viewport";               // wireframe.geom
constexpr const char* kShadingUniform = "u_shading";                 // shade.frag
constexpr const char* kColorUniform = "u_color";                     // shade.frag
constexpr const char* kLightDirUniform = "u_light_dir";              // shade.frag
constexpr const char* kWireframeUniform = "u_wireframe";             // shade.frag
constexpr const char* kEdgeColorUniform = "u_edge_color";            // shade.frag

// How shade.frag colours a fragment: each value is the one sent to u_shading.
enum class Shading { Fill = SHADING_FILL, Lambert = SHADING_LAMBERT, Normal = SHADING_NORMAL };

// Scene triangle: unlit, in its fill colour; edges in white.
const glm::vec3 kFillColor{0.2f, 0.3f, 0.8f};
const glm::vec3 kWhite{1.0f};
// Sphere, param_sphere (as lab 4) and flag: lit with Lambert alone.
const glm::vec3 kGrey{0.8f};
const glm::vec3 kLightDir = glm::normalize(glm::vec3(1.0f, 1.0f, 1.0f));

// Patches drawn through an index buffer: the corners, the indices and the
// vertex array that records both, each with its debug label.
struct IndexedPatches {
    struct Labels {
        const char *corners, *indices, *vertex_array;
    };
    IndexedPatches() = default;
    IndexedPatches(const Patches& patches, const fw::VertexLayout& layout, const Labels& labels)
        : corners(fw::Buffer::from(patches.vertices, GL_ARRAY_BUFFER, labels.corners)),
          indices(fw::Buffer::from(patches.indices, GL_ELEMENT_ARRAY_BUFFER, labels.indices)),
          vertex_array(fw::VertexArrayDesc{.vertices = &corners,
                                           .layout = layout,
                                           .indices = &indices,
                                           .index_type = GL_UNSIGNED_INT,
                                           .label = labels.vertex_array}) {}
    fw::Buffer corners, indices;
    fw::VertexArray vertex_array;
};

}  // namespace

class TessellationLab : public fw::Lab {
public:
    static fw::LabInfo info() {
        fw::LabInfo i;
        i.title = "Tessellation control and evaluation";
        i.params = params();
        i.controls = {"scroll: inner and outer levels up / down together"};
        return i;
    }

    void init(fw::ProgramLibrary& programs) override {
        // File names within shaders/05_tessellation/.
        for (const fw::Choice<Scene>& scene : kScenes)
            for (const fw::Choice<Spacing>& spacing : kSpacings) {
                std::vector<std::string> files = {"patch.vert"};
                for (const std::string& control : control_shaders(scene.value))
                    files.push_back(control);
                files.insert(files.end(), {evaluation_shader(scene.value),
                                           "spacing_" + std::string(spacing.name) + ".tese",
                                           "wireframe.geom", "shade.frag"});
                program(scene.value, spacing.value) = &programs.load(files);
            }

        // The vertex arrays record the layout (and the icosahedron's index
        // buffer); draw() binds one and draws its patches.
        const fw::VertexLayout layout =
            fw::VertexLayout::of<Vertex>().attr(A_POSITION, &Vertex::position);
        triangle_vbo_ = fw::Buffer::from(triangle_patch(), GL_ARRAY_BUFFER, "triangle patch");
        triangle_ = fw::VertexArray(
            fw::VertexArrayDesc{.vertices = &triangle_vbo_, .layout = layout, .label = "triangle"});
        quad_vbo_ = fw::Buffer::from(quad_patch(), GL_ARRAY_BUFFER, "quad patch");
        quad_ = fw::VertexArray(
            fw::VertexArrayDesc{.vertices = &quad_vbo_, .layout = layout, .label = "quad"});
        ico_ = IndexedPatches(icosahedron_patches(), layout,
                              {"icosahedron corners", "icosahedron faces", "icosahedron"});
        ground_ = IndexedPatches(ground_patches(), layout,
                                 {"ground corners", "ground patches", "ground"});
    }

    void draw(const fw::ParamValues& p, const fw::Frame& frame) override {
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glDisable(GL_CULL_FACE);

        const Scene scene = p[kScene];
        const fw::Program& program = *programs_[index(scene)][index(p[kSpacing])];
        set_uniforms(program, scene, p, frame);
        program.use();
        draw_patches(scene);
    }

    // The patches drawn and their domain: {"patches": 20, "domain": "triangles"}.
    nlohmann::json stats(const fw::ParamValues& p, const fw::Frame&) const override {
        const Scene scene = p[kScene];
        const std::size_t patches = scene == Scene::Sphere ? ico_.vertex_array.index_count() / 3
                                    : scene == Scene::Lod  ? ground_.vertex_array.index_count() / 4
                                                           : 1;
        return {{"patches", patches}, {"domain", quad_patches(scene) ? "quads" : "triangles"}};
    }

    // Scroll: both levels up or down by one a step, within their range [1, 64].
    bool on_scroll(fw::ParamValues& p, const fw::Frame&, double steps) override {
        for (const fw::ParamId<float> id : {kInner, kOuter}) p.set_clamped(id, p[id] + steps);
        return true;
    }

private:
    // The levels, the camera, the shading and the edges; the flag's wave.
    static void set_uniforms(const fw::Program& program, Scene scene, const fw::ParamValues& p,
                             const fw::Frame& frame) {
        // The uniforms that only the student parts read are set with
        // set_if_active(): the compiler removes them until that part is written.
        if (scene == Scene::Lod) {
            // lod.tesc computes the levels from the distance to the eye.
            program.set_if_active(kEyeUniform, ground_eye());
            program.set_if_active(kDetailUniform, p[kDetail]);
            program.set(kFromCentreUniform, p[kLod] == Lod::Centre);
        } else {
            program.set_if_active(kInnerUniform, p[kInner]);
            program.set_if_active(kOuterUniform, p[kOuter]);
        }
        program.set(kViewportUniform, glm::vec2(frame.width, frame.height));
        program.set(kWireframeUniform, p[kWireframe]);
        program.set(kEdgeColorUniform, kWhite);
        program.set(kLightDirUniform, kLightDir);

        const float aspect = static_cast<float>(frame.width) / static_cast<float>(frame.height);
        program.set(kViewProjectionUniform, view_projection(scene, aspect));
        if (scene == Scene::Flag) {
            program.set_if_active(kFlagWUniform, kFlagW);
            program.set_if_active(kFlagHUniform, kFlagH);
            program.set_if_active(kFlagDUniform, p[kFlagD]);
            program.set_if_active(kFlagKUniform, p[kFlagK]);
            program.set_if_active(kPhaseUniform, flag_phase(p[kPhase], p[kAnimate], frame.time));
        }

        const bool normals = p[kShow] == Show::Normals;
        const Shading shading = normals                    ? Shading::Normal
                                : scene == Scene::Triangle ? Shading::Fill
                                                           : Shading::Lambert;
        program.set(kShadingUniform, static_cast<int>(shading));
        program.set(kColorUniform, scene == Scene::Triangle ? kFillColor : kGrey);
    }

    // A patch is a list of control points with no shape of its own:
    // GL_PATCH_VERTICES says how many make one, and the draw call's
    // count how many points there are, so count / GL_PATCH_VERTICES patches.
    void draw_patches(Scene scene) const {
        switch (scene) {
            case Scene::Sphere:
                // 20 patches of 3 corners each, through the icosahedron's 60
                // indices (GL_UNSIGNED_INT, in the element buffer of ico_).
                glPatchParameteri(GL_PATCH_VERTICES, 3);
                glBindVertexArray(ico_.vertex_array.id());
                glDrawElements(GL_PATCHES, static_cast<GLsizei>(ico_.vertex_array.index_count()),
                               GL_UNSIGNED_INT, nullptr);
                break;
            case Scene::Flag:
            case Scene::ParamSphere:
                // One patch of the unit square's 4 corners.
                glPatchParameteri(GL_PATCH_VERTICES, 4);
                glBindVertexArray(quad_.id());
                glDrawArrays(GL_PATCHES, 0, static_cast<GLsizei>(quad_.vertex_count()));
                break;
            case Scene::Lod:
                // 16 patches of 4 corners each, through 64 indices into the
                // grid's 25 corners: neighbours share the corners of their edge.
                glPatchParameteri(GL_PATCH_VERTICES, 4);
                glBindVertexArray(ground_.vertex_array.id());
                glDrawElements(GL_PATCHES, static_cast<GLsizei>(ground_.vertex_array.index_count()),
                               GL_UNSIGNED_INT, nullptr);
                break;
            case Scene::Triangle:
                // One patch of the triangle's 3 corners.
                glPatchParameteri(GL_PATCH_VERTICES, 3);
                glBindVertexArray(triangle_.id());
                glDrawArrays(GL_PATCHES, 0, static_cast<GLsizei>(triangle_.vertex_count()));
                break;
        }
        glBindVertexArray(0);
    }

    static std::size_t index(Scene scene) { return static_cast<std::size_t>(scene); }
    static std::size_t index(Spacing spacing) { return static_cast<std::size_t>(spacing); }
    fw::Program*& program(Scene scene, Spacing spacing) {
        return programs_[index(scene)][index(spacing)];
    }

    // programs_[scene][spacing]: the spacing is fixed when a program is linked.
    std::array<std::array<fw::Program*, std::size(kSpacings)>, std::size(kScenes)> programs_{};
    fw::Buffer triangle_vbo_, quad_vbo_;
    fw::VertexArray triangle_, quad_;
    IndexedPatches ico_, ground_;
};

FW_LAB(TessellationLab)

}  // namespace tessellation
