// Lab 12 `shadows`: shadows and fog.
//
// Teaches: planar projected shadows (an object flattened onto the ground by
// the shadow matrix of a point or a directional light, drawn dark and
// blended), the stencil buffer that darkens each pixel once; fog per
// fragment (linear, exponential, exponential squared) from the eye-space
// distance; a shadow map (depth from the light into a depth-only
// framebuffer, then the comparison in the fragment shader), its acne, peter
// panning and percentage-closer filtering.
// Lecture: the object model's shadow shader (the object drawn flattened and
// black with its own MVP), the shadows cast by objects on each other,
// atmospheric effects such as fog, the stencil and depth tests, blending.
// GL: glBlendFunc, glStencilFunc, glStencilOp, glStencilMask, glGenFramebuffers,
// glFramebufferTexture2D with GL_DEPTH_ATTACHMENT, glDrawBuffer(GL_NONE),
// glTexParameteri with GL_TEXTURE_COMPARE_MODE and GL_TEXTURE_COMPARE_FUNC,
// sampler2DShadow, glViewport, glBindVertexArray with glDrawArrays.
// Student parts (marked TODO): shadow_matrix() and fog_factor() in
// shadow_math.cpp; set_shadow_stencil(), attach_depth() and
// set_shadow_compare() in shadow_state.cpp; the fog factor in
// shaders/12_shadows/fog.frag and the shadow lookup in shadowmap.frag.
#include <string>

#include "framework/gl.hpp"
#include "framework/lab.hpp"
#include "parameters.hpp"
#include "scenes.hpp"
#include "shadow_math.hpp"
#include "shadow_state.hpp"
// A_POSITION (the attribute location), shared with the shaders.
#include "shared.glsl"

namespace shadows {

namespace {

constexpr const char* kModelUniform = "u_model";  // scene.vert
constexpr const char* kViewUniform = "u_view";
constexpr const char* kProjectionUniform = "u_projection";
constexpr const char* kLightViewProjUniform = "u_light_view_proj";
constexpr const char* kColorUniform = "u_color";         // every fragment shader but depth.frag
constexpr const char* kFogColorUniform = "u_fog_color";  // fog.frag
constexpr const char* kFogModeUniform = "u_fog_mode";
constexpr const char* kFogStartUniform = "u_fog_start";
constexpr const char* kFogEndUniform = "u_fog_end";
constexpr const char* kFogDensityUniform = "u_fog_density";
constexpr const char* kShadowMapUniform = "u_shadow_map";  // shadowmap.frag
constexpr const char* kBiasUniform = "u_bias";

// Triangles in a vertex buffer and the vertex array reading it.
struct GpuMesh {
    fw::Buffer vbo;
    fw::VertexArray vao;
};

GpuMesh upload(const Mesh& mesh, const std::string& label) {
    GpuMesh g;
    g.vbo = fw::Buffer::from(mesh, GL_ARRAY_BUFFER, label + " vertices");
    g.vao = fw::VertexArray(fw::VertexArrayDesc{
        .vertices = &g.vbo,
        .layout = fw::VertexLayout::of<Vertex>().attr(A_POSITION, &Vertex::position),
        .label = label});
    return g;
}

void draw_mesh(const GpuMesh& mesh) {
    glBindVertexArray(mesh.vao.id());
    glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(mesh.vao.vertex_count()));
}

// The frame's framebuffers and viewport, put back after a pass elsewhere.
struct FrameTarget {
    GLint draw = 0, read = 0, viewport[4] = {0, 0, 0, 0};
    FrameTarget() {
        glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &draw);
        glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &read);
        glGetIntegerv(GL_VIEWPORT, viewport);
    }
    void restore() const {
        glBindFramebuffer(GL_DRAW_FRAMEBUFFER, static_cast<GLuint>(draw));
        glBindFramebuffer(GL_READ_FRAMEBUFFER, static_cast<GLuint>(read));
        glViewport(viewport[0], viewport[1], viewport[2], viewport[3]);
    }
};

}  // namespace

class ShadowsLab : public fw::Lab {
public:
    static fw::LabInfo info() {
        fw::LabInfo i;
        i.title = "Shadows and fog";
        i.aspect = 1.0;  // a square scene: letterboxed in a frame of another shape
        i.params = params();
        i.functions = {fw::unit_function("shadow_matrix", &shadow_matrix),
                       fw::unit_function("fog_factor", &fog_factor)};
        return i;
    }

    void init(fw::ProgramLibrary& programs) override {
        // File names within shaders/12_shadows/.
        solid_ = &programs.load({"scene.vert", "solid.frag"});
        fog_ = &programs.load({"scene.vert", "fog.frag"});
        depth_ = &programs.load({"scene.vert", "depth.frag"});
        lit_ = &programs.load({"scene.vert", "shadowmap.frag"});
        ground_ = upload(ground(), "ground");
        caster_a_ = upload(caster_a(), "caster A");
        caster_b_ = upload(caster_b(), "caster B");
        fog_planes_ = upload(fog_planes(), "fog planes");
        wall_ = upload(wall(), "wall");
        fw::Texture2DDesc desc;
        desc.width = desc.height = kShadowMapSize;
        desc.internal_format = GL_DEPTH_COMPONENT32F;
        desc.min_filter = desc.mag_filter = GL_NEAREST;
        desc.label = "shadow map";
        shadow_map_ = fw::Texture2D(desc);
        GLuint id = 0;
        glGenFramebuffers(1, &id);
        shadow_fbo_ = fw::detail::Handle(id, [](GLuint n) { glDeleteFramebuffers(1, &n); });
        const FrameTarget frame;
        attach_depth(id, shadow_map_);
        shadow_fbo_complete_ = glCheckFramebufferStatus(GL_FRAMEBUFFER) == GL_FRAMEBUFFER_COMPLETE;
        frame.restore();
    }

    void draw(const fw::ParamValues& p, const fw::Frame&) override {
        glDisable(GL_CULL_FACE);
        glDisable(GL_DEPTH_TEST);
        switch (p[kScene]) {
            case Scene::Planar:
                draw_planar(p);
                break;
            case Scene::Fog:
                draw_fog(p);
                break;
            case Scene::Shadowmap:
                draw_shadow_map(p);
                break;
        }
    }

private:
    void use(const fw::Program& program, const glm::mat4& view, const glm::mat4& projection) {
        program.use();
        program.set(kModelUniform, glm::mat4(1.0f));
        program.set(kViewUniform, view);
        program.set(kProjectionUniform, projection);
        program.set_if_active(kLightViewProjUniform, light_view_projection());
    }

    // The ground, the shadow (both casters flattened, black, blended, through
    // the stencil), then the casters: no depth test, drawn in this order.
    void draw_planar(const fw::ParamValues& p) {
        use(*solid_, top_view(), top_projection());
        solid_->set(kColorUniform, kGroundColor);
        draw_mesh(ground_);

        const glm::vec4 light = p[kLight] == Light::Point ? kPointLight : kDirectionalLight;
        solid_->set(kModelUniform, shadow_matrix(light));
        solid_->set(kColorUniform, glm::vec4(0.0f, 0.0f, 0.0f, p[kShadowAlpha]));
        glEnable(GL_BLEND);
        glBlendEquation(GL_FUNC_ADD);
        glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);  // the frame stays opaque
        set_shadow_stencil(p[kStencil]);
        draw_mesh(caster_a_);
        draw_mesh(caster_b_);
        glDisable(GL_STENCIL_TEST);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
        glDisable(GL_BLEND);

        solid_->set(kModelUniform, glm::mat4(1.0f));
        solid_->set(kColorUniform, kCasterAColor);
        draw_mesh(caster_a_);
        solid_->set(kColorUniform, kCasterBColor);
        draw_mesh(caster_b_);
    }

    void draw_fog(const fw::ParamValues& p) {
        use(*fog_, glm::mat4(1.0f), fog_projection());
        fog_->set(kColorUniform, kSurfaceColor);
        // Unused, and dropped, until the student's fog is written.
        fog_->set_if_active(kFogColorUniform, kFogColor);
        fog_->set_if_active(kFogModeUniform, static_cast<int>(p[kFog]));
        fog_->set_if_active(kFogStartUniform, p[kFogStart]);
        fog_->set_if_active(kFogEndUniform, p[kFogEnd]);
        fog_->set_if_active(kFogDensityUniform, p[kFogDensity]);
        draw_mesh(fog_planes_);
    }

    // Pass 1: the ground and the wall from the light, depth only. Pass 2: the
    // ground from above, each fragment compared with the map.
    void draw_shadow_map(const fw::ParamValues& p) {
        if (shadow_fbo_complete_) {
            const FrameTarget frame;
            glBindFramebuffer(GL_FRAMEBUFFER, shadow_fbo_.get());
            glViewport(0, 0, kShadowMapSize, kShadowMapSize);
            glEnable(GL_DEPTH_TEST);
            glDepthFunc(GL_LESS);
            glClear(GL_DEPTH_BUFFER_BIT);
            const glm::mat4 light = light_view_projection();
            use(*depth_, glm::mat4(1.0f), light);
            draw_mesh(ground_);
            draw_mesh(wall_);
            glDisable(GL_DEPTH_TEST);
            frame.restore();
        }
        use(*lit_, top_view(), top_projection());
        glActiveTexture(GL_TEXTURE0);
        glBindTexture(GL_TEXTURE_2D, shadow_map_.id());
        set_shadow_compare(p[kPcf]);
        lit_->set(kColorUniform, kGroundColor);
        // Unused, and dropped, until the student's lookup is written.
        lit_->set_if_active(kShadowMapUniform, 0);
        lit_->set_if_active(kBiasUniform, p[kBias]);
        draw_mesh(ground_);
    }

    fw::Program* solid_ = nullptr;
    fw::Program* fog_ = nullptr;
    fw::Program* depth_ = nullptr;
    fw::Program* lit_ = nullptr;
    GpuMesh ground_, caster_a_, caster_b_, fog_planes_, wall_;
    fw::Texture2D shadow_map_;
    fw::detail::Handle shadow_fbo_;
    bool shadow_fbo_complete_ = false;
};

FW_LAB(ShadowsLab)

}  // namespace shadows
