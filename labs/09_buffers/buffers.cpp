// Lab 9 `buffers`: what shaders write into buffers, and what they read from one.
//
// Teaches: transform feedback (a vertex shader's outputs captured into a
// buffer with the rasterizer off, buffers ping-ponged step after step, a
// geometry shader's triangles fed back as the next pass's input); a compute
// shader over a shader storage buffer, its work groups and memory barriers;
// a uniform block and the std140 rules that place its members.
// Lecture: the geometry stage's transform feedback (run the vertex or
// geometry shader without rasterization and keep what it writes; use those
// buffers as the input of the next draw); uniform blocks (std140); GL 4.3's
// compute stage.
// GL: glBindTransformFeedback, glBindBufferBase, glBeginTransformFeedback,
// glEndTransformFeedback, glDrawTransformFeedback, glEnable and glDisable of
// GL_RASTERIZER_DISCARD, the query GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN;
// glDispatchCompute, glMemoryBarrier, glGetProgramiv
// (GL_COMPUTE_WORK_GROUP_SIZE); glBindBufferRange for GL_SHADER_STORAGE_BUFFER
// and glBindBufferBase for GL_UNIFORM_BUFFER, glGetUniformIndices, glGetActiveUniformsiv
// (GL_UNIFORM_OFFSET), glGetActiveUniformBlockiv; glBindVertexArray with
// glDrawArrays and glDrawElements. The outputs transform feedback captures
// are named when a program is linked: the framework does it for
// programs.load(files, outputs).
// Student parts (marked TODO): advance_with_feedback() and
// advance_with_compute() in particles.cpp; std140_place() and pack_scene() in
// block.cpp; the step in shaders/09_buffers/advance.vert, the work-group size
// and the step in advance.comp, the four triangles in subdivide.geom.
#include <algorithm>
#include <cstddef>
#include <cstring>
#include <glm/gtc/matrix_transform.hpp>

#include "block.hpp"
#include "framework/gl.hpp"
#include "framework/lab.hpp"
#include "framework/trace/usage.hpp"
#include "parameters.hpp"
#include "particles.hpp"
#include "subdivide.hpp"
// A_POSITION, A_NORMAL, B_PARTICLES, B_SCENE: shared with the shaders.
#include "shared.glsl"

namespace buffers {

namespace {

constexpr const char* kDtUniform = "u_dt";  // advance.vert, advance.comp
constexpr const char* kGravityUniform = "u_gravity";
constexpr const char* kCountUniform = "u_count";            // advance.comp
constexpr const char* kProjectionUniform = "u_projection";  // points.vert
constexpr const char* kPointSizeUniform = "u_point_size";
constexpr const char* kColorUniform = "u_color";  // points.frag, flat.frag
constexpr const char* kMvpUniform = "u_mvp";      // mesh.vert
constexpr const char* kLightUniform = "u_light";  // flat.frag

// The particles' world, x and y in [-2, 2], seen straight along -z.
const glm::mat4 kParticleProjection = glm::ortho(-2.0f, 2.0f, -2.0f, 2.0f, -1.0f, 1.0f);
constexpr float kPointSize = 5.0f;
constexpr glm::vec3 kFeedbackColor{1.0f, 0.8f, 0.3f}, kComputeColor{0.3f, 0.8f, 1.0f};
// scene=block: the unit sphere squashed to 0.6 in y, turned by `angle` about
// y, seen along -z in the square [-1.25, 1.25]^2; light towards (1, 1, 1).
constexpr glm::vec3 kEllipsoidScale{1.0f, 0.6f, 1.0f};
constexpr float kBlockExtent = 1.25f, kAmbient = 0.2f;
constexpr glm::vec4 kBlockColor{0.9f, 0.5f, 0.2f, 1.0f};
const glm::vec3 kLight = glm::normalize(glm::vec3(1.0f));

}  // namespace

class BuffersLab : public fw::Lab {
public:
    static fw::LabInfo info() {
        fw::LabInfo i;
        i.title = "Buffers shaders write and read";
        i.aspect = 1.0;  // a square scene: letterboxed in a frame of another shape
        i.params = params();
        i.functions = {fw::unit_function("std140_place", &std140_place)};
        return i;
    }

    void init(fw::ProgramLibrary& programs) override {
        // File names within shaders/09_buffers/; the outputs transform feedback captures.
        step_ = &programs.load({"advance.vert"}, {"v_position", "v_velocity"});
        compute_ = &programs.load({"advance.comp"});
        points_ = &programs.load({"points.vert", "points.frag"});
        subdivide_ = &programs.load({"subdivide.vert", "subdivide.geom"}, {"g_position"});
        mesh_ = &programs.load({"mesh.vert", "flat.frag"});
        sphere_ = &programs.load({"sphere.vert", "sphere.frag"});
        feedback_ = make_feedback_pair();
        compute_particles_ = make_compute_particles();
        subdivision_ = make_subdivision_pair();
        written_ = fw::Query(GL_TRANSFORM_FEEDBACK_PRIMITIVES_WRITTEN, "primitives written");
        ellipsoid_ = make_ellipsoid();
    }

    void draw(const fw::ParamValues& p, const fw::Frame&) override {
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_CULL_FACE);
        scene_ = p[kScene];
        count_ = p[kCount];
        switch (scene_) {
            case Scene::Feedback: {
                feedback_.buffer[0].update(initial_particles(count_));
                step_->use();
                // Read only by the student's step: set once it is written.
                step_->set_if_active(kDtUniform, kDt);
                step_->set_if_active(kGravityUniform, kGravity);
                written_.begin();
                result_ = advance_with_feedback(feedback_, *step_, count_, p[kSteps]);
                written_.end();
                draw_points(feedback_.vertices[result_], kFeedbackColor);
                break;
            }
            case Scene::Compute:
                run_compute(p[kSteps]);
                draw_points(compute_particles_.vertices, kComputeColor);
                break;
            case Scene::Subdivide:
                draw_subdivided(p[kPasses]);
                break;
            case Scene::Block:
                draw_ellipsoid(p[kAngle]);
                break;
        }
    }

    nlohmann::json stats(const fw::ParamValues&, const fw::Frame&) const override {
        switch (scene_) {
            case Scene::Feedback:
            case Scene::Subdivide:
                return {{"primitives_written", written_.result()}};
            case Scene::Compute:
                return {{"work_groups", groups_}, {"work_group_size", work_group_size()}};
            case Scene::Block:
                return {{"block", block_layouts(*sphere_)}};
        }
        return nlohmann::json::object();
    }

    std::vector<fw::LabBuffer> buffers(const fw::ParamValues&, const fw::Frame&) const override {
        switch (scene_) {
            case Scene::Feedback:
                return {{"particles", 3,
                         positions_of(feedback_.buffer[result_].read_as<Particle>(), count_)}};
            case Scene::Compute:
                return {{"particles", 3,
                         positions_of(compute_particles_.buffer.read_as<GpuParticle>(), count_)}};
            case Scene::Subdivide: {
                const std::vector<std::uint8_t> bytes =
                    subdivision_.buffer[result_].read(0, vertices_ * sizeof(glm::vec3));
                std::vector<float> values(vertices_ * 3);
                std::memcpy(values.data(), bytes.data(), bytes.size());
                return {{"vertices", 3, values}};
            }
            case Scene::Block:
                break;
        }
        return {};
    }

private:
    void draw_points(const fw::VertexArray& vertices, glm::vec3 color) {
        glEnable(GL_PROGRAM_POINT_SIZE);
        points_->use();
        points_->set(kProjectionUniform, kParticleProjection);
        points_->set(kPointSizeUniform, kPointSize);
        points_->set(kColorUniform, color);
        glBindVertexArray(vertices.id());
        glDrawArrays(GL_POINTS, 0, count_);
    }

    void run_compute(int steps) {
        // The particles, then a guard of one work group that invocations
        // past u_count must leave as it is: the storage block ends after it
        // (glBindBufferRange), and the grader looks at it after each dispatch.
        const int guard = std::clamp(work_group_size(), 1, kMaxGuard);
        const std::vector<GpuParticle> start = make_guarded(initial_particles(count_), guard);
        compute_particles_.buffer.update(start);
        fw::gl_usage::guard(compute_particles_.buffer.id(), count_ * sizeof(GpuParticle),
                            guard * sizeof(GpuParticle), sizeof(GpuParticle), "the particles");
        compute_->use();
        // Read only by the student's step: set once it is written.
        compute_->set_if_active(kCountUniform, static_cast<unsigned>(count_));
        compute_->set_if_active(kDtUniform, kDt);
        compute_->set_if_active(kGravityUniform, kGravity);
        glBindBufferRange(GL_SHADER_STORAGE_BUFFER, B_PARTICLES, compute_particles_.buffer.id(), 0,
                          static_cast<GLsizeiptr>(start.size() * sizeof(GpuParticle)));
        groups_ = advance_with_compute(*compute_, count_, steps);
    }

    void draw_subdivided(int passes) {
        subdivision_.buffer[0].update(octahedron());
        written_.begin();
        result_ = subdivide(subdivision_, *subdivide_, passes);
        written_.end();
        vertices_ = 24;
        for (int k = 0; k < passes; ++k) vertices_ *= 4;
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        mesh_->use();
        mesh_->set(kMvpUniform, glm::perspective(glm::radians(45.0f), 1.0f, 0.1f, 10.0f) *
                                    glm::lookAt(glm::vec3(1.5f, 1.2f, 2.5f), glm::vec3(0.0f),
                                                glm::vec3(0.0f, 1.0f, 0.0f)));
        mesh_->set(kLightUniform, kLight);
        mesh_->set(kColorUniform, glm::vec3(0.4f, 0.7f, 0.9f));
        glBindVertexArray(subdivision_.vertices[result_].id());
        if (passes == 0)
            glDrawArrays(GL_TRIANGLES, 0, 24);
        else
            glDrawTransformFeedback(GL_TRIANGLES, subdivision_.capture[result_].id());
    }

    void draw_ellipsoid(float angle) {
        const glm::mat4 model = glm::rotate(glm::scale(glm::mat4(1.0f), kEllipsoidScale),
                                            glm::radians(angle), glm::vec3(0.0f, 1.0f, 0.0f));
        const glm::mat4 projection =
            glm::ortho(-kBlockExtent, kBlockExtent, -kBlockExtent, kBlockExtent, -2.0f, 2.0f);
        const glm::mat3 normal_matrix = glm::transpose(glm::inverse(glm::mat3(model)));
        const SceneBlock block =
            pack_scene(projection * model, normal_matrix, kLight, kAmbient, kBlockColor);
        ellipsoid_.block.update(0, &block, sizeof block);
        glBindBufferBase(GL_UNIFORM_BUFFER, B_SCENE, ellipsoid_.block.id());
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        sphere_->use();
        glBindVertexArray(ellipsoid_.vertices.id());
        glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(ellipsoid_.vertices.index_count()),
                       GL_UNSIGNED_INT, nullptr);
    }

    int work_group_size() const {
        GLint size[3] = {0, 0, 0};
        glGetProgramiv(compute_->id(), GL_COMPUTE_WORK_GROUP_SIZE, size);
        return size[0];
    }

    fw::Program *step_ = nullptr, *compute_ = nullptr, *points_ = nullptr;
    fw::Program *subdivide_ = nullptr, *mesh_ = nullptr, *sphere_ = nullptr;
    FeedbackPair feedback_;
    ComputeParticles compute_particles_;
    SubdivisionPair subdivision_;
    fw::Query written_;
    Ellipsoid ellipsoid_;
    // What the last draw did, for stats() and buffers().
    Scene scene_ = Scene::Feedback;
    int count_ = 0, result_ = 0, groups_ = 0;
    std::size_t vertices_ = 0;
};

FW_LAB(BuffersLab)

}  // namespace buffers
