// Lab 4 `geometry`: geometry shaders.
//
// Teaches: the stage between vertex shader and rasterizer that receives a
// whole primitive and emits any number of new ones (EmitVertex, EndPrimitive,
// max_vertices, an output type of its own); re-emitting, duplicating and
// moving triangles, turning triangles into lines, and per-triangle data (edge
// distances) that no vertex shader could compute.
// Lecture: geometry shaders (the pass-through and duplicating examples),
// face normals from cross products, Lambert shading.
// GL: GL_GEOMETRY_SHADER (layout(triangles) in, layout(triangle_strip /
// line_strip, max_vertices = N) out), noperspective interpolation,
// GL_PRIMITIVES_GENERATED (counts what the geometry shader emits).
// Student parts (marked TODO): the geometry
// shaders shaders/04_geometry/duplicate.geom, explode.geom, normals.geom and
// the edge distances in wireframe.geom.
#include <array>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <string>
#include <vector>

#include "framework/gl.hpp"
#include "framework/lab.hpp"
#include "framework/meshes.hpp"

namespace geometry {

namespace {

// Vertex attribute locations, the same numbers as `layout(location = ...)`
// in shaders/04_geometry/mesh.vert: change both or neither.
constexpr GLuint kPositionLocation = 0;  // in vec3 a_position
constexpr GLuint kNormalLocation = 1;    // in vec3 a_normal

constexpr int kMaxSubdiv = 5;

// The sheet's scene: eye on +z looking at the sphere's centre, light from
// the upper right front, grey sphere, orange copy, yellow normals, white edges.
const glm::vec3 kEye{0.0f, 0.0f, 4.0f};
constexpr float kFovYDegrees = 45.0f, kNear = 0.1f, kFar = 100.0f;
const glm::vec3 kLightDir = glm::normalize(glm::vec3(1.0f, 1.0f, 1.0f));
const glm::vec3 kGrey{0.8f, 0.8f, 0.8f};
const glm::vec3 kTint{1.0f, 0.5f, 0.2f};
const glm::vec3 kYellow{1.0f, 1.0f, 0.0f};
const glm::vec3 kWhite{1.0f, 1.0f, 1.0f};

// 24 bytes: two vec3, no padding. Read by shaders/04_geometry/mesh.vert.
struct Vertex {
    glm::vec3 position;
    glm::vec3 normal;
};

// One icosphere on the GPU.
struct Mesh {
    fw::Buffer vertices, indices;
    fw::VertexArray vao;
};

// Uniforms read only by the student parts. A GLSL compiler removes a uniform
// that the shader never reads, and fw::Program::set() refuses a uniform the
// program lacks; until the part that reads it is written, it is not set.
template <class T>
void set_student_uniform(const fw::Program& program, const char* name, const T& value) {
    if (program.has_uniform(name)) program.set(name, value);
}

}  // namespace

class GeometryLab : public fw::Lab {
public:
    static fw::LabInfo info() {
        fw::LabInfo i;
        i.number = 4;
        i.id = "geometry";
        i.dir = "04_geometry";
        i.title = "Geometry shaders";
        i.params = {
            fw::Param::choice("mode",
                              {"passthrough", "duplicate", "explode", "normals", "wireframe"},
                              "passthrough")
                .help("passthrough: re-emit each triangle; duplicate: add a moved, tinted copy; "
                      "explode: move each triangle along its face normal; normals: draw vertex "
                      "normals as lines; wireframe: edges from distances in the same pass")
                .key('M'),
            fw::Param::integer("subdiv", 2)
                .range(0, kMaxSubdiv)
                .help("subdivisions of the icosahedron: 20 * 4^subdiv triangles")
                .key('S'),
            fw::Param::number("spin", 0)
                .range(-180, 180)
                .step(15)
                .unit("deg")
                .help("model rotation about the y axis")
                .key('Y'),
            fw::Param::number("amount", 0.2)
                .range(0, 1)
                .step(0.05)
                .help("how far each triangle moves along its face normal (explode)")
                .key('A'),
            fw::Param::number("offset_x", 1.5)
                .range(-3, 3)
                .step(0.25)
                .help("x of the copy's offset in object space (duplicate)")
                .key('X'),
            fw::Param::number("offset_y", 0)
                .range(-3, 3)
                .step(0.25)
                .help("y (up) of the copy's offset in object space (duplicate)")
                .key('U'),
            fw::Param::number("offset_z", -1.5)
                .range(-3, 3)
                .step(0.25)
                .help("z of the copy's offset in object space (duplicate)")
                .key('Z'),
            fw::Param::number("length", 0.15)
                .range(0, 0.5)
                .step(0.05)
                .help("length of each normal line (normals)")
                .key('L'),
        };
        i.controls = {"drag: spin the sphere about the y axis"};
        return i;
    }

    void init(fw::ProgramLibrary& programs) override {
        auto load = [&](const char* geom, const char* frag) {
            return &programs.load({"04_geometry/mesh.vert", std::string("04_geometry/") + geom,
                                   std::string("04_geometry/") + frag});
        };
        passthrough_ = load("passthrough.geom", "lambert.frag");
        duplicate_ = load("duplicate.geom", "lambert.frag");
        explode_ = load("explode.geom", "lambert.frag");
        normals_ = load("normals.geom", "line.frag");
        wireframe_ = load("wireframe.geom", "wireframe.frag");

        const fw::VertexLayout layout = fw::VertexLayout::of<Vertex>()
                                            .attr(kPositionLocation, &Vertex::position)
                                            .attr(kNormalLocation, &Vertex::normal);
        for (int level = 0; level <= kMaxSubdiv; ++level) {
            const fw::MeshData data = fw::icosphere(level);
            std::vector<Vertex> vertices;
            for (std::size_t v = 0; v < data.positions.size(); ++v)
                vertices.push_back({data.positions[v], data.normals[v]});
            const std::string label = "icosphere " + std::to_string(level);
            Mesh& mesh = meshes_[level];
            mesh.vertices = fw::Buffer::from(vertices, GL_ARRAY_BUFFER, label + " vertices");
            mesh.indices = fw::Buffer::from(data.indices, GL_ELEMENT_ARRAY_BUFFER, label);
            mesh.vao =
                fw::VertexArray({&mesh.vertices, layout, &mesh.indices, GL_UNSIGNED_INT, label});
        }
    }

    void draw(const fw::ParamValues& p, const fw::Frame& frame) override {
        // A closed mesh with outward counter-clockwise faces (lab 0): the
        // depth test plus back-face culling, so gaps show the background.
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glEnable(GL_CULL_FACE);
        glFrontFace(GL_CCW);
        glCullFace(GL_BACK);

        const glm::mat4 model =
            glm::rotate(glm::mat4(1.0f), glm::radians(p.number("spin")), {0.0f, 1.0f, 0.0f});
        const float aspect = static_cast<float>(frame.width) / static_cast<float>(frame.height);
        const glm::mat4 view_projection =
            glm::perspective(glm::radians(kFovYDegrees), aspect, kNear, kFar) *
            glm::lookAt(kEye, glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
        for (fw::Program* program : {passthrough_, duplicate_, explode_, normals_, wireframe_}) {
            program->set("u_model", model);
            program->set("u_view_projection", view_projection);
        }

        const std::string& mode = p.choice("mode");
        fw::Program* shaded = passthrough_;
        if (mode == "duplicate") {
            shaded = duplicate_;
            const glm::vec3 offset{p.number("offset_x"), p.number("offset_y"),
                                   p.number("offset_z")};
            // model * (q + offset) = model * q + mat3(model) * offset.
            set_student_uniform(*shaded, "u_offset", glm::mat3(model) * offset);
            set_student_uniform(*shaded, "u_tint", kTint);
        } else if (mode == "explode") {
            shaded = explode_;
            set_student_uniform(*shaded, "u_amount", p.number("amount"));
        } else if (mode == "wireframe") {
            shaded = wireframe_;
            set_student_uniform(
                *shaded, "u_viewport",
                glm::vec2(static_cast<float>(frame.width), static_cast<float>(frame.height)));
            shaded->set("u_edge_color", kWhite);
        }
        shaded->set("u_color", kGrey);
        shaded->set("u_light_dir", kLightDir);

        const Mesh& mesh = meshes_[static_cast<std::size_t>(p.integer("subdiv"))];
        const auto index_count = static_cast<GLsizei>(mesh.vao.index_count());
        shaded->use();
        mesh.vao.draw_indexed(GL_TRIANGLES, index_count);
        if (mode == "normals") {
            // The same triangles again, through the geometry shader that
            // turns each into three lines.
            normals_->set("u_color", kYellow);
            set_student_uniform(*normals_, "u_length", p.number("length"));
            normals_->use();
            mesh.vao.draw_indexed(GL_TRIANGLES, index_count);
        }
    }

    // The mesh's size: {"triangles": 320, "vertices": 162} at subdiv 2.
    nlohmann::json stats(const fw::ParamValues& p) const override {
        const Mesh& mesh = meshes_[static_cast<std::size_t>(p.integer("subdiv"))];
        return {{"triangles", mesh.vao.index_count() / 3}, {"vertices", mesh.vao.vertex_count()}};
    }

    bool on_drag(fw::ParamValues& p, double dx, double /*dy*/) override {
        // Half a degree per pixel, wrapped into [-180, 180].
        p.number_ref("spin") = std::remainder(p.number("spin") + 0.5 * dx, 360.0);
        return true;
    }

private:
    fw::Program *passthrough_ = nullptr, *duplicate_ = nullptr, *explode_ = nullptr;
    fw::Program *normals_ = nullptr, *wireframe_ = nullptr;
    std::array<Mesh, kMaxSubdiv + 1> meshes_;
};

FW_LAB(GeometryLab)

}  // namespace geometry
