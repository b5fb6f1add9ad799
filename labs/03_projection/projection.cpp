// Lab 3 `projection`: camera, perspective and the depth buffer.
//
// Teaches: the view matrix from the camera's u, v, w basis; the perspective
// and orthographic matrices; the divide by w and the viewport mapping; why
// window depth is not linear in distance, and what a tiny near plane does to
// the depth buffer (z-fighting).
// Lecture: camera coordinates (lookAt), the view frustum, perspective and
// parallel projection, NDC, the viewport transform, the depth buffer.
// GL: the vertex shader's gl_Position, gl_FragCoord.z, glEnable(GL_DEPTH_TEST)
// with glDepthFunc, glDisable(GL_CULL_FACE), glBindVertexArray, glDrawArrays.
// Student parts (marked TODO): lookAt(),
// perspective(), orthographic(), perspective01() and viewport() in
// camera_math.cpp, and the transform in shaders/03_projection/projection.vert.
#include <algorithm>
#include <cmath>
#include <glm/gtc/matrix_transform.hpp>
#include <string>
#include <vector>

#include "camera_math.hpp"
#include "framework/gl.hpp"
#include "framework/lab.hpp"
#include "scene.hpp"
// A_POSITION: the attribute location, shared with projection.vert.
#include "shared.glsl"

namespace projection {

namespace {

// The choices of `scene`, `show` and `mode`.
constexpr fw::Choice<Scene> kScenes[] = {{Scene::Cards, "cards"}, {Scene::ZFight, "zfight"}};
enum class Show { Color, Depth };
constexpr fw::Choice<Show> kShows[] = {{Show::Color, "color"}, {Show::Depth, "depth"}};
enum class Mode { Perspective, Orthographic };
constexpr fw::Choice<Mode> kModes[] = {{Mode::Perspective, "perspective"},
                                       {Mode::Orthographic, "orthographic"}};

// The lab's parameters, each named once. A point is three of them, x, y, z.
struct PointParam {
    fw::ParamId<float> x, y, z;
};
constexpr fw::ParamId<Scene> kScene{"scene"};
constexpr fw::ParamId<Show> kShow{"show"};
constexpr fw::ParamId<Mode> kMode{"mode"};
constexpr fw::ParamId<float> kFov{"fov"};
constexpr fw::ParamId<float> kNear{"near"};
constexpr fw::ParamId<float> kFar{"far"};
constexpr fw::ParamId<float> kOrthoSize{"ortho_size"};
constexpr PointParam kEye{{"eye_x"}, {"eye_y"}, {"eye_z"}};
constexpr PointParam kTarget{{"target_x"}, {"target_y"}, {"target_z"}};

// Uniforms of projection.vert (the matrices) and projection.frag.
constexpr const char* kModelUniform = "u_model";
constexpr const char* kViewUniform = "u_view";
constexpr const char* kProjectionUniform = "u_projection";
constexpr const char* kColorUniform = "u_color";
constexpr const char* kShowDepthUniform = "u_show_depth";
constexpr const char* kOrthographicUniform = "u_orthographic";
constexpr const char* kNearUniform = "u_near";
constexpr const char* kFarUniform = "u_far";

const glm::vec3 kUp{0.0f, 1.0f, 0.0f};

glm::vec3 vec3_param(const fw::ParamValues& p, const PointParam& point) {
    return {p[point.x], p[point.y], p[point.z]};
}

// V = lookAt(eye, target, (0, 1, 0)).
glm::mat4 view_matrix(const fw::ParamValues& p) {
    return lookAt(vec3_param(p, kEye), vec3_param(p, kTarget), kUp);
}

// P: perspective(fov, W/H, near, far), or orthographic with the half-height
// s = ortho_size and the half-width s * W/H, so that squares stay square.
glm::mat4 projection_matrix(const fw::ParamValues& p, float aspect) {
    const float n = p[kNear], f = p[kFar];
    if (p[kMode] == Mode::Orthographic) {
        const float s = p[kOrthoSize];
        return orthographic(-s * aspect, s * aspect, -s, s, n, f);
    }
    return perspective(p[kFov], aspect, n, f);
}

fw::Param coordinate(fw::ParamId<float> id, double def, const std::string& what, int key) {
    return fw::Param::number(id, def).range(-50, 50).step(0.5).help(what).key(key);
}

}  // namespace

class ProjectionLab : public fw::Lab {
public:
    static fw::LabInfo info() {
        fw::LabInfo i;
        i.title = "Camera, perspective and the depth buffer";
        i.params = {
            fw::Param::choice(kScene, kScenes, Scene::Cards)
                .help("cards: five squares at distances 2 to 32; zfight: two tilted quads "
                      "0.002 apart, 20 units away")
                .key('S'),
            fw::Param::choice(kShow, kShows, Show::Color)
                .help("each square's colour, or its linearised depth as grey (near black, "
                      "far white)")
                .key('D'),
            fw::Param::choice(kMode, kModes, Mode::Perspective)
                .help("perspective(fov, W/H, near, far) or orthographic(-s W/H, s W/H, -s, s, "
                      "near, far), s = ortho_size")
                .key('M'),
            fw::Param::number(kFov, 60)
                .range(10, 150)
                .step(5)
                .unit("deg")
                .help("vertical field of view (perspective)")
                .key('V'),
            fw::Param::number(kNear, 1)
                .range(0.0001, 10)
                .step(0.25)
                .help("distance of the near plane; must be less than far")
                .key('N'),
            fw::Param::number(kFar, 50)
                .range(0.1, 1000)
                .step(10)
                .help("distance of the far plane; must exceed near")
                .key('F'),
            fw::Param::number(kOrthoSize, 2)
                .range(0.1, 50)
                .step(0.5)
                .help("half the height of the orthographic view volume (orthographic)")
                .key('O'),
            coordinate(kEye.x, 0, "eye position, x (world)", 'X'),
            coordinate(kEye.y, 0, "eye position, y (world)", 'Y'),
            coordinate(kEye.z, 0, "eye position, z (world)", 'Z'),
            coordinate(kTarget.x, 0, "point the eye looks at, x (world)", 'J'),
            coordinate(kTarget.y, 0, "point the eye looks at, y (world)", 'K'),
            coordinate(kTarget.z, -1, "point the eye looks at, z (world)", 'L'),
        };
        i.controls = {"drag: orbit the eye around the target at the same distance",
                      "wheel: field of view (fov)"};
        i.functions = {
            fw::unit_function("lookAt", &lookAt),
            fw::unit_function("perspective", &perspective),
            fw::unit_function("orthographic", &orthographic),
            fw::unit_function("perspective01", &perspective01),
            fw::unit_function("viewport", &viewport),
        };
        return i;
    }

    void init(fw::ProgramLibrary& programs) override {
        program_ = &programs.load({"projection.vert", "projection.frag"});
        square_vbo_ = fw::Buffer::from(unit_square(), GL_ARRAY_BUFFER, "unit square");
        square_ = fw::VertexArray(fw::VertexArrayDesc{
            .vertices = &square_vbo_,
            .layout = fw::VertexLayout::of<Vertex>().attr(A_POSITION, &Vertex::position),
            .label = "unit square",
        });
    }

    void draw(const fw::ParamValues& p, const fw::Frame& frame) override {
        const float aspect = static_cast<float>(frame.width) / static_cast<float>(frame.height);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glDisable(GL_CULL_FACE);

        program_->use();
        program_->set(kViewUniform, view_matrix(p));
        program_->set(kProjectionUniform, projection_matrix(p, aspect));
        program_->set(kShowDepthUniform, p[kShow] == Show::Depth);
        program_->set(kOrthographicUniform, p[kMode] == Mode::Orthographic);
        program_->set(kNearUniform, p[kNear]);
        program_->set(kFarUniform, p[kFar]);
        // Every object is the same square, placed by its own model matrix.
        glBindVertexArray(square_.id());
        for (const Object& object : scene_objects(p[kScene])) {
            program_->set(kModelUniform, object.model);
            program_->set(kColorUniform, object.color);
            glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(square_.vertex_count()));
        }
    }

    // Where each square's centre went, through your matrices and viewport():
    // {"centres": [{"object": "red", "clip": [x, y, z, w], "window": [x, y, depth]}, ...]}.
    // Compare "window" with the PNG (pixels) and the --depth-out PFM (depth).
    nlohmann::json stats(const fw::ParamValues& p, const fw::Frame& frame) const override {
        const float aspect = static_cast<float>(frame.width) / static_cast<float>(frame.height);
        const glm::mat4 clip_from_world = projection_matrix(p, aspect) * view_matrix(p);
        nlohmann::json centres = nlohmann::json::array();
        for (const Object& object : scene_objects(p[kScene])) {
            const glm::vec4 clip = clip_from_world * object.model * glm::vec4(0, 0, 0, 1);
            const glm::vec3 window = viewport(glm::vec3(clip) / clip.w, frame.width, frame.height);
            centres.push_back({{"object", object.name},
                               {"clip", {clip.x, clip.y, clip.z, clip.w}},
                               {"window", {window.x, window.y, window.z}}});
        }
        return {{"centres", centres}};
    }

    // far > near, and a camera that lookAt can build: the eye away from the
    // target, and a view direction that is not parallel to up (0, 1, 0).
    std::string validate(const fw::ParamValues& p) const override {
        if (!(p[kFar] > p[kNear]))
            return "far (" + p.text(kFar.name) + ") must exceed near (" + p.text(kNear.name) +
                   "); raise far or lower near";
        const glm::vec3 view = vec3_param(p, kTarget) - vec3_param(p, kEye);
        if (glm::length(view) == 0.0f)
            return "the eye (eye_x/y/z) is at the target (target_x/y/z), so lookAt has no "
                   "view direction; move one of them";
        if (glm::length(glm::cross(view, kUp)) <= 1e-6f * glm::length(view))
            return "the view direction, target - eye, is parallel to up (0, 1, 0), so lookAt "
                   "has no right axis u; move eye_x/eye_z or target_x/target_z";
        return {};
    }

    // Orbit: the eye turns about the target on a sphere of the same radius.
    // Dragging right turns the scene right (the eye moves left); the
    // elevation stops short of the poles, where the view would be parallel
    // to up.
    bool on_drag(fw::ParamValues& p, const fw::Frame&, double dx, double dy) override {
        const glm::dvec3 target = vec3_param(p, kTarget);
        const glm::dvec3 offset = glm::dvec3(vec3_param(p, kEye)) - target;
        const double r = glm::length(offset);
        if (r == 0.0) return false;
        const double yaw = std::atan2(offset.x, offset.z) - 0.01 * dx;
        const double pitch = std::clamp(std::asin(offset.y / r) - 0.01 * dy, -1.5, 1.5);
        const glm::dvec3 eye =
            target + r * glm::dvec3(std::cos(pitch) * std::sin(yaw), std::sin(pitch),
                                    std::cos(pitch) * std::cos(yaw));
        p.set_clamped(kEye.x, eye.x);
        p.set_clamped(kEye.y, eye.y);
        p.set_clamped(kEye.z, eye.z);
        return true;
    }

    // The wheel zooms: up narrows the field of view by 5 degrees a step.
    bool on_scroll(fw::ParamValues& p, const fw::Frame&, double steps) override {
        p.set_clamped(kFov, p[kFov] - 5.0 * steps);
        return true;
    }

private:
    fw::Program* program_ = nullptr;
    fw::Buffer square_vbo_;
    fw::VertexArray square_;
};

FW_LAB(ProjectionLab)

}  // namespace projection
