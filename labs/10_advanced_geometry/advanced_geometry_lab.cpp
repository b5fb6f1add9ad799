// Lab 10 `advanced-geometry`: one draw, many results.
//
// Teaches: instancing (one draw of many copies, each placed by gl_InstanceID
// and coloured by an attribute that advances once per instance); a user clip
// plane (gl_ClipDistance); layered rendering (one draw into all six faces of
// a cube map, the face chosen by the geometry shader's gl_Layer, each with
// its own view); adjacency primitives (a geometry shader that sees a
// triangle's neighbours and draws a mesh's silhouette).
// Lecture: the vertex shader's built-ins gl_InstanceID and gl_ClipDistance;
// the geometry stage's inputs (triangles_adjacency: 6 vertices) and outputs
// (line_strip, gl_Layer, gl_ViewportIndex); layered rendering into a cube
// map's 6 layers; the primitive types GL_TRIANGLES_ADJACENCY.
// GL: glBindBuffer, glVertexAttribPointer, glEnableVertexAttribArray,
// glVertexAttribDivisor, glDrawElementsInstanced, glDrawArraysInstanced;
// glEnable and glDisable of GL_CLIP_DISTANCE0; glBindFramebuffer and
// glViewport around the draw into a fw::CubeFramebuffer (a cube map attached
// whole, as layers, by the framework), a samplerCube; glDrawElements with
// GL_TRIANGLES_ADJACENCY; glBindVertexArray, glDrawArrays, glDrawElements.
// Student parts (marked TODO): draw_instances() in instances.cpp,
// draw_clipped() in advanced_geometry.cpp, cube_face_view() in layers.cpp,
// adjacency_indices() in silhouette.cpp; the instance's cell in
// shaders/10_advanced_geometry/grid.vert, the clip distance in sphere.vert,
// the six faces in layers.geom and the outline in silhouette.geom.
#include <cmath>
#include <cstdint>
#include <glm/gtc/matrix_transform.hpp>

#include "advanced_geometry.hpp"
#include "framework/gl.hpp"
#include "framework/lab.hpp"
#include "framework/meshes.hpp"
#include "instances.hpp"
#include "layers.hpp"
#include "parameters.hpp"
#include "silhouette.hpp"
// A_POSITION, A_NORMAL, T_CUBE: shared with the shaders.
#include "shared.glsl"

namespace advanced_geometry {

namespace {

constexpr const char* kColumnsUniform = "u_columns";  // grid.vert
constexpr const char* kRowsUniform = "u_rows";
constexpr const char* kProjectionUniform = "u_projection";  // sphere.vert, layers.geom, cube.vert
constexpr const char* kViewsUniform = "u_views";            // layers.geom
constexpr const char* kCubeUniform = "u_cube";              // cross.frag
constexpr const char* kModelUniform = "u_model";            // cube.vert
constexpr const char* kColorUniform = "u_color";            // flat.frag, line.frag

// The clip and silhouette scenes: the world's [-1.25, 1.25]^2 on the frame,
// seen along -z.
const glm::mat4 kOrtho = glm::ortho(-1.25f, 1.25f, -1.25f, 1.25f, -2.0f, 2.0f);
constexpr int kSphereSubdiv = 4;
constexpr glm::vec3 kCubeColor{0.25f, 0.45f, 0.7f}, kOutlineColor{1.0f, 0.85f, 0.2f};

// A mesh in buffers: its vertex array reads positions (and normals).
struct Mesh {
    fw::Buffer vertices, indices;
    fw::VertexArray vertex_array;
    GLsizei count = 0;
};

template <class V>
Mesh make_mesh(const std::vector<V>& vertices, const fw::VertexLayout& layout,
               const std::vector<std::uint32_t>& indices, const std::string& label) {
    Mesh m;
    m.vertices = fw::Buffer::from(vertices, GL_ARRAY_BUFFER, label);
    m.indices = fw::Buffer::from(indices, GL_ELEMENT_ARRAY_BUFFER, label + " indices");
    m.vertex_array = fw::VertexArray(fw::VertexArrayDesc{
        .vertices = &m.vertices, .layout = layout, .indices = &m.indices, .label = label});
    m.count = static_cast<GLsizei>(indices.size());
    return m;
}

struct SphereVertex {
    glm::vec3 position, normal;
};

}  // namespace

class AdvancedGeometryLab : public fw::Lab {
public:
    static fw::LabInfo info() {
        fw::LabInfo i;
        i.title = "One draw, many results: instances, layers, adjacency, clip planes";
        i.aspect = 1.0;  // a square scene: letterboxed in a frame of another shape
        i.params = params();
        i.functions = {fw::unit_function("cube_face_view", &cube_face_view)};
        return i;
    }

    void init(fw::ProgramLibrary& programs) override {
        // File names within shaders/10_advanced_geometry/.
        grid_ = &programs.load({"grid.vert", "color.frag"});
        sphere_ = &programs.load({"sphere.vert", "normal.frag"});
        layers_ = &programs.load({"layers.vert", "layers.geom", "layers.frag"});
        cross_ = &programs.load({"cross.vert", "cross.frag"});
        fill_ = &programs.load({"cube.vert", "flat.frag"});
        outline_ = &programs.load({"cube.vert", "silhouette.geom", "line.frag"});
        grid_mesh_ = make_instance_grid();

        const fw::MeshData ico = fw::icosphere(kSphereSubdiv);
        std::vector<SphereVertex> sphere;
        for (std::size_t k = 0; k < ico.positions.size(); ++k)
            sphere.push_back({ico.positions[k], ico.normals[k]});
        sphere_mesh_ = make_mesh(sphere,
                                 fw::VertexLayout::of<SphereVertex>()
                                     .attr(A_POSITION, &SphereVertex::position)
                                     .attr(A_NORMAL, &SphereVertex::normal),
                                 ico.indices, "sphere");

        const std::vector<glm::vec3> world = layer_world();
        world_vertices_ = static_cast<GLsizei>(world.size());
        world_buffer_ = fw::Buffer::from(world, GL_ARRAY_BUFFER, "layer world");
        world_ = fw::VertexArray(fw::VertexArrayDesc{
            .vertices = &world_buffer_, .layout = position_layout(3), .label = "layer world"});
        const std::vector<glm::vec2> square = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
        square_buffer_ = fw::Buffer::from(square, GL_ARRAY_BUFFER, "cross square");
        square_ = fw::VertexArray(fw::VertexArrayDesc{
            .vertices = &square_buffer_, .layout = position_layout(2), .label = "cross square"});

        const fw::VertexLayout corner = position_layout(3);
        cube_ = make_mesh(cube_corners(), corner, cube_triangles(), "cube");
        adjacency_ = adjacency_indices(cube_triangles());
        cube_adjacency_ = make_mesh(cube_corners(), corner, adjacency_, "cube adjacency");
    }

    void draw(const fw::ParamValues& p, const fw::Frame&) override {
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_CULL_FACE);
        scene_ = p[kScene];
        switch (scene_) {
            case Scene::Instances: {
                const int columns = p[kColumns], rows = p[kRows];
                grid_mesh_.colors.update(instance_colors(columns, rows));
                grid_->use();
                grid_->set(kColumnsUniform, columns);
                grid_->set(kRowsUniform, rows);
                draw_instances(grid_mesh_, columns * rows);
                break;
            }
            case Scene::Clip:
                glEnable(GL_DEPTH_TEST);
                glDepthFunc(GL_LESS);
                sphere_->use();
                sphere_->set(kProjectionUniform, kOrtho);
                draw_clipped(*sphere_, sphere_mesh_.vertex_array, sphere_mesh_.count, p[kClipAngle],
                             p[kClipOffset]);
                break;
            case Scene::Layers:
                draw_layers(p[kFaceSize]);
                break;
            case Scene::Silhouette:
                draw_silhouette(p[kYaw], p[kPitch]);
                break;
        }
    }

    nlohmann::json stats(const fw::ParamValues&, const fw::Frame&) const override {
        if (scene_ == Scene::Silhouette) return {{"adjacency", adjacency_}};
        return nlohmann::json::object();
    }

private:
    static fw::VertexLayout position_layout(int components) {
        fw::VertexLayout layout(components * sizeof(float));
        layout.add({A_POSITION, components, GL_FLOAT, 0, false, false});
        return layout;
    }

    // One draw of the world into all six faces, then the faces unfolded.
    void draw_layers(int face_size) {
        if (environment_.size() != face_size)
            environment_ = fw::CubeFramebuffer({face_size, "environment"});
        // The frame's target, put back after the faces are drawn.
        GLint frame = 0, viewport[4] = {0, 0, 0, 0};
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &frame);
        glGetIntegerv(GL_VIEWPORT, viewport);
        environment_.bind();
        glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);  // all six faces
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        layers_->use();
        layers_->set(kProjectionUniform, glm::perspective(glm::radians(90.0f), 1.0f, 0.1f, 10.0f));
        for (int face = 0; face < 6; ++face)
            layers_->set_if_active(std::string(kViewsUniform) + "[" + std::to_string(face) + "]",
                                   cube_face_view(face));
        glBindVertexArray(world_.id());
        glDrawArrays(GL_TRIANGLES, 0, world_vertices_);
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(frame));
        glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
        glDisable(GL_DEPTH_TEST);
        cross_->use();
        environment_.color_texture().bind(T_CUBE);
        cross_->set(kCubeUniform, T_CUBE);
        glBindVertexArray(square_.id());
        glDrawArraysInstanced(GL_TRIANGLE_STRIP, 0, 4, 6);
    }

    // The cube shaded, then its outline from the adjacency draw on top.
    void draw_silhouette(float yaw, float pitch) {
        const glm::mat4 model =
            glm::rotate(glm::mat4(1.0f), glm::radians(pitch), glm::vec3(1.0f, 0.0f, 0.0f)) *
            glm::rotate(glm::mat4(1.0f), glm::radians(yaw), glm::vec3(0.0f, 1.0f, 0.0f));
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        fill_->use();
        fill_->set(kModelUniform, model);
        fill_->set(kProjectionUniform, kOrtho);
        fill_->set(kColorUniform, kCubeColor);
        glBindVertexArray(cube_.vertex_array.id());
        glDrawElements(GL_TRIANGLES, cube_.count, GL_UNSIGNED_INT, nullptr);
        glDisable(GL_DEPTH_TEST);
        outline_->use();
        // Until silhouette.geom emits a vertex, cube.vert's output is unused
        // and a compiler (Mesa 25) may drop its uniforms.
        outline_->set_if_active(kModelUniform, model);
        outline_->set_if_active(kProjectionUniform, kOrtho);
        outline_->set(kColorUniform, kOutlineColor);
        glBindVertexArray(cube_adjacency_.vertex_array.id());
        glDrawElements(GL_TRIANGLES_ADJACENCY, cube_adjacency_.count, GL_UNSIGNED_INT, nullptr);
    }

    fw::Program *grid_ = nullptr, *sphere_ = nullptr, *layers_ = nullptr, *cross_ = nullptr;
    fw::Program *fill_ = nullptr, *outline_ = nullptr;
    InstanceGrid grid_mesh_;
    Mesh sphere_mesh_, cube_, cube_adjacency_;
    fw::Buffer world_buffer_, square_buffer_;
    fw::VertexArray world_, square_;
    GLsizei world_vertices_ = 0;
    fw::CubeFramebuffer environment_;
    std::vector<std::uint32_t> adjacency_;
    Scene scene_ = Scene::Instances;
};

FW_LAB(AdvancedGeometryLab)

}  // namespace advanced_geometry
