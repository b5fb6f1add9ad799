// Lab 2 `robot-arm`: the hierarchy S, J = S T, H = J R.
//
// Teaches: hierarchical modelling. Each part is designed once at the origin
// and placed by a product of matrices that starts with its parent's, so a
// turn at the shoulder carries the hand and the fingers along.
// Lecture: the robot arm of the transformations deck (S := S N, J = S T,
// H = J R), composition order, local versus world frames.
// GL: one vertex buffer holding every part, glBindVertexArray and
// glDrawArrays with a first vertex, glDisable; a mat4 and a vec3 uniform per
// draw, which the framework's fw::Program::set sends; orthographic projection.
// Student part (marked TODO): arm_matrices() in
// arm.cpp.
#include <cmath>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <string>
#include <vector>

#include "arm.hpp"
#include "framework/error.hpp"
#include "framework/gl.hpp"
#include "framework/json_glm.hpp"
#include "framework/lab.hpp"
// A_POSITION: the attribute location, shared with arm.vert.
#include "shared.glsl"

namespace robot_arm {

namespace {

constexpr const char* kMvpUniform = "u_mvp";
constexpr const char* kColorUniform = "u_color";

struct Vertex {
    glm::vec2 position;
};

// One part as designed at the origin: `count` vertices from `first` in the
// shared vertex buffer, drawn as `mode`.
struct Part {
    GLint first = 0;
    GLsizei count = 0;
    GLenum mode = GL_TRIANGLES;
    glm::vec3 color{0.0f};
};

// World x, y in [-3, 3] fill the frame (orthographic; z is unused).
const glm::mat4 kProjection = glm::ortho(-3.0f, 3.0f, -3.0f, 3.0f, -1.0f, 1.0f);

// The base under the shoulder: a grey disc of radius 0.3 around the shoulder
// point (-1.5, -1.5), a fan of 32 triangles, drawn before the arm.
constexpr float kBaseRadius = 0.3f;
constexpr int kBaseSegments = 32;
const glm::vec3 kBaseColor{0.4f, 0.4f, 0.4f};

// The box [x0, x1] x [y0, y1] as two counter-clockwise triangles.
Part add_box(std::vector<Vertex>& out, float x0, float x1, float y0, float y1, glm::vec3 color) {
    const Part part{static_cast<GLint>(out.size()), 6, GL_TRIANGLES, color};
    const glm::vec2 a{x0, y0}, b{x1, y0}, c{x1, y1}, d{x0, y1};
    for (glm::vec2 p : {a, b, c, a, c, d}) out.push_back({p});
    return part;
}

Part add_disc(std::vector<Vertex>& out, float radius, int segments, glm::vec3 color) {
    const Part part{static_cast<GLint>(out.size()), segments + 2, GL_TRIANGLE_FAN, color};
    out.push_back({{0.0f, 0.0f}});
    for (int i = 0; i <= segments; ++i) {
        const float a = 2.0f * glm::pi<float>() * float(i) / float(segments);
        out.push_back({radius * glm::vec2(std::cos(a), std::sin(a))});
    }
    return part;
}

// The lab's parameters, the joint angles in degrees, each named once.
constexpr fw::ParamId<float> kShoulder{"shoulder"};
constexpr fw::ParamId<float> kHand{"hand"};
constexpr fw::ParamId<float> kGrip{"grip"};

// The joint angles of `p`, through the student's hierarchy.
ArmMatrices pose(const fw::ParamValues& p) {
    return arm_matrices(p[kShoulder], p[kHand], p[kGrip]);
}

glm::vec2 place(const glm::mat4& m, float x, float y) {
    return glm::vec2(m * glm::vec4(x, y, 0.0f, 1.0f));
}

}  // namespace

class RobotArmLab : public fw::Lab {
public:
    static fw::LabInfo info() {
        fw::LabInfo i;
        i.title = "The hierarchy S, J = S T, H = J R";
        i.aspect = 1.0;  // a square scene: letterboxed in a frame of another shape
        i.params = {
            fw::Param::number(kShoulder, 30)
                .range(-180, 180)
                .step(15)
                .unit("deg")
                .help("the arm's turn about the shoulder (-1.5, -1.5): "
                      "S = translate(-1.5, -1.5) * rotateZ(shoulder)")
                .key('S'),
            fw::Param::number(kHand, -45)
                .range(-150, 150)
                .step(15)
                .unit("deg")
                .help("the hand's turn about the elbow, relative to the arm: R = rotateZ(hand)")
                .key('H'),
            fw::Param::number(kGrip, 20)
                .range(0, 90)
                .step(10)
                .unit("deg")
                .help("how far each finger opens away from the other: rotateZ(+grip), "
                      "rotateZ(-grip)")
                .key('G'),
        };
        i.controls = {"drag left/right: turn the shoulder", "drag up/down: turn the hand",
                      "wheel: open or close the grip"};
        i.functions = {fw::unit_function("arm_matrices", &arm_matrices)};
        return i;
    }

    void init(fw::ProgramLibrary& programs) override {
        program_ = &programs.load({"arm.vert", "arm.frag"});
        // Every part designed at the origin, pointing along +x (README.md).
        std::vector<Vertex> v;
        base_ = add_disc(v, kBaseRadius, kBaseSegments, kBaseColor);
        arm_ = add_box(v, 0.0f, 2.0f, -0.2f, 0.2f, {0.2f, 0.4f, 1.0f});
        hand_ = add_box(v, 0.0f, 1.0f, -0.15f, 0.15f, {0.2f, 0.9f, 0.3f});
        finger_ = add_box(v, 0.0f, 0.6f, -0.05f, 0.05f, {1.0f, 0.6f, 0.1f});
        vbo_ = fw::Buffer::from(v, GL_ARRAY_BUFFER, "robot arm parts");
        parts_ = fw::VertexArray(fw::VertexArrayDesc{
            .vertices = &vbo_,
            .layout = fw::VertexLayout::of<Vertex>().attr(A_POSITION, &Vertex::position),
            .label = "robot arm parts",
        });
    }

    void draw(const fw::ParamValues& p, const fw::Frame&) override {
        // Depth test off: each part covers what was drawn before it.
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_CULL_FACE);
        program_->use();
        const ArmMatrices m = pose(p);
        draw_part(base_, translate(-1.5f, -1.5f));
        draw_part(arm_, m.S);
        draw_part(hand_, m.H);
        draw_part(finger_, m.upper_finger);
        draw_part(finger_, m.lower_finger);
    }

    // Where the joints land in the world, to check against pencil and paper:
    // the elbow J * (0, 0), the fingers' root H * (1, 0), each finger's tip
    // F * (0.6, 0).
    nlohmann::json stats(const fw::ParamValues& p, const fw::Frame&) const override {
        const ArmMatrices m = pose(p);
        auto json = [](glm::vec2 v) { return fw::to_json_value(v); };
        return {{"shoulder", json(place(m.S, 0.0f, 0.0f))},
                {"elbow", json(place(m.J, 0.0f, 0.0f))},
                {"finger_root", json(place(m.H, 1.0f, 0.0f))},
                {"upper_tip", json(place(m.upper_finger, 0.6f, 0.0f))},
                {"lower_tip", json(place(m.lower_finger, 0.6f, 0.0f))}};
    }

    bool on_drag(fw::ParamValues& p, const fw::Frame&, double dx, double dy) override {
        // Half a degree per pixel; the shoulder turns round and round, the
        // hand stops at the ends of its range.
        p.number_ref(kShoulder) = std::remainder(p[kShoulder] + 0.5 * dx, 360.0);
        p.set_clamped(kHand, p[kHand] + 0.5 * dy);
        return true;
    }

    bool on_scroll(fw::ParamValues& p, const fw::Frame&, double steps) override {
        p.set_clamped(kGrip, p[kGrip] + 5.0 * steps);
        return true;
    }

private:
    void draw_part(const Part& part, const glm::mat4& model) {
        program_->set(kMvpUniform, kProjection * model);
        program_->set(kColorUniform, part.color);
        // Every part lives in the one vertex buffer: `first` says where.
        glBindVertexArray(parts_.id());
        glDrawArrays(part.mode, part.first, part.count);
    }

    fw::Program* program_ = nullptr;
    fw::Buffer vbo_;
    fw::VertexArray parts_;
    Part base_, arm_, hand_, finger_;
};

FW_LAB(RobotArmLab)

}  // namespace robot_arm
