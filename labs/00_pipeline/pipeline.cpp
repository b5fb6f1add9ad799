// Lab 0 `pipeline`: what the pipeline does to triangles (warm-up).
//
// Teaches: the depth test versus draw order; an indexed face set versus the
// flat vertex list it expands to; how primitive assembly reads one vertex list
// in seven modes; front faces, back faces and culling.
// Lecture: depth buffer and draw order, indexed face sets, primitive types
// (points, lines, strips, fans), face orientation and back-face culling.
// GL: glDrawArrays, glDrawElements, glEnable/glDisable, glDepthFunc,
// glFrontFace, glCullFace, gl_PointSize with GL_PROGRAM_POINT_SIZE.
// Student parts (marked TODO): set_depth_test()
// and set_culling() below, expand_indices() in meshes.cpp, and the
// pass-through in shaders/00_pipeline/pipeline.vert.
#include <glm/gtc/matrix_transform.hpp>
#include <string>
#include <vector>

#include "framework/gl.hpp"
#include "framework/lab.hpp"
#include "meshes.hpp"

namespace pipeline {

namespace {

// Vertex attribute locations, the same numbers as `layout(location = ...)`
// in shaders/00_pipeline/pipeline.vert: change both or neither.
constexpr GLuint kPositionLocation = 0;  // in vec3 a_position
constexpr GLuint kColorLocation = 1;     // in vec3 a_color
constexpr const char* kMvpUniform = "u_mvp";

// The values of `primitive`, in the order the parameter lists them.
struct PrimitiveMode {
    const char* name;
    GLenum mode;
};
constexpr PrimitiveMode kPrimitiveModes[] = {
    {"points", GL_POINTS},
    {"lines", GL_LINES},
    {"line_strip", GL_LINE_STRIP},
    {"line_loop", GL_LINE_LOOP},
    {"triangles", GL_TRIANGLES},
    {"triangle_strip", GL_TRIANGLE_STRIP},
    {"triangle_fan", GL_TRIANGLE_FAN},
};

// scene=culling's camera: on the +z axis looking at the cube's centre.
const glm::vec3 kEye{0.0f, 0.0f, 3.0f};
constexpr float kFovYDegrees = 45.0f, kNear = 0.1f, kFar = 100.0f;

// On: of the fragments that land on one pixel, the one with the smallest
// depth is kept (GL_LESS), whatever the draw order. Off: every fragment is
// written and the depth buffer is left alone, so the last one drawn wins.
void set_depth_test(bool on) {
    // BEGIN SOLUTION
    // STUDENT: (void)on;  // TODO: if on: glEnable(GL_DEPTH_TEST), glDepthFunc(GL_LESS); else off
    if (on) {
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
    } else {
        glDisable(GL_DEPTH_TEST);
    }
    // END SOLUTION
}

// `cull` is "none", "back" or "front". A triangle whose vertices run
// counter-clockwise on screen is a front face (the cube's faces are CCW seen
// from outside); "back" drops the faces turned away from the eye, "front" the
// faces turned towards it.
void set_culling(const std::string& cull) {
    // BEGIN SOLUTION
    // STUDENT: (void)cull;  // TODO: glFrontFace; unless "none", glEnable(GL_CULL_FACE), glCullFace
    glFrontFace(GL_CCW);
    if (cull == "none") {
        glDisable(GL_CULL_FACE);
    } else {
        glEnable(GL_CULL_FACE);
        glCullFace(cull == "front" ? GL_FRONT : GL_BACK);
    }
    // END SOLUTION
}

// Unit check `expand_quad` (checkpoints.json): the quad a b c d as the
// triangles (a, b, c) and (a, c, d), 4 vertices and 6 indices that
// expand_indices() turns into 6 positions; course compares them with its own.
std::vector<glm::vec3> expand_quad(glm::vec3 a, glm::vec3 b, glm::vec3 c, glm::vec3 d) {
    std::vector<Vertex> vertices;
    for (const glm::vec3& p : {a, b, c, d}) vertices.push_back({p, glm::vec3(0.0f)});
    std::vector<glm::vec3> positions;
    for (const Vertex& v : expand_indices(vertices, {0, 1, 2, 0, 2, 3}))
        positions.push_back(v.position);
    return positions;
}

float wrap_degrees(float a) {
    while (a > 180.0f) a -= 360.0f;
    while (a < -180.0f) a += 360.0f;
    return a;
}

}  // namespace

class PipelineLab : public fw::Lab {
public:
    static fw::LabInfo info() {
        std::vector<std::string> primitives;
        for (const PrimitiveMode& m : kPrimitiveModes) primitives.push_back(m.name);
        fw::LabInfo i;
        i.number = 0;
        i.id = "pipeline";
        i.dir = "00_pipeline";
        i.title = "What the pipeline does to triangles";
        i.params = {
            fw::Param::choice("scene", {"order", "indexed", "primitives", "culling"}, "order")
                .help("order: two quads and the depth test; indexed: an indexed face set; "
                      "primitives: 6 vertices in each primitive mode; culling: a cube")
                .key('S'),
            fw::Param::boolean("depth_test", true)
                .help("keep the nearest fragment (GL_LESS) instead of the last drawn (order, "
                      "culling)")
                .key('D'),
            fw::Param::choice("first", {"red", "blue"}, "red")
                .help("which quad is drawn first (order)")
                .key('F'),
            fw::Param::choice("storage", {"indexed", "flat"}, "indexed")
                .help("6 vertices + 12 indices, or the 12 vertices they expand to (indexed)")
                .key('I'),
            fw::Param::choice("primitive", primitives, "triangles")
                .help("how the 6 vertices are assembled (primitives)")
                .key('P'),
            fw::Param::choice("cull", {"none", "back", "front"}, "back")
                .help("which faces are culled; front faces are counter-clockwise (culling)")
                .key('C'),
            fw::Param::number("yaw", 30)
                .range(-180, 180)
                .step(15)
                .unit("deg")
                .help("cube rotation about the y axis, applied first (culling)")
                .key('Y'),
            fw::Param::number("pitch", 20)
                .range(-180, 180)
                .step(15)
                .unit("deg")
                .help("cube rotation about the x axis, applied after yaw (culling)")
                .key('X'),
        };
        i.controls = {"drag: rotate the cube (yaw, pitch) in scene culling"};
        i.functions = {fw::unit_function("expand_quad", &expand_quad)};
        return i;
    }

    void init(fw::ProgramLibrary& programs) override {
        program_ = &programs.load({"00_pipeline/pipeline.vert", "00_pipeline/pipeline.frag"});
        const fw::VertexLayout layout = fw::VertexLayout::of<Vertex>()
                                            .attr(kPositionLocation, &Vertex::position)
                                            .attr(kColorLocation, &Vertex::color);

        quad_vbo_ = fw::Buffer::from(order_quads(), GL_ARRAY_BUFFER, "order quads");
        quads_ = fw::VertexArray({&quad_vbo_, layout, nullptr, GL_UNSIGNED_INT, "order quads"});

        // The same 6 vertices serve scene=indexed (through the indices) and
        // scene=primitives (in their own order, without the indices).
        std::vector<Vertex> vertices = face_set_vertices();
        std::vector<GLuint> indices = face_set_indices();
        face_vbo_ = fw::Buffer::from(vertices, GL_ARRAY_BUFFER, "face set vertices");
        face_ibo_ = fw::Buffer::from(indices, GL_ELEMENT_ARRAY_BUFFER, "face set indices");
        faces_ = fw::VertexArray({&face_vbo_, layout, &face_ibo_, GL_UNSIGNED_INT, "face set"});
        flat_vbo_ =
            fw::Buffer::from(expand_indices(vertices, indices), GL_ARRAY_BUFFER, "face set, flat");
        flat_ = fw::VertexArray({&flat_vbo_, layout, nullptr, GL_UNSIGNED_INT, "face set, flat"});

        cube_vbo_ = fw::Buffer::from(cube_vertices(), GL_ARRAY_BUFFER, "cube vertices");
        cube_ibo_ = fw::Buffer::from(cube_indices(), GL_ELEMENT_ARRAY_BUFFER, "cube indices");
        cube_ = fw::VertexArray({&cube_vbo_, layout, &cube_ibo_, GL_UNSIGNED_INT, "cube"});
    }

    void draw(const fw::ParamValues& p, const fw::Frame& frame) override {
        // Each frame sets all the state it uses, whatever the last frame left.
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_CULL_FACE);
        glEnable(GL_PROGRAM_POINT_SIZE);
        program_->use();
        program_->set(kMvpUniform, glm::mat4(1.0f));

        const std::string& scene = p.choice("scene");
        if (scene == "order") {
            set_depth_test(p.flag("depth_test"));
            const bool red_first = p.choice("first") == "red";
            quads_.draw(GL_TRIANGLES, kQuadVertices, red_first ? kRedQuadFirst : kBlueQuadFirst);
            quads_.draw(GL_TRIANGLES, kQuadVertices, red_first ? kBlueQuadFirst : kRedQuadFirst);
        } else if (scene == "indexed") {
            if (p.choice("storage") == "indexed")
                faces_.draw_indexed(GL_TRIANGLES, static_cast<GLsizei>(faces_.index_count()));
            else
                flat_.draw(GL_TRIANGLES, static_cast<GLsizei>(flat_.vertex_count()));
        } else if (scene == "primitives") {
            const GLenum mode = kPrimitiveModes[p.choice_index("primitive")].mode;
            faces_.draw(mode, static_cast<GLsizei>(faces_.vertex_count()));
        } else {
            draw_cube(p, frame);
        }
    }

    // scene=indexed: the bytes each storage needs, e.g. {"storage": "indexed",
    // "vertex_bytes": 144, "index_bytes": 48, "total_bytes": 192, "indexed":
    // {...}, "flat": {...}}.
    nlohmann::json stats(const fw::ParamValues& p) const override {
        if (p.choice("scene") != "indexed") return nlohmann::json::object();
        auto bytes = [](std::size_t vertex_bytes, std::size_t index_bytes) {
            return nlohmann::json{{"vertex_bytes", vertex_bytes},
                                  {"index_bytes", index_bytes},
                                  {"total_bytes", vertex_bytes + index_bytes}};
        };
        const nlohmann::json indexed = bytes(face_vbo_.size(), face_ibo_.size());
        const nlohmann::json flat = bytes(flat_vbo_.size(), 0);
        nlohmann::json out = p.choice("storage") == "flat" ? flat : indexed;
        out["storage"] = p.choice("storage");
        out["indexed"] = indexed;
        out["flat"] = flat;
        return out;
    }

    bool on_drag(fw::ParamValues& p, double dx, double dy) override {
        if (p.choice("scene") != "culling") return false;
        p.number_ref("yaw") = wrap_degrees(p.number("yaw") + 0.5f * static_cast<float>(dx));
        p.number_ref("pitch") = wrap_degrees(p.number("pitch") + 0.5f * static_cast<float>(dy));
        return true;
    }

private:
    // scene=culling: P * V * M with M = rotateX(pitch) * rotateY(yaw).
    void draw_cube(const fw::ParamValues& p, const fw::Frame& frame) {
        const float aspect = static_cast<float>(frame.width) / static_cast<float>(frame.height);
        const glm::mat4 projection =
            glm::perspective(glm::radians(kFovYDegrees), aspect, kNear, kFar);
        const glm::mat4 view = glm::lookAt(kEye, glm::vec3(0.0f), glm::vec3(0.0f, 1.0f, 0.0f));
        glm::mat4 model = glm::rotate(glm::mat4(1.0f), glm::radians(p.number("pitch")), {1, 0, 0});
        model = glm::rotate(model, glm::radians(p.number("yaw")), {0, 1, 0});
        program_->set(kMvpUniform, projection * view * model);

        set_depth_test(p.flag("depth_test"));
        set_culling(p.choice("cull"));
        cube_.draw_indexed(GL_TRIANGLES, static_cast<GLsizei>(cube_.index_count()));
    }

    fw::Program* program_ = nullptr;
    fw::Buffer quad_vbo_, face_vbo_, face_ibo_, flat_vbo_, cube_vbo_, cube_ibo_;
    fw::VertexArray quads_, faces_, flat_, cube_;
};

FW_LAB(PipelineLab)

}  // namespace pipeline
