// Lab 7 `framebuffer-ops`: what happens to a fragment after the fragment shader.
//
// Teaches: the blend equation and its common modes (over, additive, multiply,
// premultiplied alpha) and why "over" depends on the draw order; translucent
// objects with the depth test: depth writes off, drawn back to front;
// discarded fragments write no depth (alpha-tested cut-outs); the stencil
// test as a mask and an outline; front and back faces, primitive ids and
// window coordinates in the fragment shader; the scissor test.
// Lecture: the blending stage, the per-fragment tests (alpha, stencil,
// depth), frame buffer operations, the fragment shader's inputs.
// GL: glEnable/glDisable (GL_BLEND, GL_DEPTH_TEST, GL_STENCIL_TEST,
// GL_SCISSOR_TEST, GL_CULL_FACE), glBlendFunc, glBlendEquation, glDepthMask,
// glDepthFunc, glColorMask, glStencilFunc, glStencilOp, glStencilMask,
// glScissor, glClearColor, glClear, glCullFace, glFrontFace,
// glBindVertexArray with glDrawElements (the squares and the box) and
// glDrawArrays (the discs); GLSL discard, gl_FrontFacing, gl_PrimitiveID,
// gl_FragCoord.
// Student parts (marked TODO): set_blend_mode(), set_depth_writes(),
// mark_stencil(), draw_where_marked(), draw_where_unmarked() and
// scissor_to() in fragment_state.cpp; blend() and back_to_front() in
// blending.cpp; the discard in shaders/07_framebuffer_ops/cutout.frag and
// the patterns in faces.frag.
#include <glm/glm.hpp>
#include <string>
#include <vector>

#include "blending.hpp"
#include "fragment_state.hpp"
#include "framework/gl.hpp"
#include "framework/lab.hpp"
#include "parameters.hpp"
#include "scenes.hpp"
// A_POSITION, A_UV (attribute locations) and the PATTERN_* values of
// u_pattern, shared with the shaders.
#include "shared.glsl"

namespace framebuffer_ops {

namespace {

constexpr const char* kMvpUniform = "u_mvp";      // quad.vert
constexpr const char* kColorUniform = "u_color";  // solid.frag, cutout.frag
constexpr const char* kCellsUniform = "u_cells";  // cutout.frag
constexpr const char* kAlphaTestUniform = "u_alpha_test";
constexpr const char* kCutoffUniform = "u_cutoff";
constexpr const char* kPatternUniform = "u_pattern";  // faces.frag

}  // namespace

class FramebufferOpsLab : public fw::Lab {
public:
    static fw::LabInfo info();

    void init(fw::ProgramLibrary& programs) override {
        // File names within shaders/07_framebuffer_ops/.
        solid_ = &programs.load({"quad.vert", "solid.frag"});
        cutout_ = &programs.load({"quad.vert", "cutout.frag"});
        faces_ = &programs.load({"quad.vert", "faces.frag"});
        const fw::VertexLayout layout = fw::VertexLayout::of<Vertex>()
                                            .attr(A_POSITION, &Vertex::position)
                                            .attr(A_UV, &Vertex::uv);
        square_vbo_ = fw::Buffer::from(square_vertices(), GL_ARRAY_BUFFER, "square vertices");
        square_ibo_ = fw::Buffer::from(square_indices(), GL_ELEMENT_ARRAY_BUFFER, "square indices");
        square_ = fw::VertexArray(fw::VertexArrayDesc{.vertices = &square_vbo_,
                                                      .layout = layout,
                                                      .indices = &square_ibo_,
                                                      .index_type = GL_UNSIGNED_INT,
                                                      .label = "square"});
        disc_vbo_ = fw::Buffer::from(disc_vertices(), GL_ARRAY_BUFFER, "disc fan");
        disc_ = fw::VertexArray(
            fw::VertexArrayDesc{.vertices = &disc_vbo_, .layout = layout, .label = "disc"});
        box_vbo_ = fw::Buffer::from(box_vertices(), GL_ARRAY_BUFFER, "box vertices");
        box_ibo_ = fw::Buffer::from(box_indices(), GL_ELEMENT_ARRAY_BUFFER, "box indices");
        box_ = fw::VertexArray(fw::VertexArrayDesc{.vertices = &box_vbo_,
                                                   .layout = layout,
                                                   .indices = &box_ibo_,
                                                   .index_type = GL_UNSIGNED_INT,
                                                   .label = "open box"});
    }

    void draw(const fw::ParamValues& p, const fw::Frame&) override {
        // Each frame sets all the state it uses, from GL's defaults: the
        // tests off, blending off. The frame's alpha stays 1 (the window is
        // opaque): colour writes leave alpha alone.
        glDisable(GL_BLEND);
        glDisable(GL_DEPTH_TEST);
        glDisable(GL_STENCIL_TEST);
        glDisable(GL_SCISSOR_TEST);
        glDisable(GL_CULL_FACE);
        glDepthMask(GL_TRUE);
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
        switch (p[kScene]) {
            case Scene::Blend:
                draw_blend(p);
                break;
            case Scene::Sorting:
                draw_sorting(p);
                break;
            case Scene::Discard:
                draw_discard(p);
                break;
            case Scene::Stencil:
                draw_stencil(p);
                break;
            case Scene::Faces:
                draw_faces(p);
                break;
            case Scene::Scissor:
                draw_scissor(p);
                break;
        }
    }

private:
    void draw_square(const fw::Program& program, const glm::mat4& mvp) {
        program.set(kMvpUniform, mvp);
        glBindVertexArray(square_.id());
        glDrawElements(GL_TRIANGLES, 6, GL_UNSIGNED_INT, nullptr);
    }
    void draw_solid_square(const glm::mat4& mvp, glm::vec4 color) {
        solid_->use();
        solid_->set(kColorUniform, color);
        draw_square(*solid_, mvp);
    }
    void draw_disc(float radius, glm::vec4 color) {
        solid_->use();
        solid_->set(kColorUniform, color);
        solid_->set(kMvpUniform, disc(radius));
        glBindVertexArray(disc_.id());
        glDrawArrays(GL_TRIANGLE_FAN, 0, static_cast<GLsizei>(disc_.vertex_count()));
    }

    void draw_blend(const fw::ParamValues& p) {
        draw_solid_square(rect(-1, -1, 1, 1, 0), kBlendBackground);
        const Mode mode = p[kMode];
        set_blend_mode(mode);
        // Premultiplied alpha: the colour arrives already multiplied by its alpha.
        const auto color = [&](glm::vec4 c) {
            return mode == Mode::Premultiplied ? glm::vec4(glm::vec3(c) * c.a, c.a) : c;
        };
        if (p[kFirst] == First::A) {
            draw_solid_square(quad_a(), color(kQuadA));
            draw_solid_square(quad_b(), color(kQuadB));
        } else {
            draw_solid_square(quad_b(), color(kQuadB));
            draw_solid_square(quad_a(), color(kQuadA));
        }
    }

    void draw_sorting(const fw::ParamValues& p) {
        // The grey background, with the depth test still off: it writes no depth.
        draw_solid_square(rect(-1, -1, 1, 1, 0), kBlendBackground);
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        set_blend_mode(Mode::Over);
        set_depth_writes(p[kDepthWrite]);
        const std::vector<Pane> list = panes();
        std::vector<int> order;
        if (p[kSorted]) {
            std::vector<glm::vec3> centres;
            for (const Pane& pane : list) centres.push_back(pane.centre);
            order = back_to_front(centres, kSortingEye);
        } else {
            order = {0, 1, 2};  // as the scene lists them: near, middle, far
        }
        const glm::mat4 vp = sorting_view_projection();
        for (int i : order) draw_solid_square(vp * pane_model(list[i]), list[i].color);
    }

    void draw_discard(const fw::ParamValues& p) {
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        set_blend_mode(Mode::Over);
        cutout_->use();
        cutout_->set(kColorUniform, kFenceColor);
        cutout_->set(kCellsUniform, kFenceCells);
        // Until the student's discard is written the compiler drops these.
        cutout_->set_if_active(kAlphaTestUniform, p[kAlphaTest]);
        cutout_->set_if_active(kCutoffUniform, p[kCutoff]);
        draw_square(*cutout_, fence());
        set_blend_mode(Mode::None);
        draw_solid_square(back_quad(), kBackColor);
    }

    void draw_stencil(const fw::ParamValues& p) {
        mark_stencil();
        draw_disc(kMaskRadius, kOutlineColor);
        draw_where_marked();
        for (const Band& b : bands()) draw_solid_square(rect(-1, b.y0, 1, b.y1, 0), b.color);
        if (p[kOutline]) {
            draw_where_unmarked();
            draw_disc(kOutlineRadius, kOutlineColor);
        }
        glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_FALSE);
    }

    void draw_faces(const fw::ParamValues& p) {
        glEnable(GL_DEPTH_TEST);
        glDepthFunc(GL_LESS);
        glFrontFace(GL_CCW);
        if (p[kCull]) {
            glEnable(GL_CULL_FACE);
            glCullFace(GL_BACK);
        }
        faces_->use();
        faces_->set(kMvpUniform, box_view_projection());
        // The enum's value is the shader's PATTERN_* (shared.glsl); unused,
        // and dropped, until the student's patterns are written.
        faces_->set_if_active(kPatternUniform, static_cast<int>(p[kPattern]));
        glBindVertexArray(box_.id());
        glDrawElements(GL_TRIANGLES, static_cast<GLsizei>(box_.index_count()), GL_UNSIGNED_INT,
                       nullptr);
    }

    void draw_scissor(const fw::ParamValues& p) {
        glm::ivec4 viewport;
        glGetIntegerv(GL_VIEWPORT, &viewport[0]);
        // A clear obeys the scissor test like a draw does.
        if (p[kScissor]) scissor_to(viewport, kClearRect);
        glClearColor(kScissorClear.r, kScissorClear.g, kScissorClear.b, 1.0f);
        glClear(GL_COLOR_BUFFER_BIT);
        if (p[kScissor]) scissor_to(viewport, kDrawRect);
        draw_solid_square(rect(-1, -1, 1, 1, 0), kScissorDraw);
    }

    fw::Program* solid_ = nullptr;
    fw::Program* cutout_ = nullptr;
    fw::Program* faces_ = nullptr;
    fw::Buffer square_vbo_, square_ibo_, disc_vbo_, box_vbo_, box_ibo_;
    fw::VertexArray square_, disc_, box_;
};

fw::LabInfo FramebufferOpsLab::info() {
    fw::LabInfo i;
    i.title = "After the fragment shader: frame buffer operations";
    i.aspect = 1.0;  // a square scene: letterboxed in a frame of another shape
    i.params = params();
    i.functions = {fw::unit_function("blend", &blend),
                   fw::unit_function("back_to_front", &back_to_front4)};
    return i;
}

FW_LAB(FramebufferOpsLab)

}  // namespace framebuffer_ops
