// Lab 6 `interpolation`: what the rasterizer interpolates.
//
// Teaches: barycentric interpolation of vertex values across a triangle;
// perspective-correct (smooth) versus screen-space (noperspective)
// interpolation; flat shading and the provoking vertex; Gouraud (per-vertex)
// versus Phong (per-pixel) shading of the Blinn-Phong model; toon shading.
// Lecture: rasterization and interpolation, shading models, NPR.
// GL: the GLSL interpolation qualifiers smooth, noperspective and flat,
// glProvokingVertex, glEnable/glDisable(GL_DEPTH_TEST), glDepthFunc,
// glDisable(GL_CULL_FACE), glBindVertexArray with glDrawArrays (the triangle)
// and glDrawElements (the plane and the sphere).
// Student parts (marked TODO), all GLSL: the
// qualifiers in shaders/06_interpolation/interpolate.frag; the lighting in
// shading.vert (Gouraud) and shading.frag (Phong, toon).
#include <glm/gtc/matrix_transform.hpp>
#include <string>
#include <vector>

#include "framework/gl.hpp"
#include "framework/lab.hpp"
#include "parameters.hpp"
#include "scenes.hpp"
// A_POSITION, A_VALUE, A_NORMAL: the attribute locations, shared with the
// shaders.
#include "shared.glsl"

namespace interpolation {

namespace {

// The shaders' uniforms.
constexpr const char* kMvpUniform = "u_mvp";                         // interpolate.vert
constexpr const char* kQualifierUniform = "u_qualifier";             // interpolate.frag
constexpr const char* kCheckerboardUniform = "u_checkerboard";       // interpolate.frag
constexpr const char* kChecksUniform = "u_checks";                   // interpolate.frag
constexpr const char* kViewProjectionUniform = "u_view_projection";  // shading.vert
constexpr const char* kShadingUniform = "u_shading";                 // shading.frag
// The light, the eye and the material: shading.vert and shading.frag.
constexpr const char* kLightUniform = "u_light";
constexpr const char* kEyeUniform = "u_eye";
constexpr const char* kKaUniform = "u_ka";
constexpr const char* kKdUniform = "u_kd";
constexpr const char* kKsUniform = "u_ks";
constexpr const char* kShineUniform = "u_shine";
constexpr const char* kLaUniform = "u_la";
constexpr const char* kLeUniform = "u_le";

// The lecture's material and light: ka La + (kd cos(theta) + ks cos(delta)^shine) Le.
const glm::vec3 kKa{0.1f}, kKd{0.8f, 0.3f, 0.2f}, kKs{0.5f}, kLa{1.0f}, kLe{1.0f};
constexpr float kShine = 32.0f;

}  // namespace

class InterpolationLab : public fw::Lab {
public:
    static fw::LabInfo info() {
        fw::LabInfo i;
        i.title = "What the rasterizer interpolates";
        i.params = {
            fw::Param::choice(kScene, kScenes, Scene::Triangle)
                .help("triangle: one colour per vertex; plane: a checkered floor in "
                      "perspective; shading: a lit icosphere")
                .key('S'),
            fw::Param::choice(kQualifier, kQualifiers, Qualifier::Smooth)
                .help("how the fragment shader's input is interpolated (triangle, plane)")
                .key('Q'),
            fw::Param::color(kColorA, "ff0000").help("colour of A (-0.8, -0.8) (triangle)"),
            fw::Param::color(kColorB, "ffffff").help("colour of B (0.8, -0.8) (triangle)"),
            fw::Param::color(kColorC, "ffffff")
                .help("colour of C (0, 0.8), the provoking vertex (triangle)"),
            fw::Param::integer(kChecks, 8)
                .range(1, 64)
                .help("checkerboard cells along u and along v (plane)")
                .key('C'),
            fw::Param::choice(kShading, kShadings, Shading::Gouraud)
                .help("gouraud: lit per vertex; phong: lit per pixel; toon: three tones and "
                      "an outline (shading)")
                .key('H'),
            fw::Param::integer(kSubdiv, 3)
                .range(0, 6)
                .help("icosphere subdivisions: 20 * 4^subdiv triangles (shading)")
                .key('U'),
            light_coordinate(kLightX, 'x', 2),
            light_coordinate(kLightY, 'y', 2),
            light_coordinate(kLightZ, 'z', 3),
        };
        i.controls = {"drag: move the light in x and y (scene shading)"};
        return i;
    }

    void init(fw::ProgramLibrary& programs) override {
        // File names within shaders/06_interpolation/.
        interpolate_ = &programs.load({"interpolate.vert", "interpolate.frag"});
        shading_ = &programs.load({"shading.vert", "shading.frag"});
        const fw::VertexLayout layout = fw::VertexLayout::of<Vertex>()
                                            .attr(A_POSITION, &Vertex::position)
                                            .attr(A_VALUE, &Vertex::value);

        // The colours change with the parameters: draw() rewrites them.
        triangle_vbo_ =
            fw::Buffer::from(triangle_vertices({}, {}, {}), GL_ARRAY_BUFFER, "triangle");
        triangle_ = fw::VertexArray(
            fw::VertexArrayDesc{.vertices = &triangle_vbo_, .layout = layout, .label = "triangle"});

        plane_vbo_ = fw::Buffer::from(plane_vertices(), GL_ARRAY_BUFFER, "plane vertices");
        plane_ibo_ = fw::Buffer::from(plane_indices(), GL_ELEMENT_ARRAY_BUFFER, "plane indices");
        plane_ = fw::VertexArray(fw::VertexArrayDesc{.vertices = &plane_vbo_,
                                                     .layout = layout,
                                                     .indices = &plane_ibo_,
                                                     .index_type = GL_UNSIGNED_INT,
                                                     .label = "plane"});
    }

    void draw(const fw::ParamValues& p, const fw::Frame& frame) override {
        // Each frame sets all the state it uses. GL's default, said aloud:
        // a flat input takes the value of each triangle's last vertex.
        glProvokingVertex(GL_LAST_VERTEX_CONVENTION);
        glDisable(GL_CULL_FACE);
        const float aspect = static_cast<float>(frame.width) / static_cast<float>(frame.height);
        const Scene scene = p[kScene];

        if (scene == Scene::Shading) {
            draw_sphere(p, aspect);
            return;
        }
        glDisable(GL_DEPTH_TEST);
        interpolate_->use();
        // The enum's value is the shader's QUALIFIER_* (shared.glsl). The
        // uniform is set only while active: until the student qualifies the
        // three inputs they carry the same value, and the compiler may drop it.
        interpolate_->set_if_active(kQualifierUniform, static_cast<int>(p[kQualifier]));
        interpolate_->set(kCheckerboardUniform, scene == Scene::Plane);
        interpolate_->set(kChecksUniform, static_cast<float>(p[kChecks]));
        if (scene == Scene::Triangle) {
            interpolate_->set(kMvpUniform, glm::mat4(1.0f));
            triangle_vbo_.update(triangle_vertices(p[kColorA], p[kColorB], p[kColorC]));
            glBindVertexArray(triangle_.id());
            glDrawArrays(GL_TRIANGLES, 0, 3);
        } else {
            interpolate_->set(kMvpUniform, plane_view_projection(aspect));
            // Two triangles through 6 indices (GL_UNSIGNED_INT, in the
            // element buffer of plane_).
            glBindVertexArray(plane_.id());
            glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(plane_.index_count()),
                           GL_UNSIGNED_INT, nullptr);
        }
    }

    // scene=shading: the sphere's size, e.g. {"subdiv": 3, "vertices": 642,
    // "triangles": 1280}.
    nlohmann::json stats(const fw::ParamValues& p, const fw::Frame&) const override {
        if (p[kScene] != Scene::Shading || sphere_subdiv_ < 0) return nlohmann::json::object();
        return {{kSubdiv.name, sphere_subdiv_},
                {"vertices", sphere_.vertex_count()},
                {"triangles", sphere_.index_count() / 3}};
    }

    bool on_drag(fw::ParamValues& p, const fw::Frame&, double dx, double dy) override {
        if (p[kScene] != Scene::Shading) return false;
        // 50 pixels of drag move the light one unit, within its range.
        p.set_clamped(kLightX, p[kLightX] + 0.02f * float(dx));
        p.set_clamped(kLightY, p[kLightY] + 0.02f * float(dy));
        return true;
    }

private:
    void draw_sphere(const fw::ParamValues& p, float aspect) {
        if (p[kSubdiv] != sphere_subdiv_) build_sphere(p[kSubdiv]);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        shading_->use();
        shading_->set(kViewProjectionUniform, sphere_view_projection(aspect));
        // The enum's value is the shader's SHADING_* (shared.glsl).
        shading_->set(kShadingUniform, static_cast<int>(p[kShading]));
        // The light and the material matter only once the student's lighting
        // is written; until then the compiler drops them: set while active.
        const glm::vec3 light{p[kLightX], p[kLightY], p[kLightZ]};
        shading_->set_if_active(kLightUniform, light);
        shading_->set_if_active(kEyeUniform, kSphereEye);
        shading_->set_if_active(kKaUniform, kKa);
        shading_->set_if_active(kKdUniform, kKd);
        shading_->set_if_active(kKsUniform, kKs);
        shading_->set_if_active(kShineUniform, kShine);
        shading_->set_if_active(kLaUniform, kLa);
        shading_->set_if_active(kLeUniform, kLe);
        glBindVertexArray(sphere_.id());
        glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(sphere_.index_count()), GL_UNSIGNED_INT,
                       nullptr);
    }

    void build_sphere(int subdiv) {
        const SphereMesh mesh = sphere_mesh(subdiv);
        sphere_vbo_ = fw::Buffer::from(mesh.vertices, GL_ARRAY_BUFFER, "icosphere vertices");
        sphere_ibo_ = fw::Buffer::from(mesh.indices, GL_ELEMENT_ARRAY_BUFFER, "icosphere indices");
        sphere_ = fw::VertexArray(
            fw::VertexArrayDesc{.vertices = &sphere_vbo_,
                                .layout = fw::VertexLayout::of<SurfaceVertex>()
                                              .attr(A_POSITION, &SurfaceVertex::position)
                                              .attr(A_NORMAL, &SurfaceVertex::normal),
                                .indices = &sphere_ibo_,
                                .index_type = GL_UNSIGNED_INT,
                                .label = "icosphere"});
        sphere_subdiv_ = subdiv;
    }

    fw::Program* interpolate_ = nullptr;
    fw::Program* shading_ = nullptr;
    fw::Buffer triangle_vbo_, plane_vbo_, plane_ibo_, sphere_vbo_, sphere_ibo_;
    fw::VertexArray triangle_, plane_, sphere_;
    int sphere_subdiv_ = -1;  // the subdivision sphere_ holds; -1: none yet
};

FW_LAB(InterpolationLab)

}  // namespace interpolation
