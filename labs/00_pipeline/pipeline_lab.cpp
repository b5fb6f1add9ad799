// Lab 0 `pipeline`: what the pipeline does to triangles (warm-up).
//
// Teaches: how a vertex array describes the vertex layout; the depth test
// versus draw order; an indexed face set versus the flat vertex list it
// expands to; how primitive assembly reads one vertex list in seven modes;
// front faces, back faces and culling.
// Lecture: depth buffer and draw order, indexed face sets, primitive types
// (points, lines, strips, fans), face orientation and back-face culling.
// GL: glBindVertexArray, glBindBuffer, glVertexAttribPointer,
// glEnableVertexAttribArray, glDrawArrays, glDrawElements, glEnable/glDisable,
// glDepthFunc, glFrontFace, glCullFace, gl_PointSize with GL_PROGRAM_POINT_SIZE.
// Student parts (marked TODO): describe_vertex_layout(), draw_face_set(),
// set_depth_test() and set_culling() in pipeline.cpp, expand_indices() in
// meshes.cpp, and the pass-through in shaders/00_pipeline/pipeline.vert.
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "framework/gl.hpp"
#include "framework/lab.hpp"
#include "meshes.hpp"
#include "pipeline.hpp"
#include "scenes.hpp"
// A_POSITION, A_COLOR: attribute locations, shared with pipeline.vert.
#include "shared.glsl"

namespace pipeline {

namespace {

constexpr const char* kMvpUniform = "u_mvp";

}  // namespace

class PipelineLab : public fw::Lab {
public:
    static fw::LabInfo info() {
        fw::LabInfo i;
        i.title = "What the pipeline does to triangles";
        i.aspect = 1.0;  // a square scene: letterboxed in a frame of another shape
        i.params = params();
        i.controls = {"drag: rotate the cube (yaw, pitch) in scene culling"};
        i.functions = {fw::unit_function("expand_quad", &expand_quad)};
        return i;
    }

    void init(fw::ProgramLibrary& programs) override {
        program_ = &programs.load({"pipeline.vert", "pipeline.frag"});

        quad_vbo_ = fw::Buffer::from(order_quads(), GL_ARRAY_BUFFER, "order quads");
        quads_ = make_vertex_array("order quads", quad_vbo_, nullptr);

        // The same 6 vertices serve scene=indexed (through the indices) and
        // scene=primitives (in their own order, without the indices).
        const std::vector<Vertex> vertices = face_set_vertices();
        const std::vector<GLuint> indices = face_set_indices();
        face_vertex_count_ = static_cast<GLsizei>(vertices.size());
        face_index_count_ = static_cast<GLsizei>(indices.size());
        face_vbo_ = fw::Buffer::from(vertices, GL_ARRAY_BUFFER, "face set vertices");
        face_ibo_ = fw::Buffer::from(indices, GL_ELEMENT_ARRAY_BUFFER, "face set indices");
        faces_ = make_vertex_array("face set", face_vbo_, &face_ibo_);
        flat_vbo_ =
            fw::Buffer::from(expand_indices(vertices, indices), GL_ARRAY_BUFFER, "face set, flat");
        flat_ = make_vertex_array("face set, flat", flat_vbo_, nullptr);

        const std::vector<GLuint> cube_index_list = cube_indices();
        cube_index_count_ = static_cast<GLsizei>(cube_index_list.size());
        cube_vbo_ = fw::Buffer::from(cube_vertices(), GL_ARRAY_BUFFER, "cube vertices");
        cube_ibo_ = fw::Buffer::from(cube_index_list, GL_ELEMENT_ARRAY_BUFFER, "cube indices");
        cube_ = make_vertex_array("cube", cube_vbo_, &cube_ibo_);
    }

    void draw(const fw::ParamValues& p, const fw::Frame& frame) override {
        // Each frame sets all the state it uses, whatever the last frame left.
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_CULL_FACE);
        glEnable(GL_PROGRAM_POINT_SIZE);
        program_->use();
        program_->set(kMvpUniform, glm::mat4(1.0f));

        switch (p[kScene]) {
            case Scene::Order: {
                set_depth_test(p[kDepthTest]);
                const bool red_first = p[kFirst] == First::Red;
                glBindVertexArray(quads_.id());
                glDrawArrays(GL_TRIANGLES, red_first ? kRedQuadFirst : kBlueQuadFirst,
                             kQuadVertices);
                glDrawArrays(GL_TRIANGLES, red_first ? kBlueQuadFirst : kRedQuadFirst,
                             kQuadVertices);
                break;
            }
            case Scene::Indexed:
                draw_face_set(p[kStorage], faces_, flat_, face_index_count_);
                break;
            case Scene::Primitives:
                // The 6 vertices in their own order, assembled in the chosen mode.
                glBindVertexArray(faces_.id());
                glDrawArrays(static_cast<GLenum>(p[kPrimitive]), 0, face_vertex_count_);
                break;
            case Scene::Culling:
                draw_cube(p, frame);
                break;
        }
        glBindVertexArray(0);
    }

    // Every scene: "layout", the vertex layout as GL holds it in the quads'
    // vertex array (describe_vertex_layout() made it), read back attribute by
    // attribute: {"position": {"enabled": 1, "size": 3, "stride": 24,
    // "offset": 0}, "color": {...}}. scene=indexed adds the bytes each
    // storage needs, e.g. {"storage": "indexed", "vertex_bytes": 144,
    // "index_bytes": 48, "total_bytes": 192, "indexed": {...}, "flat": {...}}.
    nlohmann::json stats(const fw::ParamValues& p, const fw::Frame&) const override {
        nlohmann::json layout;
        glBindVertexArray(quads_.id());
        for (const auto& [name, location] :
             {std::pair<const char*, GLuint>{"position", A_POSITION}, {"color", A_COLOR}}) {
            GLint enabled = 0, size = 0, stride = 0;
            void* offset = nullptr;
            glGetVertexAttribiv(location, GL_VERTEX_ATTRIB_ARRAY_ENABLED, &enabled);
            glGetVertexAttribiv(location, GL_VERTEX_ATTRIB_ARRAY_SIZE, &size);
            glGetVertexAttribiv(location, GL_VERTEX_ATTRIB_ARRAY_STRIDE, &stride);
            glGetVertexAttribPointerv(location, GL_VERTEX_ATTRIB_ARRAY_POINTER, &offset);
            layout[name] = {{"enabled", enabled},
                            {"size", size},
                            {"stride", stride},
                            {"offset", reinterpret_cast<std::uintptr_t>(offset)}};
        }
        glBindVertexArray(0);
        if (p[kScene] != Scene::Indexed) return {{"layout", layout}};
        auto bytes = [](std::size_t vertex_bytes, std::size_t index_bytes) {
            return nlohmann::json{{"vertex_bytes", vertex_bytes},
                                  {"index_bytes", index_bytes},
                                  {"total_bytes", vertex_bytes + index_bytes}};
        };
        const nlohmann::json indexed = bytes(face_vbo_.size(), face_ibo_.size());
        const nlohmann::json flat = bytes(flat_vbo_.size(), 0);
        nlohmann::json out = p[kStorage] == Storage::Flat ? flat : indexed;
        out[kStorage.name] = p.text(kStorage.name);
        out["indexed"] = indexed;
        out["flat"] = flat;
        out["layout"] = layout;
        return out;
    }

    bool on_drag(fw::ParamValues& p, const fw::Frame&, double dx, double dy) override {
        if (p[kScene] != Scene::Culling) return false;
        p.number_ref(kYaw) = wrap_degrees(p[kYaw] + 0.5f * static_cast<float>(dx));
        p.number_ref(kPitch) = wrap_degrees(p[kPitch] + 0.5f * static_cast<float>(dy));
        return true;
    }

private:
    // scene=culling: the cube turned by yaw and pitch, seen in perspective.
    void draw_cube(const fw::ParamValues& p, const fw::Frame& frame) {
        const float aspect = static_cast<float>(frame.width) / static_cast<float>(frame.height);
        program_->set(kMvpUniform, cube_mvp(p[kYaw], p[kPitch], aspect));

        set_depth_test(p[kDepthTest]);
        set_culling(p[kCull]);
        glBindVertexArray(cube_.id());
        glDrawElements(GL_TRIANGLES, cube_index_count_, GL_UNSIGNED_INT, nullptr);
    }

    fw::Program* program_ = nullptr;
    fw::Buffer quad_vbo_, face_vbo_, face_ibo_, flat_vbo_, cube_vbo_, cube_ibo_;
    fw::VertexArray quads_, faces_, flat_, cube_;
    GLsizei face_vertex_count_ = 0, face_index_count_ = 0, cube_index_count_ = 0;
};

FW_LAB(PipelineLab)

}  // namespace pipeline
