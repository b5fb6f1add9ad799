// Lab 1 `transforms`: homogeneous coordinates and composition.
//
// Teaches: translation, scaling and rotation as 4x4 matrices acting on points
// with w = 1; Rodrigues' rotation about any axis; why the order of a product
// of transformations matters (T R S is not S R T).
// Lecture: homogeneous coordinates, the basic transformations, rotation about
// an arbitrary axis (Rodrigues), composition of transformations.
// GL: glBindVertexArray, glDrawArrays with a first vertex, glDisable; the
// matrices and the colour as uniforms (mat4, vec3), which the framework's
// fw::Program::set sends.
// Student parts (marked TODO): translate, scale,
// rotateX/Y/Z, rotate and compose in transforms_math.cpp.
#include <string>
#include <vector>

#include "framework/gl.hpp"
#include "framework/lab.hpp"
#include "transforms_math.hpp"
// A_POSITION: the attribute location, shared with transforms.vert.
#include "shared.glsl"

namespace transforms {

namespace {

constexpr const char* kProjectionUniform = "u_projection";
constexpr const char* kModelUniform = "u_model";
constexpr const char* kColorUniform = "u_color";

// The world is the square x, y in [-2, 2]; the projection P halves x and y
// so that it fills NDC [-1, 1]. (For z = 0 this is glm::ortho(-2, 2, -2, 2, -1, 1).)
constexpr float kWorldHalfSize = 2.0f;
// clang-format off
const glm::mat4 kProjection = from_rows(0.5f, 0,    0, 0,
                                        0,    0.5f, 0, 0,
                                        0,    0,    1, 0,
                                        0,    0,    0, 1);
// clang-format on

const glm::vec3 kGrey{0.25f, 0.25f, 0.25f}, kRed{1.0f, 0.0f, 0.0f}, kYellow{1.0f, 1.0f, 0.0f};
// The marker [0.25, 0.5]^2 is the red square's top-right corner.
const glm::vec2 kMarkerCentre{0.375f, 0.375f};

struct Vertex {
    glm::vec2 position;
};

// One vertex buffer: the square [-0.5, 0.5]^2 (vertices 0-5), then the
// marker [0.25, 0.5]^2 (vertices 6-11), two counter-clockwise triangles each.
constexpr GLint kSquareFirst = 0, kMarkerFirst = 6;
constexpr GLsizei kQuadVertices = 6;

void add_quad(std::vector<Vertex>& out, glm::vec2 lo, glm::vec2 hi) {
    const Vertex a{lo}, b{{hi.x, lo.y}}, c{hi}, d{{lo.x, hi.y}};
    out.insert(out.end(), {a, b, c, a, c, d});
}

std::vector<Vertex> squares() {
    std::vector<Vertex> v;
    add_quad(v, {-0.5f, -0.5f}, {0.5f, 0.5f});
    add_quad(v, {0.25f, 0.25f}, {0.5f, 0.5f});
    return v;
}

// The lab's parameters, each named once.
constexpr fw::ParamId<float> kTx{"tx"};
constexpr fw::ParamId<float> kTy{"ty"};
constexpr fw::ParamId<float> kAngle{"angle"};
constexpr fw::ParamId<float> kSx{"sx"};
constexpr fw::ParamId<float> kSy{"sy"};
constexpr fw::ParamId<Order> kOrder{"order"};

glm::mat4 model_of(const fw::ParamValues& p) {
    return model_matrix(p[kTx], p[kTy], p[kAngle], p[kSx], p[kSy], p[kOrder]);
}

}  // namespace

class TransformsLab : public fw::Lab {
public:
    static fw::LabInfo info() {
        fw::LabInfo i;
        i.title = "Homogeneous coordinates and composition";
        i.aspect = 1.0;  // a square scene: letterboxed in a frame of another shape
        auto coordinate = [](fw::ParamId<float> id, const char* h, int k) {
            return fw::Param::number(id, 0).range(-2, 2).step(0.25).unit("world").help(h).key(k);
        };
        auto factor = [](fw::ParamId<float> id, const char* h, int k) {
            return fw::Param::number(id, 1).range(-3, 3).step(0.25).help(h).key(k);
        };
        i.params = {
            coordinate(kTx, "translation T along x", 'X'),
            coordinate(kTy, "translation T along y", 'Y'),
            fw::Param::number(kAngle, 0)
                .range(-360, 360)
                .step(15)
                .unit("deg")
                .help("rotation R about z, counter-clockwise")
                .key('A'),
            factor(kSx, "scale S along x (negative mirrors)", 'U'),
            factor(kSy, "scale S along y (negative mirrors)", 'V'),
            fw::Param::choice(kOrder, Order::Trs)
                .help("M is the product of T, R and S in this order, left to right: trs is "
                      "M = T R S (S acts first)")
                .key('O'),
        };
        i.controls = {"drag: move the object (tx, ty)", "wheel: turn the object (angle)"};
        i.functions = {
            fw::unit_function("translate", &translate),  // mat4 (vec3 t)
            fw::unit_function("scale", &scale),          // mat4 (vec3 s)
            fw::unit_function("rotateX", &rotateX),      // mat4 (float degrees)
            fw::unit_function("rotateY", &rotateY),
            fw::unit_function("rotateZ", &rotateZ),
            fw::unit_function("rotate", &rotate),  // mat4 (float degrees, vec3 axis)
            // mat4 (tx, ty, angle, sx, sy, Order order): order by its name, "srt".
            fw::unit_function("compose", &model_matrix),
        };
        return i;
    }

    void init(fw::ProgramLibrary& programs) override {
        program_ = &programs.load({"transforms.vert", "transforms.frag"});
        vbo_ = fw::Buffer::from(squares(), GL_ARRAY_BUFFER, "square and marker");
        squares_ = fw::VertexArray(fw::VertexArrayDesc{
            .vertices = &vbo_,
            .layout = fw::VertexLayout::of<Vertex>().attr(A_POSITION, &Vertex::position),
            .label = "square and marker",
        });
    }

    void draw(const fw::ParamValues& p, const fw::Frame&) override {
        // Later draws cover earlier ones: the reference, then the object.
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_CULL_FACE);
        program_->use();
        program_->set(kProjectionUniform, kProjection);

        // Both squares live in the one vertex buffer: `first` says which.
        glBindVertexArray(squares_.id());
        program_->set(kModelUniform, glm::mat4(1.0f));
        program_->set(kColorUniform, kGrey);
        glDrawArrays(GL_TRIANGLES, kSquareFirst, kQuadVertices);

        program_->set(kModelUniform, model_of(p));
        program_->set(kColorUniform, kRed);
        glDrawArrays(GL_TRIANGLES, kSquareFirst, kQuadVertices);
        program_->set(kColorUniform, kYellow);
        glDrawArrays(GL_TRIANGLES, kMarkerFirst, kQuadVertices);
    }

    // M row by row and where it puts the marker's centre, e.g.
    // {"order": "trs", "model_rows": [[1,0,0,0], ...], "marker_centre": [0.375, 0.375]}.
    nlohmann::json stats(const fw::ParamValues& p, const fw::Frame&) const override {
        const glm::mat4 m = model_of(p);
        nlohmann::json rows = nlohmann::json::array();
        for (int r = 0; r < 4; ++r) rows.push_back({m[0][r], m[1][r], m[2][r], m[3][r]});
        const glm::vec4 centre = m * glm::vec4(kMarkerCentre, 0.0f, 1.0f);
        return {{kOrder.name, p.text(kOrder.name)},
                {"model_rows", rows},
                {"marker_centre", {centre.x, centre.y}}};
    }

    // Dragging moves the object with the mouse: a pixel is 4 / width world
    // units. Each parameter stays in its declared range.
    bool on_drag(fw::ParamValues& p, const fw::Frame& frame, double dx, double dy) override {
        const double world = 2.0 * kWorldHalfSize;
        p.set_clamped(kTx, p[kTx] + dx * world / frame.width);
        p.set_clamped(kTy, p[kTy] + dy * world / frame.height);
        return true;
    }

    bool on_scroll(fw::ParamValues& p, const fw::Frame&, double steps) override {
        p.set_clamped(kAngle, p[kAngle] + 15.0 * steps);
        return true;
    }

private:
    fw::Program* program_ = nullptr;
    fw::Buffer vbo_;
    fw::VertexArray squares_;
};

FW_LAB(TransformsLab)

}  // namespace transforms
