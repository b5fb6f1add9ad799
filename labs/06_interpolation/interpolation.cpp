// Lab 6 `interpolation`: what the rasterizer interpolates.
//
// Teaches: barycentric interpolation of vertex values across a triangle;
// perspective-correct (smooth) versus screen-space (noperspective)
// interpolation; flat shading and the provoking vertex; Gouraud (per-vertex)
// versus Phong (per-pixel) shading of the Blinn-Phong model; toon shading.
// Lecture: rasterization and interpolation, shading models, NPR.
// GL: the GLSL interpolation qualifiers smooth, noperspective and flat,
// glProvokingVertex, glDrawElements.
// Student parts (marked TODO), all GLSL: the
// qualifiers in shaders/06_interpolation/interpolate.frag; the lighting in
// shading.vert (Gouraud) and shading.frag (Phong, toon).
#include <cctype>
#include <glm/gtc/matrix_transform.hpp>
#include <string>
#include <vector>

#include "framework/gl.hpp"
#include "framework/lab.hpp"
#include "scenes.hpp"

namespace interpolation {

namespace {

// Vertex attribute locations, the same numbers as `layout(location = ...)`
// in interpolate.vert and shading.vert: change both or neither.
constexpr GLuint kPositionLocation = 0;  // in vec3 a_position
constexpr GLuint kValueLocation = 1;     // in vec3 a_value (interpolate.vert)
constexpr GLuint kNormalLocation = 1;    // in vec3 a_normal (shading.vert)

// The lecture's material and light: ka La + (kd cos(theta) + ks cos(delta)^shine) Le.
const glm::vec3 kKa{0.1f}, kKd{0.8f, 0.3f, 0.2f}, kKs{0.5f}, kLa{1.0f}, kLe{1.0f};
constexpr float kShine = 32.0f;

// Sets a uniform that matters only once the student parts are written.
// Until then the compiler may drop it, e.g. when three unqualified inputs
// carry the same value: only uniforms that "will actually be accessed when
// the executable code is executed" are active and have a location (GL 4.3,
// Uniform Variables), and Program::set refuses the others.
template <class T>
void set_if_used(const fw::Program& program, const char* name, const T& value) {
    if (program.has_uniform(name)) program.set(name, value);
}

// The light's coordinates, in world units; on_drag keeps them in range.
constexpr float kLightRange = 10.0f;
fw::Param light_coordinate(char axis, double def) {
    return fw::Param::number(std::string("light_") + axis, def)
        .range(-kLightRange, kLightRange)
        .step(0.5)
        .help(std::string("the point light's ") + axis + " (shading)")
        .key(std::toupper(axis));
}

}  // namespace

class InterpolationLab : public fw::Lab {
public:
    static fw::LabInfo info() {
        fw::LabInfo i;
        i.number = 6;
        i.id = "interpolation";
        i.dir = "06_interpolation";
        i.title = "What the rasterizer interpolates";
        i.params = {
            fw::Param::choice("scene", {"triangle", "plane", "shading"}, "triangle")
                .help("triangle: one colour per vertex; plane: a checkered floor in "
                      "perspective; shading: a lit icosphere")
                .key('S'),
            fw::Param::choice("qualifier", {"smooth", "noperspective", "flat"}, "smooth")
                .help("how the fragment shader's input is interpolated (triangle, plane)")
                .key('Q'),
            fw::Param::color("color_a", "ff0000").help("colour of A (-0.8, -0.8) (triangle)"),
            fw::Param::color("color_b", "ffffff").help("colour of B (0.8, -0.8) (triangle)"),
            fw::Param::color("color_c", "ffffff")
                .help("colour of C (0, 0.8), the provoking vertex (triangle)"),
            fw::Param::integer("checks", 8)
                .range(1, 64)
                .help("checkerboard cells along u and along v (plane)")
                .key('C'),
            fw::Param::choice("shading", {"gouraud", "phong", "toon"}, "gouraud")
                .help("gouraud: lit per vertex; phong: lit per pixel; toon: three tones and "
                      "an outline (shading)")
                .key('H'),
            fw::Param::integer("subdiv", 3)
                .range(0, 6)
                .help("icosphere subdivisions: 20 * 4^subdiv triangles (shading)")
                .key('U'),
            light_coordinate('x', 2),
            light_coordinate('y', 2),
            light_coordinate('z', 3),
        };
        i.controls = {"drag: move the light in x and y (scene shading)"};
        return i;
    }

    void init(fw::ProgramLibrary& programs) override {
        interpolate_ = &programs.load(
            {"06_interpolation/interpolate.vert", "06_interpolation/interpolate.frag"});
        shading_ =
            &programs.load({"06_interpolation/shading.vert", "06_interpolation/shading.frag"});
        const fw::VertexLayout layout = fw::VertexLayout::of<Vertex>()
                                            .attr(kPositionLocation, &Vertex::position)
                                            .attr(kValueLocation, &Vertex::value);

        // The colours change with the parameters: draw() rewrites them.
        triangle_vbo_ =
            fw::Buffer::from(triangle_vertices({}, {}, {}), GL_ARRAY_BUFFER, "triangle");
        triangle_ = fw::VertexArray({&triangle_vbo_, layout, nullptr, GL_UNSIGNED_INT, "triangle"});

        plane_vbo_ = fw::Buffer::from(plane_vertices(), GL_ARRAY_BUFFER, "plane vertices");
        plane_ibo_ = fw::Buffer::from(plane_indices(), GL_ELEMENT_ARRAY_BUFFER, "plane indices");
        plane_ = fw::VertexArray({&plane_vbo_, layout, &plane_ibo_, GL_UNSIGNED_INT, "plane"});
    }

    void draw(const fw::ParamValues& p, const fw::Frame& frame) override {
        // Each frame sets all the state it uses. GL's default, said aloud:
        // a flat input takes the value of each triangle's last vertex.
        glProvokingVertex(GL_LAST_VERTEX_CONVENTION);
        glDisable(GL_CULL_FACE);
        const float aspect = static_cast<float>(frame.width) / static_cast<float>(frame.height);
        const std::string& scene = p.choice("scene");

        if (scene == "shading") {
            draw_sphere(p, aspect);
            return;
        }
        glDisable(GL_DEPTH_TEST);
        interpolate_->use();
        // 0 smooth, 1 noperspective, 2 flat: the order of the parameter's choices.
        set_if_used(*interpolate_, "u_qualifier", p.choice_index("qualifier"));
        interpolate_->set("u_checkerboard", scene == "plane");
        interpolate_->set("u_checks", static_cast<float>(p.integer("checks")));
        if (scene == "triangle") {
            interpolate_->set("u_mvp", glm::mat4(1.0f));
            triangle_vbo_.update(
                triangle_vertices(p.color("color_a"), p.color("color_b"), p.color("color_c")));
            triangle_.draw(GL_TRIANGLES, 3);
        } else {
            interpolate_->set("u_mvp", plane_view_projection(aspect));
            plane_.draw_indexed(GL_TRIANGLES, static_cast<GLsizei>(plane_.index_count()));
        }
    }

    // scene=shading: the sphere's size, e.g. {"subdiv": 3, "vertices": 642,
    // "triangles": 1280}.
    nlohmann::json stats(const fw::ParamValues& p) const override {
        if (p.choice("scene") != "shading" || sphere_subdiv_ < 0) return nlohmann::json::object();
        return {{"subdiv", sphere_subdiv_},
                {"vertices", sphere_.vertex_count()},
                {"triangles", sphere_.index_count() / 3}};
    }

    bool on_drag(fw::ParamValues& p, double dx, double dy) override {
        if (p.choice("scene") != "shading") return false;
        // 50 pixels of drag move the light one unit.
        const float x = p.number("light_x") + 0.02f * float(dx);
        const float y = p.number("light_y") + 0.02f * float(dy);
        p.number_ref("light_x") = glm::clamp(x, -kLightRange, kLightRange);
        p.number_ref("light_y") = glm::clamp(y, -kLightRange, kLightRange);
        return true;
    }

private:
    void draw_sphere(const fw::ParamValues& p, float aspect) {
        if (p.integer("subdiv") != sphere_subdiv_) build_sphere(p.integer("subdiv"));
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        shading_->use();
        shading_->set("u_view_projection", sphere_view_projection(aspect));
        // 0 gouraud, 1 phong, 2 toon: the order of the parameter's choices.
        shading_->set("u_shading", p.choice_index("shading"));
        const glm::vec3 light{p.number("light_x"), p.number("light_y"), p.number("light_z")};
        set_if_used(*shading_, "u_light", light);
        set_if_used(*shading_, "u_eye", kSphereEye);
        set_if_used(*shading_, "u_ka", kKa);
        set_if_used(*shading_, "u_kd", kKd);
        set_if_used(*shading_, "u_ks", kKs);
        set_if_used(*shading_, "u_shine", kShine);
        set_if_used(*shading_, "u_la", kLa);
        set_if_used(*shading_, "u_le", kLe);
        sphere_.draw_indexed(GL_TRIANGLES, static_cast<GLsizei>(sphere_.index_count()));
    }

    void build_sphere(int subdiv) {
        const SphereMesh mesh = sphere_mesh(subdiv);
        sphere_vbo_ = fw::Buffer::from(mesh.vertices, GL_ARRAY_BUFFER, "icosphere vertices");
        sphere_ibo_ = fw::Buffer::from(mesh.indices, GL_ELEMENT_ARRAY_BUFFER, "icosphere indices");
        sphere_ = fw::VertexArray({&sphere_vbo_,
                                   fw::VertexLayout::of<SurfaceVertex>()
                                       .attr(kPositionLocation, &SurfaceVertex::position)
                                       .attr(kNormalLocation, &SurfaceVertex::normal),
                                   &sphere_ibo_, GL_UNSIGNED_INT, "icosphere"});
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
