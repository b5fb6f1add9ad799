// Lab 4 `geometry`: geometry shaders.
//
// Teaches: the stage between vertex shader and rasterizer that receives a
// whole primitive and emits any number of new ones (EmitVertex, EndPrimitive,
// max_vertices, an output type of its own); re-emitting, duplicating and
// moving triangles, turning triangles into lines, and per-triangle data (edge
// distances) that no vertex shader could compute.
// Lecture: geometry shaders (the pass-through and duplicating examples),
// face normals from cross products, Lambert shading.
// GL: glEnable(GL_DEPTH_TEST / GL_CULL_FACE), glDepthFunc, glFrontFace,
// glCullFace, glBindVertexArray, glDrawElements (GL_TRIANGLES, each triangle
// handed whole to the geometry shader), GL_GEOMETRY_SHADER (layout(triangles)
// in, layout(triangle_strip / line_strip, max_vertices = N) out),
// noperspective interpolation, GL_PRIMITIVES_GENERATED (the framework's query
// around each frame: counts what the geometry shader emits).
// Student parts (marked TODO): the geometry
// shaders shaders/04_geometry/duplicate.geom, explode.geom, normals.geom and
// the edge distances in wireframe.geom.
#include <array>
#include <cmath>
#include <string>

#include "framework/gl.hpp"
#include "framework/lab.hpp"
#include "scene.hpp"
// A_POSITION, A_NORMAL: attribute locations, shared with mesh.vert.
#include "shared.glsl"

namespace geometry {

namespace {

// The shaders' uniforms.
constexpr const char* kModelUniform = "u_model";                     // mesh.vert
constexpr const char* kViewProjectionUniform = "u_view_projection";  // mesh.vert, the .geom
constexpr const char* kColorUniform = "u_color";                     // the .geom, line.frag
constexpr const char* kLightDirUniform = "u_light_dir";              // lambert.frag, wireframe.frag
constexpr const char* kOffsetUniform = "u_offset";                   // duplicate.geom
constexpr const char* kTintUniform = "u_tint";                       // duplicate.geom
constexpr const char* kAmountUniform = "u_amount";                   // explode.geom
constexpr const char* kLengthUniform = "u_length";                   // normals.geom
constexpr const char* kViewportUniform = "u_viewport";               // wireframe.geom
constexpr const char* kEdgeColorUniform = "u_edge_color";            // wireframe.frag

// The sheet's shading: light from the upper right front, grey sphere,
// orange copy, yellow normals, white edges.
const glm::vec3 kLightDir = glm::normalize(glm::vec3(1.0f, 1.0f, 1.0f));
const glm::vec3 kGrey{0.8f, 0.8f, 0.8f};
const glm::vec3 kTint{1.0f, 0.5f, 0.2f};
const glm::vec3 kYellow{1.0f, 1.0f, 0.0f};
const glm::vec3 kWhite{1.0f, 1.0f, 1.0f};

// One icosphere on the GPU.
struct Mesh {
    fw::Buffer vertices, indices;
    fw::VertexArray vao;
};

}  // namespace

class GeometryLab : public fw::Lab {
public:
    static fw::LabInfo info() {
        fw::LabInfo i;
        i.title = "Geometry shaders";
        i.params = params();
        i.controls = {"drag: spin the sphere about the y axis"};
        return i;
    }

    void init(fw::ProgramLibrary& programs) override {
        // File names within shaders/04_geometry/.
        auto load = [&](const char* geom, const char* frag) {
            return &programs.load({"mesh.vert", geom, frag});
        };
        passthrough_ = load("passthrough.geom", "lambert.frag");
        duplicate_ = load("duplicate.geom", "lambert.frag");
        explode_ = load("explode.geom", "lambert.frag");
        normals_ = load("normals.geom", "line.frag");
        wireframe_ = load("wireframe.geom", "wireframe.frag");

        const fw::VertexLayout layout = fw::VertexLayout::of<Vertex>()
                                            .attr(A_POSITION, &Vertex::position)
                                            .attr(A_NORMAL, &Vertex::normal);
        for (int level = 0; level <= kMaxSubdiv; ++level) {
            const SphereMesh data = sphere_mesh(level);
            const std::string label = "icosphere " + std::to_string(level);
            Mesh& mesh = meshes_[level];
            mesh.vertices = fw::Buffer::from(data.vertices, GL_ARRAY_BUFFER, label + " vertices");
            mesh.indices = fw::Buffer::from(data.indices, GL_ELEMENT_ARRAY_BUFFER, label);
            // The vertex array records the layout and the index buffer;
            // draw() binds it and draws.
            mesh.vao = fw::VertexArray(fw::VertexArrayDesc{.vertices = &mesh.vertices,
                                                           .layout = layout,
                                                           .indices = &mesh.indices,
                                                           .index_type = GL_UNSIGNED_INT,
                                                           .label = label});
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

        const Mode mode = p[kMode];
        const float aspect = static_cast<float>(frame.width) / static_cast<float>(frame.height);
        const Transforms transforms{model_matrix(p[kSpin]), view_projection(aspect)};
        const fw::Program& shaded = shaded_program(mode, p, frame, transforms);

        // The icosphere's triangles, 3 indices each (GL_UNSIGNED_INT, in the
        // element buffer the vertex array holds): the geometry shader receives
        // each triangle whole.
        const Mesh& mesh = meshes_[static_cast<std::size_t>(p[kSubdiv])];
        const auto index_count = static_cast<GLsizei>(mesh.vao.index_count());
        shaded.use();
        glBindVertexArray(mesh.vao.id());
        glDrawElements(GL_TRIANGLES, index_count, GL_UNSIGNED_INT, nullptr);
        if (mode == Mode::Normals) {
            // The same triangles again (the vertex array is still bound),
            // through the geometry shader that turns each into three lines.
            set_transforms(*normals_, transforms);
            normals_->set(kColorUniform, kYellow);
            normals_->set_if_active(kLengthUniform, p[kLength]);
            normals_->use();
            glDrawElements(GL_TRIANGLES, index_count, GL_UNSIGNED_INT, nullptr);
        }
        glBindVertexArray(0);
    }

    // The mesh's size: {"triangles": 320, "vertices": 162} at subdiv 2.
    nlohmann::json stats(const fw::ParamValues& p, const fw::Frame&) const override {
        const Mesh& mesh = meshes_[static_cast<std::size_t>(p[kSubdiv])];
        return {{"triangles", mesh.vao.index_count() / 3}, {"vertices", mesh.vao.vertex_count()}};
    }

    bool on_drag(fw::ParamValues& p, const fw::Frame&, double dx, double /*dy*/) override {
        // Half a degree per pixel, wrapped into [-180, 180].
        p.number_ref(kSpin) = std::remainder(p[kSpin] + 0.5 * dx, 360.0);
        return true;
    }

private:
    // M and P V, for mesh.vert and the geometry shaders that leave clip space.
    struct Transforms {
        glm::mat4 model, view_projection;
    };

    // Only the programs this frame draws with get their uniforms: one that
    // failed to build costs only the modes that use it.
    static void set_transforms(const fw::Program& program, const Transforms& t) {
        program.set(kModelUniform, t.model);
        program.set(kViewProjectionUniform, t.view_projection);
    }

    // The program that draws the sphere in `mode`, its uniforms set. The
    // uniforms that only the student parts read are set with set_if_active():
    // the compiler removes them until that part is written.
    const fw::Program& shaded_program(Mode mode, const fw::ParamValues& p, const fw::Frame& frame,
                                      const Transforms& t) const {
        fw::Program* shaded = passthrough_;
        switch (mode) {
            case Mode::Passthrough:
            case Mode::Normals:  // the sphere as passthrough, then the normals' lines
                break;
            case Mode::Duplicate: {
                shaded = duplicate_;
                const glm::vec3 offset{p[kOffsetX], p[kOffsetY], p[kOffsetZ]};
                // model * (q + offset) = model * q + mat3(model) * offset.
                shaded->set_if_active(kOffsetUniform, glm::mat3(t.model) * offset);
                shaded->set_if_active(kTintUniform, kTint);
                break;
            }
            case Mode::Explode:
                shaded = explode_;
                shaded->set_if_active(kAmountUniform, p[kAmount]);
                break;
            case Mode::Wireframe:
                shaded = wireframe_;
                shaded->set_if_active(
                    kViewportUniform,
                    glm::vec2(static_cast<float>(frame.width), static_cast<float>(frame.height)));
                shaded->set(kEdgeColorUniform, kWhite);
                break;
        }
        set_transforms(*shaded, t);
        shaded->set(kColorUniform, kGrey);
        shaded->set(kLightDirUniform, kLightDir);
        return *shaded;
    }

    fw::Program *passthrough_ = nullptr, *duplicate_ = nullptr, *explode_ = nullptr;
    fw::Program *normals_ = nullptr, *wireframe_ = nullptr;
    std::array<Mesh, kMaxSubdiv + 1> meshes_;
};

FW_LAB(GeometryLab)

}  // namespace geometry
